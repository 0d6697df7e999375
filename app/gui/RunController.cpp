// SPDX-License-Identifier: AGPL-3.0-or-later
#include "RunController.h"

#include <vtkImageData.h>
#include <vtkUnstructuredGrid.h>

#include <QFileDialog>
#include <QFileInfo>
#include <cmath>

#include "EnergyPlot.h"
#include "RecordedRunPanel.h"
#include "SeriesPlot.h"
#include "SimulationDock.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/rendering/MovieFile.h"
#include "tetskin/session/SkinFields.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::gui {

RunController::RunController(Scene& scene, SimulationDock& dock, WindowServices& window)
    : scene_(scene),
      dock_(dock),
      window_(window),
      runPanel_(dock.runPanel()),
      energyPlot_(dock.energyPlot()) {
  connectDock();
}

RunController::~RunController() {
  runner_.reset();  // stop the simulation thread before the scene goes
}

void RunController::connectDock() {
  connect(runPanel_, &RecordedRunPanel::frameChosen, this, [this] { showRunFrame(); });
  connect(runPanel_, &RecordedRunPanel::continueRequested, this, [this] {
    // (The frame's state, of one body or of several: the open run's.)
    FrameState start;
    try {
      start = runPanel_->state();
    } catch (const std::exception& e) {
      window_.fail(QString::fromStdString(e.what()));
      return;
    }
    startFrom(start, QString::fromStdString(runPanel_->frameName()));
  });
  connect(runPanel_, &RecordedRunPanel::filmRequested, this, [this] {
    const QString file =
        window_.interactive()
            ? QFileDialog::getSaveFileName(window_.dialogParent(), "Film run", "run.ogv", "*.ogv")
            : "";
    if (!file.isEmpty()) filmRun(file);
  });
  connect(runPanel_, &RecordedRunPanel::closeRequested, this, [this] {
    closeRun();
    showLatestState();
  });
  connect(&dock_, &SimulationDock::playToggled, this, [this](bool on) {
    if (!runner_) return;
    if (on) {
      runPanel_->pause();
      replaying_ = false;
      runner_->play();
    } else {
      runner_->pause();
    }
    dock_.showPlaying(on);
  });
  connect(&dock_, &SimulationDock::stepRequested, this, [this] {
    if (!runner_) return;
    showPlaying(false);
    runner_->pause();
    runner_->step();
    showLatestState();
    reportProblems();
  });
  connect(&dock_, &SimulationDock::resetRequested, this, [this] { reset(); });
  connect(&dock_, &SimulationDock::equilibriumRequested, this, [this] { solveStatic(); });
  connect(&dock_, &SimulationDock::fromFrameRequested, this, [this] {
    const QString file = window_.interactive() ? QFileDialog::getOpenFileName(
                                                     window_.dialogParent(), "Start from frame", {},
                                                     "Simulation frames (*.vtu)")
                                               : "";
    if (!file.isEmpty()) startFromFrame(file);
  });
  connect(&dock_, &SimulationDock::recordToggled, this, [this](bool on) {
    if (!on) {
      stopRecording();
      return;
    }
    const QString file =
        window_.interactive()
            ? QFileDialog::getSaveFileName(window_.dialogParent(), "Record run", "run.pvd", "*.pvd")
            : "";
    if (file.isEmpty() || !startRecording(file)) dock_.showRecording(false);
  });
}

void RunController::solveStatic() {
  if (!runner_) return;
  showPlaying(false);
  StaticStats stats;
  try {
    stats = runner_->solveStatic();
  } catch (const std::exception& e) {
    window_.fail(QString::fromStdString(e.what()));
    return;
  }
  showLatestState();
  const QString summary =
      QString(
          "static equilibrium: %1 Newton iterations, largest force left %2 N (largest load %3 N)")
          .arg(stats.iterations)
          .arg(stats.residual, 0, 'g', 3)
          .arg(stats.load, 0, 'g', 3);
  if (stats.converged)
    window_.succeed(summary);
  else
    window_.showStatus("warning: " + summary + ", short of its tolerance (" +
                       QString::fromStdString(formatNumber(kStaticTolerance)) + " of the load)");
}

