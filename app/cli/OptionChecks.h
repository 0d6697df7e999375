// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Checks on option values with messages a user can act on. CLI11's own
// PositiveNumber and Range name the range 0 to 1.8e308, accept "nan" and
// "inf", and let "1e3" through to an integer conversion that then reports a
// count of arguments.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tetskin/core/OptionSchema.h"
#include "tetskin/core/Types.h"
#include "tetskin/rendering/ImageSize.h"

namespace tetskin::cli {

// A whole number in [min, max] (digits with an optional sign).
CLI::Validator wholeNumber(long long min, long long max = std::numeric_limits<int>::max());

// --help of the DATASET arguments (loadDataset, io Dataset.h).
inline constexpr const char* kDatasetHelp =
    "dataset (.json, a .node/.ele pair, a Gmsh .msh or a MEDIT .mesh)";

// The required DATASET argument of a command that also takes a scene
// (simulate, render, compare); `sceneUse` says what it takes of one.
CLI::Option* addDatasetOrSceneArgument(CLI::App& cmd, std::filesystem::path& dataset,
                                       const std::string& sceneUse);

// A whole number of any sign, e.g. --level (negative counts from the
// finest) or an option whose range a module checks with its own message.
CLI::Validator anyWholeNumber();

// A finite number of any sign (its range checked where it is used).
CLI::Validator finiteNumber();

// A finite number > 0.
CLI::Validator positiveNumber();

// A finite number > `bound` (each element, on a list option).
CLI::Validator numberAbove(double bound);

// A finite number in [min, below) (below infinite: >= min).
CLI::Validator numberFrom(double min, double below = std::numeric_limits<double>::infinity());

// A finite number in `range` (OptionSchema.h), by the checks above where
// one fits; a whole number in it for wholeNumberIn.
CLI::Validator numberIn(const NumberRange& range);
CLI::Validator wholeNumberIn(const NumberRange& range);

// A schema option (OptionSchema.h) on `cmd`: its flag, its help, its
// default shown, its range checked.
// The description of an old flag's hidden option: this and the flag's name.
inline const std::string kOldNameOf = "old name of ";

// Prints "warning: WARNING" on stderr.
void warnOfOldName(const std::string& warning);

// `option`'s flag bound to `value`, with `help`, checked by `check`; and
// its old flag (a NumberOption's or SwitchOption's oldFlag), if it has one: the same value,
// hidden from --help, checked alike, a warning when it is used, an error
// beside the new flag. Returns the flag's option.
template <class Option, class T>
CLI::Option* addFlagOf(CLI::App& cmd, const Option& option, T& value, const std::string& help,
                       const CLI::Validator& check) {
  CLI::Option* current = cmd.add_option(option.flag, value, help)->check(check);
  if (!*option.oldFlag) return current;
  const std::string warning = deprecatedName(option.oldFlag, option.flag);
  const std::string old = option.oldFlag;
  const std::string both = "is the same option as " + std::string(option.flag) + ": give one";
  cmd.add_option(option.oldFlag, value, kOldNameOf + option.flag)
      ->check(check)
      ->group("")
      ->each([warning, old, both, current](const std::string&) {
        if (current->count() > 0) throw Error(old + ": " + both);
        warnOfOldName(warning);
      });
  return current;
}

// A number option (OptionSchema.h) on `cmd`: its flag (and old flag), its
// help or `help` where the command words it its own way, its range
// checked, the default shown.
CLI::Option* addNumberOption(CLI::App& cmd, const NumberOption& option, double& value,
                             const std::string& help = "");
CLI::Option* addNumberOption(CLI::App& cmd, const NumberOption& option, int& value,
                             const std::string& help = "");
CLI::Option* addNumberOption(CLI::App& cmd, const NumberOption& option, Index& value,
                             const std::string& help = "");

// An enum option (OptionSchema.h) on `cmd`: its flag, its help with the
// names' and then `note` (what the option means to this command), the
// default shown, one of the names checked.
template <SchemaEnum E>
CLI::Option* addEnumOption(CLI::App& cmd, const EnumOption<E>& option, std::string& name,
                           const std::string& note = "") {
  return cmd.add_option(option.flag, name, option.fullHelp() + note)
      ->capture_default_str()
      ->check(CLI::IsMember(namesOf<E>()));
}

// --compress for a command that writes .vtp/.vtu files: their data's
// compression (VtkCompression, setVtkCompression), set as it is parsed.
void addCompressOption(CLI::App& cmd);

// true or false (also on/off, yes/no, 1/0, any letter case) for a bool
// option. CLI11 alone reads any whole number as true ("--fur-fins 2") and
// answers other words with "Could not convert".
CLI::Validator trueOrFalse();

// A file name ending in `extension` (e.g. ".vtp", any letter case): an
// output whose format is fixed, checked before any work so that a binding
// is not written as XML into "out.obj" nor a PNG into "image.jpg".
CLI::Validator fileEnding(const std::string& extension);
// One of `extensions` (render -o: an image .png or a movie .ogv).
CLI::Validator fileEnding(const std::vector<std::string>& extensions);

// An image size "WIDTHxHEIGHT" (rendering ImageSize.h) for --size; and its
// two numbers once the validator has passed it.
CLI::Validator imageSize();
ImageSize checkedImageSize(const std::string& text);

// Throws Error naming `output` when it is the same file as one of `inputs`
// (e.g. `convert a.obj a.obj`, `deform ... b.vtp -o b.vtp`): writing it
// would replace an input, and a binding overwritten by its deformed surface
// is lost.
void requireNotAnInput(const std::filesystem::path& output,
                       std::initializer_list<std::filesystem::path> inputs);

// The name of the first option of `group` (its --help heading) given on
// `cmd`'s command line, if any: for options that would change nothing in
// the run asked for, which are errors rather than silently ignored.
std::optional<std::string> givenOptionOf(const CLI::App& cmd, const std::string& group);
// The name `option` was given by on `cmd` (its flag, or its old flag), or
// nullopt.
std::optional<std::string> givenName(const CLI::App& cmd, const NumberOption& option);

}  // namespace tetskin::cli
