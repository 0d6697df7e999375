// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ComparisonController.h"

#include <QProgressDialog>
#include <optional>

#include "CompareDock.h"
#include "SimulationDock.h"
#include "tetskin/session/LevelComparison.h"

namespace tetskin::gui {

ComparisonController::ComparisonController(Scene& scene, SimulationDock& simulationDock,
                                           CompareDock& compareDock, WindowServices& window)
    : scene_(scene), simulationDock_(simulationDock), compareDock_(compareDock), window_(window) {
  connect(&compareDock_, &CompareDock::compareRequested, this, [this] {
    compareLevels(compareDock_.referenceLevel(), compareDock_.inspectedLevel(),
                  compareDock_.steps());
  });
}

bool ComparisonController::compareLevels(int reference, int inspected, int steps) {
  if (!scene_.hasDataset() || !scene_.hasSurface()) {
    window_.fail("open a dataset and a surface before comparing levels");
    return false;
  }
  try {
    const MultiLevelTetMesh& mesh = scene_.dataset().mesh;
    const std::vector<RunSpec> specs = {simulationDock_.runSpec(inspected),
                                        simulationDock_.runSpec(reference)};
    LevelComparison comparison(mesh, scene_.surface(), specs, 1, scene_.datasetPath().string());
    ComparedLevels compared;
    compared.reference = reference;
    compared.inspected = inspected;
    compared.diagonal = comparison.diagonal();
    compared.surface = scene_.surface();
    compared.binding = comparison.surface(0).binding;
    const auto keep = [&] {
      const ComparedFrame& frame = comparison.compare();
      compared.times.push_back(frame.time);
      compared.nodes.push_back(datasetPositions(
          mesh, inspected, comparison.session(0)->state().positions, "the compared level"));
      const SurfaceErrors& e = comparison.errors(0);
      compared.distance.emplace_back(e.distance.begin(), e.distance.end());
      compared.angle.emplace_back(e.normalAngle.begin(), e.normalAngle.end());
    };
    std::optional<QProgressDialog> progress;
    if (window_.interactive()) {
      progress.emplace("Comparing level " + QString::number(inspected) + " with level " +
                           QString::number(reference) + "...",
                       "Cancel", 0, steps, window_.dialogParent());
      progress->setWindowModality(Qt::WindowModal);
      progress->setMinimumDuration(300);
    }
    keep();
    for (int i = 0; i < steps; ++i) {
      comparison.advance();
      keep();
      if (progress) {
        progress->setValue(i + 1);
        if (progress->wasCanceled()) return false;
      }
    }
    compared.overall = comparison.overall(0);
    compared.inspectedSecondsPerStep = comparison.meanStepSeconds(0);
    compared.referenceSecondsPerStep = comparison.meanStepSeconds(1);
    compareDock_.show(std::move(compared));
  } catch (const std::exception& e) {
    window_.fail(QString::fromStdString(e.what()));
    return false;
  }
  window_.raiseDock("CompareDock");
  window_.succeed(QString("compared level %1 with level %2 over %3 steps")
                      .arg(inspected)
                      .arg(reference)
                      .arg(steps));
  window_.renderNow();
  return true;
}

}  // namespace tetskin::gui