void RunController::reset() {
  stopRecording();  // the new run's time starts again at 0
  runner_.reset();
  scene_.setRunConditions({});  // (the new simulation's, if it starts)
  scene_.setLoadArrows({});
  energyPlot_->clear();
  contactSamples_.clear();
  dock_.contactPlot()->setSeries({}, {}, kContactTitle);
  dock_.contactPlot()->hide();
  dock_.clearSupports();
  plottedSteps_ = -1;
  shownSteps_ = -1;
  showPlaying(false);
  if (!scene_.hasDataset()) return;
  SimulationOptions options;
  try {
    const RunSpec spec = dock_.runSpec();
    options = spec.options;
    runner_ = std::make_unique<SimulationRunner>(scene_.dataset().mesh, spec);
    // The skin meets the obstacles, the floor (the contact points the run
    // names), other bodies and itself.
    if (runner_->session().contactNeedsSkin() && scene_.hasSurface())
      runner_->session().bindSurface(scene_.surface(), scene_.binding(),
                                     scene_.datasetPath().generic_string());
  } catch (const std::exception& e) {
    window_.fail(QString::fromStdString(e.what()));
    return;
  }
  if (scene_.deformable()) scene_.deformable()->setFrameSeconds(options.timeStep);
  // Energies below that of a uniform strain of 1e-6 in the body (E V e^2 / 2)
  // are round-off: the plot reads them 0.
  energyPlot_->setNoiseFloor(0.5 * options.material.youngsModulus *
                             std::abs(meshVolume(runner_->simulation().restMesh())) * 1e-12);
  // A drop starts above the rest shape: its ears would start out of view.
  // (A start within the rest shape's box leaves the camera as it is: a
  // surface far from its control mesh is framed alone, as opened.)
  const BoundingBox start = boundingBox(runner_->simulation().state().positions);
  const BoundingBox rest = boundingBox(runner_->simulation().restMesh().nodes);
  if ((start.min.array() < rest.min.array()).any() || (start.max.array() > rest.max.array()).any())
    scene_.keepInView(start);
  if (const QString warnings = takeWarnings(); !warnings.isEmpty()) window_.showStatus(warnings);
  showLatestState();
}

bool RunController::startFromFrame(const QString& qpath) {
  if (!runner_) {
    window_.fail("open a dataset before starting from a frame");
    return false;
  }
  FrameState start;
  try {
    start = readSimulationFrame(qpath.toStdString(), runner_->simulation().restMesh(),
                                "level " + std::to_string(scene_.level()) + " of " +
                                    scene_.datasetPath().filename().string());
  } catch (const std::exception& e) {
    window_.fail(QString::fromStdString(e.what()));
    return false;
  }
  if (!startFrom(start, qpath)) return false;
  window_.rememberRecent(QFileInfo(qpath).absoluteFilePath());
  return true;
}

bool RunController::startFrom(const FrameState& start, const QString& source) {
  reset();
  if (!runner_) return false;  // the dock's settings were refused (reported)
  runner_->session().startFrom(start);
  energyPlot_->clear();  // (its start was the scenario's, before the frame's state)
  plottedSteps_ = -1;
  showLatestState();
  QString message = "started from " + source;
  if (const QString warnings = takeWarnings(); !warnings.isEmpty()) message += "; " + warnings;
  window_.succeed(message);
  return true;
}

bool RunController::openRun(const QString& qpath) {
  try {
    runPanel_->open(qpath.toStdString(), scene_.datasetPath(), scene_.level(),
                    extractLevel(scene_.dataset().mesh, scene_.level()));
  } catch (const std::exception& e) {
    window_.fail(QString::fromStdString(e.what()));
    return false;
  }
  window_.rememberRecent(QFileInfo(qpath).absoluteFilePath());
  window_.raiseDock("SimulationDock");  // the run's slider
  if (!showRunFrame()) return false;
  window_.succeed("opened " + qpath + " (" + QString::number(runPanel_->frameCount()) + " frames)");
  return true;
}

bool RunController::showRunFrame() {
  if (!runPanel_->isOpen()) return false;
  FrameState state;
  try {
    state = runPanel_->state();
  } catch (const std::exception& e) {
    window_.fail(QString::fromStdString(e.what()));
    return false;
  }
  pause();
  replaying_ = true;
  scene_.setRunConditions(runPanel_->conditions());
  lastTimes_ = scene_.showControlState(state.positions);
  showOnSkin(state.vonMisesStress, state.equivalentStrain);  // (none in older frames)
  window_.renderNow();
  return true;
}

