// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/OptionSchema.h"

namespace tetskin {

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::string oneOf(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return text;
}

std::string NumberRange::words() const {
  if (std::isinf(max) && std::isinf(min)) return "must be finite";
  if (std::isinf(max)) {
    if (min == 0 && !minIncluded) return "must be finite and positive";
    return std::string("must be finite and ") + (minIncluded ? ">= " : "> ") + formatNumber(min);
  }
  return std::string("must lie in ") + (minIncluded ? "[" : "(") + formatNumber(min) + ", " +
         formatNumber(max) + (maxIncluded ? "]" : ")");
}

std::optional<std::string> NumberOption::problem(double value) const {
  if (range.contains(value)) return std::nullopt;
  const std::string words = rangeWords ? std::string("must be ") + rangeWords : range.words();
  return std::string(what) + " " + words + ", got " + formatNumber(value);
}

std::string deprecatedName(const std::string& oldName, const std::string& name) {
  return oldName + ": is deprecated, use " + name + " (the same option)";
}

std::string keywordOf(std::string_view flag) {
  std::string name(flag);
  while (!name.empty() && name.front() == '-') name.erase(name.begin());
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

}  // namespace tetskin
