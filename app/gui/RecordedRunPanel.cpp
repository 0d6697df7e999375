// SPDX-License-Identifier: AGPL-3.0-or-later
#include "RecordedRunPanel.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "tetskin/core/Error.h"

namespace tetskin::gui {

RecordedRunPanel::RecordedRunPanel(QWidget* parent) : QGroupBox("Recorded run", parent) {
  setObjectName("recordedRun");
  auto* layout = new QVBoxLayout(this);
  label_ = new QLabel;
  label_->setObjectName("runLabel");
  label_->setWordWrap(true);
  slider_ = new QSlider(Qt::Horizontal);
  slider_->setObjectName("runFrame");
  slider_->setToolTip("the recorded frame shown (the simulation pauses)");
  auto* buttons = new QHBoxLayout;
  play_ = new QPushButton("Play run");  // (the simulation's own Play is above)
  play_->setObjectName("runPlay");
  play_->setCheckable(true);
  play_->setToolTip("step through the frames at the times they were recorded");
  timer_ = new QTimer(this);
  timer_->setSingleShot(true);
  auto* continueButton = new QPushButton("Continue from here");
  continueButton->setObjectName("runContinue");
  continueButton->setToolTip("Reset, then simulate on from the frame shown (as From frame...)");
  auto* filmButton = new QPushButton("Film...");
  filmButton->setObjectName("runFilm");
  filmButton->setToolTip(
      "every frame into an Ogg Theora movie (.ogv), as the view shows it, at the rate they were "
      "recorded");
  auto* closeButton = new QPushButton("Close");
  closeButton->setObjectName("runClose");
  buttons->addWidget(play_);
  buttons->addWidget(filmButton);
  buttons->addWidget(continueButton);
  buttons->addWidget(closeButton);
  layout->addWidget(label_);
  layout->addWidget(slider_);
  layout->addLayout(buttons);
  hide();
  connect(slider_, &QSlider::valueChanged, this, [this](int frame) {
    showFrameText();
    Q_EMIT frameChosen(frame);
  });
  connect(play_, &QPushButton::toggled, this, [this](bool on) {
    play_->setText(on ? "Pause run" : "Play run");
    if (!on) {
      timer_->stop();
      return;
    }
    if (slider_->value() == slider_->maximum()) slider_->setValue(0);  // again from the start
    scheduleNextFrame();
  });
  connect(timer_, &QTimer::timeout, this, [this] {
    slider_->setValue(slider_->value() + 1);
    scheduleNextFrame();
  });
  connect(continueButton, &QPushButton::clicked, this, [this] {
    if (run_) Q_EMIT continueRequested();
  });
  connect(filmButton, &QPushButton::clicked, this, [this] {
    if (run_) Q_EMIT filmRequested();
  });
  connect(closeButton, &QPushButton::clicked, this, [this] { Q_EMIT closeRequested(); });
}

void RecordedRunPanel::open(const std::filesystem::path& pvd, const std::filesystem::path& dataset,
                            int level, TetMesh rest) {
  RecordedRun run(pvd);
  if (run.level() && *run.level() != level)
    throw Error(pvd.string(), 0,
                "its frames are of level " + std::to_string(*run.level()) +
                    "; the simulated level is " + std::to_string(level) +
                    ": rebind the surface to level " + std::to_string(*run.level()) +
                    " (Binding dock) first");
  std::string restName = "level " + std::to_string(level) + " of " + dataset.filename().string();
  run.read(0, rest, restName);  // a run of another body is refused now, not at a later frame
  pause();
  run_.emplace(std::move(run));
  dataset_ = dataset;
  level_ = level;
  rest_ = std::move(rest);
  restName_ = std::move(restName);
  {
    const QSignalBlocker block(slider_);
    slider_->setRange(0, static_cast<int>(run_->frameCount()) - 1);
    slider_->setValue(0);
  }
  setTitle("Recorded run: " + QString::fromStdString(pvd.filename().string()));
  showFrameText();
  show();
}

void RecordedRunPanel::scheduleNextFrame() {
  if (!run_ || slider_->value() >= slider_->maximum()) {
    play_->setChecked(false);
    return;
  }
  const auto at = static_cast<std::size_t>(slider_->value());
  const double seconds = run_->time(at + 1) - run_->time(at);
  timer_->start(static_cast<int>(std::lround(1000 * std::clamp(seconds, 0.0, 10.0))));
}

void RecordedRunPanel::pause() {
  play_->setChecked(false);
}

void RecordedRunPanel::close() {
  pause();
  run_.reset();
  rest_ = {};
  restName_.clear();
  hide();
}

bool RecordedRunPanel::isOfAnotherLevel(const std::filesystem::path& dataset, int level) const {
  return run_ && (dataset != dataset_ || level != level_);
}

void RecordedRunPanel::setFrame(int frame) {
  {
    const QSignalBlocker block(slider_);
    slider_->setValue(frame);
  }
  showFrameText();
}

int RecordedRunPanel::frame() const {
  return slider_->value();
}

const std::string& RecordedRunPanel::frameFile() const {
  return run_->file(static_cast<std::size_t>(frame()));
}

FrameState RecordedRunPanel::state() const {
  return run_->read(static_cast<std::size_t>(frame()), rest_, restName_);
}

std::string RecordedRunPanel::frameName() const {
  return "frame " + std::to_string(frame()) + " of " + run_->path().string();
}

void RecordedRunPanel::showFrameText() {
  if (!run_) return;
  label_->setText(QString("frame %1 of %2, t = %3 s")
                      .arg(frame())
                      .arg(run_->frameCount() - 1)
                      .arg(run_->time(static_cast<std::size_t>(frame()))));
}

}  // namespace tetskin::gui