void RunController::showOnSkin(const Eigen::VectorXd& stress, const Eigen::VectorXd& strain) {
  // (The simulated level is the scene's: its rest mesh is the runner's.)
  if (!scene_.colorsBySimulation() || !scene_.hasSurface() || !runner_) return;
  const bool byStress = scene_.colorBy() == ColorBy::VonMisesStress;
  const Eigen::VectorXd& values = byStress ? stress : strain;
  if (values.size() == 0) return;
  const TetMesh& rest = runner_->simulation().restMesh();
  const Index firstNode =
      scene_.dataset().mesh.levels[static_cast<std::size_t>(scene_.level())].firstNode;
  const std::vector<PointScalars> fields =
      byStress ? skinFields(rest, firstNode, scene_.binding(), values, {})
               : skinFields(rest, firstNode, scene_.binding(), {}, values);
  scene_.setSurfaceScalars(scene_.colorBy(), fields.front().values);
}

bool RunController::filmRun(const QString& qpath) {
  if (!runPanel_->isOpen()) {
    window_.fail("open a recorded run (.pvd) to film");
    return false;
  }
  const std::filesystem::path path = qpath.toStdString();
  if (lowerExtension(path) != ".ogv") {
    window_.fail(qpath + ": a film is an Ogg Theora movie: the name must end in .ogv");
    return false;
  }
  runPanel_->pause();
  const int shown = runPanel_->frame();
  const int rate = movieRate(runPanel_->meanFrameSeconds());
  const auto frames = static_cast<int>(runPanel_->frameCount());
  std::string error;
  try {
    writeMovieAtomically(path, rate, [&](MovieFile& movie) {
      for (int i = 0; i < frames; ++i) {
        runPanel_->setFrame(i);
        if (!showRunFrame()) throw Error(window_.lastError().toStdString());  // (reported)
        movie.add(window_.grabImage());
      }
    });
  } catch (const std::exception& e) {
    error = e.what();
  }
  runPanel_->setFrame(shown);  // the frame shown before, film or not
  showRunFrame();
  if (!error.empty()) {
    window_.fail(QString::fromStdString(error));
    return false;
  }
  window_.succeed(QString("wrote %1 (%2 frames at %3 frames/s)").arg(qpath).arg(frames).arg(rate));
  return true;
}

void RunController::closeRunIfItNoLongerFits() {
  if (runPanel_->isOfAnotherLevel(scene_.datasetPath(), scene_.level())) closeRun();
}

void RunController::closeRun() {
  runPanel_->close();
  replaying_ = false;
}

void RunController::showLatestState() {
  if (!runner_) return;
  runPanel_->pause();
  replaying_ = false;
  scene_.setRunConditions(runner_->simulation().conditions());
  const SimulationState state = runner_->state();
  scene_.poseObstacles(state.time);
  if (scene_.wantsSkinContact()) scene_.setSkinContact(runner_->simulation().skinContact(state));
  lastTimes_ = scene_.showControlState(state.positions);
  const Simulation& sim = runner_->simulation();
  scene_.setLoadArrows(sim.hasSurfaceLoads() ? sim.surfaceLoadForces(state) : Points3());
  if (scene_.colorsBySimulation()) {
    const FrameFields fields = runner_->simulation().frameFields(state);
    showOnSkin(fields.vonMisesStress, fields.equivalentStrain);
  }
  shownSteps_ = state.steps;
  plotEnergy(state);
  if (runner_->session().recording()) {
    try {
      // The surface as the render path drew it.
      const BoundSurface surface = scene_.deformedBoundSurface();
      runner_->session().recordFrame(state, &surface);
    } catch (const std::exception& e) {
      stopRecording();
      window_.fail(QString::fromStdString(e.what()));
    }
  }
  window_.renderNow();
}

void RunController::plotEnergy(const SimulationState& state) {
  // Every step taken by hand; while playing, at most 10 samples a second
  // of wall-clock time (each costs an element pass).
  const auto now = std::chrono::steady_clock::now();
  if (state.steps == plottedSteps_) return;
  if (runner_->playing() && now - lastEnergySample_ < std::chrono::milliseconds(100)) return;
  const Simulation& sim = runner_->simulation();
  const Energies e = sim.energies();
  energyPlot_->add({state.time, e.kinetic, e.elastic, e.gravitational, e.load});
  const SimulationOptions& options = sim.options();
  if (state.steps > 0 && options.hasContact()) {
    // The contacts of the last step, over the energy plot's window.
    contactSamples_.emplace_back(state.time, runner_->lastStats().contacts);
    while (contactSamples_.front().first < state.time - energyPlot_->window())
      contactSamples_.pop_front();
    std::vector<double> times, counts;
    for (const auto& [time, count] : contactSamples_) {
      times.push_back(time);
      counts.push_back(count);
    }
    dock_.contactPlot()->setSeries(times, counts, kContactTitle);
    dock_.contactPlot()->show();
  }
  dock_.showSupports(sim.supportReaction(state), sim.fixedNodes().size());
  plottedSteps_ = state.steps;
  lastEnergySample_ = now;
}

