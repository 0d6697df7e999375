// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One schema per enum and per numeric option: what files, the command line,
// the GUI and Python call a value, its help, range and default, declared
// once beside the type and read by toString, the parsers, the range checks,
// the command line's options and the GUI's widgets, so that they cannot
// drift apart (the way F3D generates its options from one description).
//
// An enum E takes part by a specialization beside it:
//
//   template <> struct EnumSchema<Tangent> {
//     static constexpr const char* what = "tangent";  // in errors
//     static constexpr EnumValue<Tangent> values[] = {
//         {Tangent::Full, "full", "R K R^T and the rotation term"},
//         {Tangent::Warped, "warped", "R K R^T alone"}};
//     static constexpr bool anyCase = false;  // optional: "X" reads as "x"
//   };
//
// after which toString(E), parseName<E>, fromName<E>, namesOf<E> and
// helpOf<E> work for it; the order of `values` is the order offered.

#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tetskin/core/Error.h"

namespace tetskin {

template <class E>
struct EnumValue {
  E value;
  const char* name;
  const char* help;
};

template <class E>
struct EnumSchema;

template <class E>
concept SchemaEnum = requires {
  EnumSchema<E>::what;
  EnumSchema<E>::values;
};

namespace schema_detail {
template <class E>
constexpr bool anyCase() {
  if constexpr (requires { EnumSchema<E>::anyCase; })
    return EnumSchema<E>::anyCase;
  else
    return false;
}
inline bool sameName(std::string_view a, std::string_view b, bool anyCase) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto x = static_cast<unsigned char>(a[i]), y = static_cast<unsigned char>(b[i]);
    if (anyCase ? std::tolower(x) != std::tolower(y) : x != y) return false;
  }
  return true;
}
}  // namespace schema_detail

// The value's name ("?" for a value not in the schema).
template <SchemaEnum E>
const char* toString(E value) {
  for (const EnumValue<E>& v : EnumSchema<E>::values)
    if (v.value == value) return v.name;
  return "?";
}

// The value named `text`; nullopt for any other text.
template <SchemaEnum E>
std::optional<E> parseName(std::string_view text) {
  for (const EnumValue<E>& v : EnumSchema<E>::values)
    if (schema_detail::sameName(text, v.name, schema_detail::anyCase<E>())) return v.value;
  return std::nullopt;
}

// The names in the schema's order: the choices offered.
template <SchemaEnum E>
std::vector<std::string> namesOf() {
  std::vector<std::string> names;
  for (const EnumValue<E>& v : EnumSchema<E>::values) names.emplace_back(v.name);
  return names;
}

// "a, b, c": the names as a list.
std::string listed(const std::vector<std::string>& names);

// "a, b or c": the names as a choice.
std::string oneOf(const std::vector<std::string>& names);

// The value named `text`; throws Error "unknown render path 'fur' (known:
// cpu, gpu-1pass, ...)" for any other text.
template <SchemaEnum E>
E fromName(std::string_view text) {
  if (const std::optional<E> value = parseName<E>(text)) return *value;
  throw Error("unknown " + std::string(EnumSchema<E>::what) + " '" + std::string(text) +
              "' (known: " + listed(namesOf<E>()) + ")");
}

// "full (R K R^T and the rotation term) or warped (R K R^T alone)": the
// names with their help, for --help and tool tips.
template <SchemaEnum E>
std::string helpOf() {
  std::string text;
  const auto count = std::size(EnumSchema<E>::values);
  for (std::size_t i = 0; i < count; ++i) {
    const EnumValue<E>& v = EnumSchema<E>::values[i];
    if (i > 0) text += i + 1 == count ? " or " : ", ";
    text += v.name;
    if (*v.help) text += std::string(" (") + v.help + ")";
  }
  return text;
}

// The range of a number option: finite, between min and max, each bound
// included or not.
struct NumberRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minIncluded = true, maxIncluded = true;

  bool contains(double value) const {
    return std::isfinite(value) && (minIncluded ? value >= min : value > min) &&
           (maxIncluded ? value <= max : value < max);
  }
  // "must be finite and positive", "must be finite and >= 0", "must lie in
  // (-1, 0.5)": what a value out of the range is told.
  std::string words() const;
};

