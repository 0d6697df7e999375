// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ScientificSpinBox.h"

#include <QLocale>
#include <QRegularExpression>
#include <cfloat>
#include <cmath>
#include <limits>

namespace tetskin::gui {
namespace {

// What a number can look like while it is being typed ("", "-", "1.", "2e").
bool isNumberBeingTyped(const QString& text) {
  static const QRegularExpression partial(R"(^[+-]?\d*\.?\d*([eE][+-]?\d*)?$)");
  return partial.match(text).hasMatch();
}

}  // namespace

ScientificSpinBox::ScientificSpinBox(QWidget* parent) : QDoubleSpinBox(parent) {
  // QDoubleSpinBox::setValue rounds to the decimals; at their most (323) the
  // rounding keeps every double's value.
  setDecimals(DBL_MAX_10_EXP + DBL_DIG);
  setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
  // The value changes on Enter or on leaving the box, not at each key: a
  // half-typed "0." is no Poisson ratio, and a number typed out of range
  // leaves the value as it was.
  setKeyboardTracking(false);
}

QString ScientificSpinBox::textFromValue(double value) const {
  return QLocale::c().toString(value, 'g', 6);
}

double ScientificSpinBox::valueFromText(const QString& text) const {
  const QString typed = text.trimmed();
  if (!specialValueText().isEmpty() && typed == specialValueText()) return minimum();
  // The text shown for the value (six digits) reads back as the value itself,
  // so leaving the box without an edit does not round it.
  if (typed == textFromValue(value())) return value();
  return QLocale::c().toDouble(typed);
}

QValidator::State ScientificSpinBox::validate(QString& text, int& /*position*/) const {
  const QString typed = text.trimmed();
  if (!specialValueText().isEmpty() && typed == specialValueText()) return QValidator::Acceptable;
  bool ok = false;
  const double number = QLocale::c().toDouble(typed, &ok);
  if (ok && number >= minimum() && number <= maximum()) return QValidator::Acceptable;
  return ok || isNumberBeingTyped(typed) ? QValidator::Intermediate : QValidator::Invalid;
}

void ScientificSpinBox::stepBy(int steps) {
  if (stepType() == QAbstractSpinBox::AdaptiveDecimalStepType &&
      std::abs(value()) < std::numeric_limits<double>::min()) {
    setValue(value() + steps * singleStep());
    selectAll();
    return;
  }
  QDoubleSpinBox::stepBy(steps);
}

ScientificSpinBox* numberBox(const char* name, double min, double max, double value,
                             const char* tip) {
  auto* box = new ScientificSpinBox;
  box->setObjectName(name);
  box->setRange(min, max);
  box->setValue(value);
  box->setToolTip(tip);
  return box;
}

ScientificSpinBox* numberBox(const char* name, const NumberOption& option) {
  const NumberRange& r = option.range;
  // (0 excluded: kLeastPositive, the least normal number, as everywhere.)
  const double min = std::isinf(r.min) ? -kLargest
                     : r.minIncluded   ? r.min
                     : r.min == 0      ? kLeastPositive
                                       : std::nextafter(r.min, kLargest);
  const double max = std::isinf(r.max) ? kLargest
                     : r.maxIncluded   ? r.max
                                       : std::nextafter(r.max, -kLargest);
  return numberBox(name, min, max, option.defaultValue, option.help);
}

QString labelOf(const char* what) {
  QString label = what;
  if (label.startsWith("the ")) label.remove(0, 4);
  if (!label.isEmpty()) label[0] = label[0].toUpper();
  return label;
}

QString labelOf(const NumberOption& option) {
  return labelOf(option.what);
}

QString labelOf(const ListOption& option) {
  return labelOf(option.what);
}

}  // namespace tetskin::gui