void RunController::showPlaying(bool playing) {
  dock_.showPlaying(playing);  // (the caller plays or pauses the runner)
}

void RunController::reportProblems() {
  if (!runner_) return;
  if (const std::optional<std::string> failure = runner_->takeFailure()) {
    showPlaying(false);  // the runner paused itself
    window_.fail("the simulation paused: " + QString::fromStdString(*failure) +
                 " (Reset starts it again)");
    return;
  }
  // Solves cut off at the iteration limit: in the status bar, as simulate
  // warns, when their count grows.
  if (const QString warnings = takeWarnings(); !warnings.isEmpty()) window_.showStatus(warnings);
}

QString RunController::takeWarnings() {
  QString text;
  for (const std::string& warning : runner_->session().takeWarnings(OptionNames::Words))
    text += (text.isEmpty() ? "warning: " : "; warning: ") + QString::fromStdString(warning);
  return text;
}

void RunController::pause() {
  if (runner_ && runner_->playing()) {
    runner_->pause();
    showPlaying(false);
  }
}

void RunController::refreshSkinContact() {
  if (runner_ && !replaying_ && scene_.wantsSkinContact())
    scene_.setSkinContact(runner_->simulation().skinContact(runner_->state()));
}

void RunController::tick() {
  if (runner_ && !replaying_ && runner_->steps() != shownSteps_) showLatestState();
  reportProblems();
}

void RunController::writeControlFrame(const std::filesystem::path& path) {
  if (replaying_ && runPanel_->isOpen()) {
    if (runPanel_->ofSeveralBodies())
      throw Error(runPanel_->frameName() +
                  ": a run of several bodies keeps a frame file per body "
                  "(RUN_frames/control_NNNNN_K.vtu); Continue starts the scene from this frame");
    writeVtu(path, readVtu(runPanel_->frameFile()));
    return;
  }
  if (!runner_) throw Error("open a dataset first");
  Simulation& sim = runner_->simulation();
  const SimulationState s = runner_->state();
  writeVtu(path,
           simulationFrame(sim.restMesh(), sim.frameFields(s), scene_.level(), sim.conditions()));
}

bool RunController::startRecording(const QString& pvd) {
  if (!scene_.hasSurface() || !runner_) {
    window_.fail("open a dataset and a surface before recording");
    return false;
  }
  try {
    runner_->session().record(pvd.toStdString());
  } catch (const std::exception& e) {
    window_.fail(QString::fromStdString(e.what()));
    return false;
  }
  showLatestState();  // the first frame
  dock_.showRecording(true);
  return true;
}

Index RunController::recordedFrames() const {
  if (!runner_ || !runner_->session().recorder()) return 0;
  return runner_->session().recorder()->frames();
}

void RunController::stopRecording() {
  if (!runner_ || !runner_->session().recording()) return;
  const RunRecorder& recorder = *runner_->session().recorder();
  window_.showStatus(QString("recorded %1 frames to %2")
                         .arg(recorder.frames())
                         .arg(QString::fromStdString(recorder.path().string())));
  runner_->session().stopRecording();
  dock_.showRecording(false);
}

void RunController::pull(Index vertex, int x, int y) {
  if (!runner_) return;
  const VertexInfo info = scene_.vertexInfo(vertex);
  const Eigen::Vector3d target = scene_.displayToWorld(x, y, info.position);
  // A spring to the mouse, as stiff as the body itself at the scale of its
  // size (the binding summary already holds the surface's bounding-box
  // diagonal).
  const double stiffness =
      0.2 * runner_->simulation().options().material.youngsModulus * scene_.summary().diagonal;
  const LevelRange& r = scene_.dataset().mesh.levels[static_cast<std::size_t>(scene_.level())];
  std::vector<int> nodes;
  Points3 forces(scene_.binding().controlsPerVertex(), 3);
  for (int k = 0; k < scene_.binding().controlsPerVertex(); ++k) {
    nodes.push_back(info.controlIds[k] - static_cast<int>(r.firstNode));
    forces.row(k) = (stiffness * info.weights[k] * (target - info.position)).transpose();
  }
  runner_->pull(nodes, forces);
  if (!runner_->playing()) {
    showPlaying(true);
    runner_->play();
  }
}

void RunController::release() {
  if (runner_) runner_->release();
}

}  // namespace tetskin::gui
