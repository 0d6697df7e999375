// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Numbers as a reader should see them: to the digits that mean something
// beside the largest value shown with them. A reaction of
// (-1.2e-10, 20748.1, 2.9e-11) N is round-off around 20748.1 N and reads
// "0, 20748.1, 0"; an elastic energy of 5.9e-23 J at rest, beside a scale
// of joules, reads 0.

#include <Eigen/Core>
#include <string>

namespace tetskin {

// `value` to `digits` significant digits of `scale` (the largest magnitude
// shown beside it, or a floor below which values are noise): a value
// smaller than scale * 10^-digits in magnitude reads "0", a larger one
// keeps the digits down to that resolution and no more. A scale of 0 or
// below, or one not finite, is the value's own magnitude; non-finite values
// read as printf prints them.
std::string formatToScale(double value, double scale, int digits = 6);

// The three components to `digits` digits of the largest of them (or of
// `floor`, if larger), separated by commas: "0,20748.1,0".
std::string commaSeparatedToScale(const Eigen::Vector3d& v, int digits = 6, double floor = 0);

// "must lie in [min, max], found FOUND" ("(min" when min itself is
// excluded): the words of every range check (config fields, fur parameters).
std::string outOfRange(double min, double max, bool minExclusive, const std::string& found);

}  // namespace tetskin
