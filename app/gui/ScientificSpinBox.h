// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A number box for physical quantities. QDoubleSpinBox rounds every value to
// its fixed decimals, so the dock's time step of 1/60 s ran as 0.0167 s, a
// dataset's stiffness damping of 1e-7 s as 0, a Poisson ratio of 0.49995 as
// 0.4999, and the floor offered at the body's lowest point sat up to 5e-5
// off it. This box keeps the exact value it is given, shows it with six
// significant digits, and reads what the user types in any notation (2e5,
// 1.5E-7, 0.0166667).

#include <QDoubleSpinBox>
#include <QString>
#include <limits>

#include "tetskin/core/OptionSchema.h"

namespace tetskin::gui {

class ScientificSpinBox : public QDoubleSpinBox {
 public:
  explicit ScientificSpinBox(QWidget* parent = nullptr);

  QString textFromValue(double value) const override;
  double valueFromText(const QString& text) const override;
  QValidator::State validate(QString& text, int& position) const override;
  // Steps of a tenth of the value's order of magnitude (Qt's adaptive
  // step); from 0, where that step would be 1e-323, by singleStep().
  void stepBy(int steps) override;
};

// The bounds of the ranges the simulation accepts: "> 0" is [kLeastPositive,
// kLargest], "finite" is [-kLargest, kLargest].
inline constexpr double kLeastPositive = std::numeric_limits<double>::min();
inline constexpr double kLargest = std::numeric_limits<double>::max();

// A box named `name` (for tests and settings) over [min, max], set to value.
ScientificSpinBox* numberBox(const char* name, double min, double max, double value,
                             const char* tip);
// A box over the option's range (an excluded bound: the nearest number
// inside it), set to its default, its help as tip.
ScientificSpinBox* numberBox(const char* name, const NumberOption& option);
// The option's label in a form: its name in messages, capitalized ("the
// time step" -> "Time step"); its help (with the unit) is the box's tip.
QString labelOf(const char* what);
QString labelOf(const NumberOption& option);
QString labelOf(const ListOption& option);
template <SchemaEnum E>
QString labelOf(const EnumOption<E>& option) {
  return labelOf(option.what);
}

}  // namespace tetskin::gui