// Ranges by name: x > bound, x >= bound, and [min, max] with either end
// left out.
constexpr NumberRange above(double bound) {
  return {bound, std::numeric_limits<double>::infinity(), false, true};
}
constexpr NumberRange atLeast(double bound) {
  return {bound, std::numeric_limits<double>::infinity(), true, true};
}
constexpr NumberRange between(double min, double max, bool minIncluded = true,
                              bool maxIncluded = true) {
  return {min, max, minIncluded, maxIncluded};
}

// How a front end's user names an option, in its errors and warnings: the
// command line's flags ("--poisson", "--fixed-box"), Python's and the
// files' keys ("poisson_ratio", "fixed_box"), or the GUI's words
// ("Poisson's ratio", "the fixed box").
enum class OptionNames { Flags, Keys, Words };

// A number option of a run: its key (snake_case: a config's, Python's), its
// command-line flag (the key in kebab case, after a section's prefix:
// --poisson-ratio, --fur-length; "" where the command line has none), the
// flag it had before flag and key agreed ("" for none: the command line and
// Python still read it, with a warning, as F3D marks deprecated options),
// its name in messages, its help (--help, tool tips), its range and its
// default.
struct NumberOption {
  const char* key;
  const char* flag;
  const char* oldFlag;  // "--poisson": read, with a warning
  const char* what;     // "Poisson's ratio"
  const char* help;     // "Poisson's ratio, in (-1, 0.5)"
  NumberRange range;
  double defaultValue;
  // What an error says of the range, where it is not range.words():
  // "in [0, 1)" reads "the base share must be in [0, 1), got 1".
  const char* rangeWords = nullptr;

  // "Poisson's ratio must lie in (-1, 0.5), got 0.5"; nullopt when `value`
  // is in the range.
  std::optional<std::string> problem(double value) const;
};

// An on/off option of a run (the fur's fins): its key, its command-line
// flag (taking true or false), the flag it had before flag and key agreed
// ("" for none; read with a warning), its name in messages, its help and
// its default.
struct SwitchOption {
  const char* key;
  const char* flag;
  const char* oldFlag;
  const char* what;
  const char* help;
  bool defaultValue;
};

// An option of a run that is not one number: node ids, a box, loads and
// their curve, a vector. Its key (a config's, Python's keyword), its
// command-line flag, its name in messages and the GUI's label ("the fixed
// box"), and its help: what it
// means, which each front end follows with the form it takes there (a
// text file, an array, a field).
struct ListOption {
  const char* key;
  const char* flag;
  const char* what;
  const char* help;
};

// An option whose value is one of an enum's names (the solver, the up
// axis, the render path): its key, its command-line flag (the key in kebab
// case), its name in messages and the GUI's label ("the solver"), and what
// its help says before the names and theirs ("multigrid: "; helpOf). Its
// default is the field's in the settings it sets (SimulationOptions,
// BindingOptions, ...): one place, which every front end reads.
template <SchemaEnum E>
struct EnumOption {
  const char* key;
  const char* flag;
  const char* what;
  const char* help = "";

  // "multigrid: galerkin (P^T A P) or rediscretized (...)": --help's text
  // and the GUI's tool tip.
  std::string fullHelp() const { return help + helpOf<E>(); }
};

// How a front end's user names `option` (a NumberOption, ListOption or
// EnumOption; OptionNames): "--poisson-ratio", "poisson_ratio" or
// "Poisson's ratio".
template <class Option>
requires requires(const Option& o) {
  o.key;
  o.flag;
  o.what;
}
std::string nameOf(const Option& option, OptionNames names) {
  return names == OptionNames::Flags  ? option.flag
         : names == OptionNames::Keys ? option.key
                                      : option.what;
}

// "--old: is deprecated, use --new (the same option)": the warning an old
// name's use gets, `oldName` and `name` as the front end's user writes
// them.
std::string deprecatedName(const std::string& oldName, const std::string& name);

// "--push-frequency" -> "push_frequency": a flag as Python's keyword (""
// for "").
std::string keywordOf(std::string_view flag);

}  // namespace tetskin
