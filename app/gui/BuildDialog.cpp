// SPDX-License-Identifier: AGPL-3.0-or-later
#include "BuildDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <filesystem>

#include "EnumBox.h"
#include "ScientificSpinBox.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/meshing/IsolatedJobs.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin::gui {
namespace {

// A box of whole numbers over the option's range, set to its default.
QSpinBox* countBox(const NumberOption& option) {
  auto* box = new QSpinBox;
  box->setRange(static_cast<int>(option.range.min), static_cast<int>(option.range.max));
  box->setValue(static_cast<int>(option.defaultValue));
  box->setToolTip(option.help);
  return box;
}

}  // namespace

BuildDialog::BuildDialog(QWidget* parent) : QDialog(parent) {
  setWindowTitle("Build dataset");
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  inputs_ = new QListWidget;
  inputs_->setObjectName("buildInputs");
  auto* add = new QPushButton("Add surfaces...");
  connect(add, &QPushButton::clicked, this, [this] {
    const QStringList files = QFileDialog::getOpenFileNames(this, "Input surfaces", {},
                                                            "Surfaces (*.obj *.ply *.stl *.vtp)");
    inputs_->addItems(files);
  });
  auto* inputRow = new QVBoxLayout;
  inputRow->addWidget(inputs_);
  inputRow->addWidget(add);
  form->addRow("Inputs (finest first)", inputRow);
  output_ = new QLineEdit;
  output_->setObjectName("buildOutput");
  output_->setPlaceholderText("out/bunny (writes .node, .ele, .json)");
  form->addRow("Output", output_);
  // The ranges, defaults, labels and tips are the schema's (OptionSchema.h).
  using namespace build_option;
  levels_ = countBox(kLevels);
  minElements_ = countBox(kMinElements);
  maxElements_ = countBox(kMaxElements);
  form->addRow(labelOf(kLevels), levels_);
  form->addRow(labelOf(kMinElements), minElements_);
  form->addRow(labelOf(kMaxElements), maxElements_);
  const BuildOptions defaults;
  mesher_ = enumCombo("mesher", kMesher, defaults.mesher);
  form->addRow(labelOf(kMesher), mesher_);
  up_ = enumCombo("up", kUpOption, defaults.up,
                  " in the inputs (z for most CAD and STL files): the simulation's scenarios, "
                  "floor and gravity and the camera follow it");
  form->addRow(labelOf(kUpOption), up_);
  QStringList qualities;
  for (const double q : BuildOptions{}.qualities) qualities << QString::number(q, 'f', 1);
  qualities_ = new QLineEdit(qualities.join(","));
  qualities_->setToolTip(kQualities.help);
  form->addRow(labelOf(kQualities), qualities_);
  decimate_ = new QCheckBox("derive coarser inputs by decimation");
  form->addRow("", decimate_);
  sizeToTargets_ = new QCheckBox("also mesh under size bounds aimed at the element targets");
  sizeToTargets_->setObjectName("sizeToTargets");
  sizeToTargets_->setToolTip(
      "For each level target that no quality meets, mesh again under an element size bound "
      "(TetGen -a, Netgen maxh): for shapes such as boxes, whose surface needs few elements");
  form->addRow("", sizeToTargets_);
  acceptUnfaithful_ = new QCheckBox("accept levels that lie off the input beyond their bound");
  acceptUnfaithful_->setObjectName("acceptUnfaithful");
  acceptUnfaithful_->setToolTip(
      "Without it, a level whose candidates near its target all lie off the input by more than "
      "half their element size on average (twice it at worst) stops the build with the numbers "
      "and a way out; with it, the nearest is written and the config records its distances");
  form->addRow("", acceptUnfaithful_);
  wrap_ = enumCombo("wrap", wrap_option::kMode, defaults.wrap.mode);
  auto fraction = [](const char* name, const NumberOption& option) {
    auto* box = new QDoubleSpinBox;
    box->setObjectName(name);
    box->setDecimals(5);
    box->setRange(0.00001, option.range.max);
    box->setSingleStep(0.001);
    box->setValue(option.defaultValue);
    box->setToolTip(option.help);
    return box;
  };
  wrapAlpha_ = fraction("wrapAlpha", wrap_option::kAlpha);
  wrapOffset_ = fraction("wrapOffset", wrap_option::kOffset);
  auto* wrapRow = new QHBoxLayout;
  wrapRow->addWidget(wrap_);
  wrapRow->addWidget(new QLabel("alpha"));
  wrapRow->addWidget(wrapAlpha_);
  wrapRow->addWidget(new QLabel("offset"));
  wrapRow->addWidget(wrapOffset_);
  form->addRow(labelOf(wrap_option::kMode), wrapRow);
  jobs_ = countBox(kJobs);
  jobs_->setValue(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  form->addRow(labelOf(kJobs), jobs_);
  layout->addLayout(form);
  wrapFidelity_ = new QLabel;
  wrapFidelity_->setObjectName("wrapFidelity");
  wrapFidelity_->setWordWrap(true);
  wrapFidelity_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  wrapFidelity_->hide();
  layout->addWidget(wrapFidelity_);
  progress_ = new QProgressBar;
  progress_->setObjectName("buildProgress");
  layout->addWidget(progress_);
  log_ = new QPlainTextEdit;
  log_->setReadOnly(true);
  log_->setMinimumHeight(120);
  layout->addWidget(log_);
  auto* buttons = new QHBoxLayout;
  run_ = new QPushButton("Build");
  cancel_ = new QPushButton("Cancel");
  cancel_->setEnabled(false);
  auto* close = new QPushButton("Close");
  buttons->addWidget(run_);
  buttons->addWidget(cancel_);
  buttons->addStretch();
  buttons->addWidget(close);
  layout->addLayout(buttons);
  connect(run_, &QPushButton::clicked, this, [this] { start(); });
  connect(cancel_, &QPushButton::clicked, this, [this] { cancel(); });
  connect(close, &QPushButton::clicked, this, [this] {
    cancel();
    accept();
  });
}

BuildDialog::~BuildDialog() {
  cancelled_ = true;
  if (worker_.joinable()) worker_.join();
}

void BuildDialog::setInputs(const QStringList& files) {
  inputs_->clear();
  inputs_->addItems(files);
}
void BuildDialog::setOutput(const QString& basePath) {
  output_->setText(basePath);
}
void BuildDialog::setLevels(int levels, int minElements, int maxElements) {
  levels_->setValue(levels);
  minElements_->setValue(minElements);
  maxElements_->setValue(maxElements);
}
void BuildDialog::setQualities(const QString& commaSeparated) {
  qualities_->setText(commaSeparated);
}
void BuildDialog::setSizeToTargets(bool on) {
  sizeToTargets_->setChecked(on);
}
void BuildDialog::setWrap(const QString& mode, double alpha, double offset) {
  wrap_->setCurrentText(mode);
  wrapAlpha_->setValue(alpha);
  wrapOffset_->setValue(offset);
}
QString BuildDialog::log() const {
  return log_->toPlainText();
}
QString BuildDialog::wrapFidelity() const {
  return wrapFidelity_->text();
}

void BuildDialog::appendLog(const QString& line) {
  log_->appendPlainText(line);
}

bool BuildDialog::start() {
  if (running_) return false;
  if (worker_.joinable()) worker_.join();
  BuildOptions options;
  options.levels = levels_->value();
  options.minElements = minElements_->value();
  options.maxElements = maxElements_->value();
  options.mesher = chosen<MesherKind>(mesher_);
  options.decimate = decimate_->isChecked();
  options.sizeToTargets = sizeToTargets_->isChecked();
  options.acceptUnfaithful = acceptUnfaithful_->isChecked();
  options.jobs = jobs_->value();
  options.up = chosen<UpAxis>(up_);
  options.wrap.mode = chosen<WrapMode>(wrap_);
  options.wrap.alpha = wrapAlpha_->value();
  options.wrap.offset = wrapOffset_->value();
  options.qualities.clear();
  for (const QString& q : qualities_->text().split(',', Qt::SkipEmptyParts)) {
    bool ok = false;
    const double value = q.trimmed().toDouble(&ok);
    if (!ok || !(value >= 1.0)) {
      appendLog("error: quality '" + q + "' is not a number >= 1");
      return false;
    }
    options.qualities.push_back(value);
  }
  QStringList files;
  for (int i = 0; i < inputs_->count(); ++i) files << inputs_->item(i)->text();
  if (files.isEmpty() || output_->text().isEmpty()) {
    appendLog("error: give at least one input surface and an output");
    return false;
  }
  const std::filesystem::path json = datasetConfigPath(output_->text().toStdString());
  std::vector<std::filesystem::path> paths;
  for (const QString& f : files) paths.emplace_back(f.toStdString());
  cancelled_ = false;
  running_ = true;
  run_->setEnabled(false);
  cancel_->setEnabled(true);
  progress_->setValue(0);
  wrapFidelity_->clear();
  wrapFidelity_->hide();
  appendLog("building " + QString::fromStdString(json.string()));
  worker_ = std::thread([this, options, paths, json] {
    // Runs off the GUI thread; everything it shows goes back through the event loop.
    auto post = [this](auto f) { QMetaObject::invokeMethod(this, f, Qt::QueuedConnection); };
    try {
      const std::filesystem::path directory = std::filesystem::absolute(json).parent_path();
      requireWritableLocation(json);  // before the meshing, not after it
      std::vector<SurfaceInput> inputs;
      for (const auto& path : paths) {
        SurfaceInput input{
            path.string(), readSurface(path),
            std::filesystem::relative(std::filesystem::absolute(path), directory).generic_string()};
        inputs.push_back(std::move(input));
      }
      BuildEvents events;
      events.log = [post, this](const std::string& line) {
        post([this, text = QString::fromStdString(line)] { appendLog(text); });
      };
      events.progress = [post, this](const std::string& stage, std::size_t done,
                                     std::size_t total) {
        post([this, stage = QString::fromStdString(stage), done, total] {
          progress_->setFormat(stage + " %v/%m");
          progress_->setMaximum(static_cast<int>(std::max<std::size_t>(total, 1)));
          progress_->setValue(static_cast<int>(done));
        });
      };
      events.cancelled = [this] { return cancelled_.load(); };
      BuildResult result = buildDataset(std::move(inputs), options, events);
      if (cancelled_) throw Cancelled();
      // (The writers make the folder only now: bad input, a failure or a
      // cancel leaves no empty folder.)
      saveDataset(json, result.dataset);
      // How far each level lies from the input, and what a wrap cost (as
      // build prints them).
      QString fidelity;
      for (std::size_t k = 0; k < result.dataset.config.levels.size(); ++k) {
        const LevelConfig& level = result.dataset.config.levels[k];
        if (level.fidelity)
          fidelity += QString("Level %1 against the input: %2\n")
                          .arg(k)
                          .arg(QString::fromStdString(describe(*level.fidelity)));
        if (level.source.wrap)
          fidelity += QString("Level %1 was meshed from a wrap: %2\n")
                          .arg(k)
                          .arg(QString::fromStdString(describe(*level.source.wrap)));
      }
      post([this, fidelity = fidelity.trimmed()] {
        wrapFidelity_->setText(fidelity);
        wrapFidelity_->setVisible(!fidelity.isEmpty());
      });
      post([this, j = QString::fromStdString(json.string())] { finish(true, "done", j); });
    } catch (const Cancelled&) {
      post([this] { finish(false, "cancelled", {}); });
    } catch (const std::exception& e) {
      post([this, m = QString::fromStdString(e.what())] { finish(false, "error: " + m, {}); });
    }
  });
  return true;
}

void BuildDialog::cancel() {
  if (running_) cancelled_ = true;
}

void BuildDialog::finish(bool ok, const QString& message, const QString& json) {
  if (worker_.joinable()) worker_.join();
  running_ = false;
  run_->setEnabled(true);
  cancel_->setEnabled(false);
  appendLog(message);
  if (ok) {
    progress_->setValue(progress_->maximum());
    Q_EMIT built(json);
  } else {
    Q_EMIT failed(message);
  }
}

}  // namespace tetskin::gui
