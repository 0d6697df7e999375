// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// "Build dataset": the options of `tetskin build` in a dialog; the build runs
// on a worker thread with a progress bar, its log, and Cancel (which kills the
// running mesher processes). Emits built(json) when the dataset is saved.

#include <QDialog>
#include <atomic>
#include <memory>
#include <thread>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace tetskin::gui {

class BuildDialog : public QDialog {
  Q_OBJECT
 public:
  explicit BuildDialog(QWidget* parent = nullptr);
  ~BuildDialog() override;

  void setInputs(const QStringList& files);
  void setOutput(const QString& basePath);
  void setLevels(int levels, int minElements, int maxElements);
  void setQualities(const QString& commaSeparated);
  void setSizeToTargets(bool on);
  // --wrap, --wrap-alpha, --wrap-offset: "auto", "always" or "never", and
  // fractions of the diagonal.
  void setWrap(const QString& mode, double alpha, double offset);
  // Starts the build; false (with a message in the log) on bad options.
  bool start();
  void cancel();
  bool running() const { return running_; }
  QString log() const;
  // What the last build's wrapped levels cost: their distances to the
  // input, one line a level (empty when none was wrapped).
  QString wrapFidelity() const;

 Q_SIGNALS:
  void built(const QString& jsonPath);
  void failed(const QString& message);

 private:
  void finish(bool ok, const QString& message, const QString& json);
  void appendLog(const QString& line);

  QListWidget* inputs_;
  QLineEdit* output_;
  QSpinBox *levels_, *minElements_, *maxElements_, *jobs_;
  QComboBox* mesher_;
  QComboBox* up_;
  QLineEdit* qualities_;
  QCheckBox *decimate_, *sizeToTargets_, *acceptUnfaithful_;
  QComboBox* wrap_;
  QDoubleSpinBox *wrapAlpha_, *wrapOffset_;
  QLabel* wrapFidelity_;
  QProgressBar* progress_;
  QPlainTextEdit* log_;
  QPushButton *run_, *cancel_;
  std::thread worker_;
  std::atomic<bool> cancelled_{false}, running_{false};
};

}  // namespace tetskin::gui
