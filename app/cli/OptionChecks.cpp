// SPDX-License-Identifier: AGPL-3.0-or-later
#include "OptionChecks.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

#include "tetskin/core/Error.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::cli {

namespace {

// Whether all of `text` reads as one number, into `value`. A leading '+'
// is allowed on floating-point numbers only: CLI11's own conversion reads
// "+0.5" as a double but fails on "+5" as an integer.
template <typename Number>
bool parsesAll(const std::string& text, Number& value) {
  const bool plus = std::is_floating_point_v<Number> && text.size() > 1 && text[0] == '+';
  const char* first = text.data() + (plus ? 1 : 0);
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(first, end, value);
  return !text.empty() && error == std::errc{} && stop == end;
}

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace

CLI::Validator wholeNumber(long long min, long long max) {
  const bool bounded = max != std::numeric_limits<int>::max();
  const std::string interval = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  const std::string range = bounded ? "in " + interval : ">= " + std::to_string(min);
  return CLI::Validator(
      [min, max, range, interval](std::string& text) -> std::string {
        long long value = 0;
        if (!parsesAll(text, value)) return "'" + text + "' is not a whole number";
        if (value < min) return text + " is not " + range;
        // (The whole interval: an unbounded check shows only its minimum.)
        if (value > max) return text + " is not in " + interval;
        return {};
      },
      // Shown in --help after the type, as CLI11's own checks are.
      bounded    ? interval
      : min == 0 ? "NONNEGATIVE"
      : min == 1 ? "POSITIVE"
                 : range);
}

// The two below are wholeNumber's and numberAbove's checks without a bound
// of their own, and so with nothing to add to --help.
CLI::Validator anyWholeNumber() {
  return wholeNumber(std::numeric_limits<int>::min()).description("");
}

CLI::Validator finiteNumber() {
  return numberAbove(-std::numeric_limits<double>::infinity()).description("");
}

CLI::Validator trueOrFalse() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string word = lowerCase(text);
        for (const char* known : {"true", "false", "on", "off", "yes", "no", "1", "0"})
          if (word == known) return {};
        return "'" + text + "' is not true or false";
      },
      "true/false");
}

CLI::Validator positiveNumber() {
  return numberAbove(0);
}

CLI::Validator numberAbove(double bound) {
  const std::string limit = formatNumber(bound);
  return CLI::Validator(
      [bound, limit](std::string& text) -> std::string {
        double value = 0;
        if (!parsesAll(text, value) || !std::isfinite(value))
          return "'" + text + "' is not a finite number";
        if (!(value > bound)) return text + " is not > " + limit;
        return {};
      },
      // Shown in --help after the type, as CLI11's own checks are.
      bound == 0 ? "POSITIVE" : "> " + limit);
}

CLI::Validator numberFrom(double min, double below) {
  const std::string range = std::isinf(below)
                                ? ">= " + formatNumber(min)
                                : "in [" + formatNumber(min) + ", " + formatNumber(below) + ")";
  return CLI::Validator(
      [min, below, range](std::string& text) -> std::string {
        double value = 0;
        if (!parsesAll(text, value) || !std::isfinite(value))
          return "'" + text + "' is not a finite number";
        if (!(value >= min && value < below)) return text + " is not " + range;
        return {};
      },
      // Shown in --help after the type, as CLI11's own checks are.
      std::isinf(below) ? (min == 0 ? "NONNEGATIVE" : range) : range.substr(3));
}

CLI::Validator numberIn(const NumberRange& range) {
  if (std::isinf(range.min) && std::isinf(range.max)) return finiteNumber();
  if (std::isinf(range.max))
    return range.minIncluded ? numberFrom(range.min) : numberAbove(range.min);
  if (range.minIncluded && !range.maxIncluded) return numberFrom(range.min, range.max);
  std::string interval = range.words();  // "must lie in (0, 1)"
  interval = interval.substr(interval.find("in "));
  return CLI::Validator(
      [range, interval](std::string& text) -> std::string {
        double value = 0;
        if (!parsesAll(text, value) || !std::isfinite(value))
          return "'" + text + "' is not a finite number";
        if (!range.contains(value)) return text + " is not " + interval;
        return {};
      },
      interval.substr(3));
}

CLI::Validator wholeNumberIn(const NumberRange& range) {
  const long long least =
      std::isinf(range.min) ? std::numeric_limits<int>::min()
                            : static_cast<long long>(range.minIncluded ? std::ceil(range.min)
                                                                       : std::floor(range.min) + 1);
  if (std::isinf(range.max)) return wholeNumber(least);
  return wholeNumber(least, static_cast<long long>(range.maxIncluded ? std::floor(range.max)
                                                                     : std::ceil(range.max) - 1));
}

namespace {
std::string shownHelp(const NumberOption& option, const std::string& help) {
  return help.empty() ? option.help : help;
}
}  // namespace

CLI::Option* addNumberOption(CLI::App& cmd, const NumberOption& option, double& value,
                             const std::string& help) {
  return addFlagOf(cmd, option, value, shownHelp(option, help), numberIn(option.range))
      ->capture_default_str();
}

CLI::Option* addNumberOption(CLI::App& cmd, const NumberOption& option, Index& value,
                             const std::string& help) {
  return addFlagOf(cmd, option, value, shownHelp(option, help), wholeNumberIn(option.range))
      ->capture_default_str();
}

CLI::Option* addNumberOption(CLI::App& cmd, const NumberOption& option, int& value,
                             const std::string& help) {
  return addFlagOf(cmd, option, value, shownHelp(option, help), wholeNumberIn(option.range))
      ->capture_default_str();
}

CLI::Validator fileEnding(const std::string& extension) {
  return fileEnding(std::vector<std::string>{extension});
}

CLI::Validator fileEnding(const std::vector<std::string>& extensions) {
  return CLI::Validator(
      [extensions](std::string& text) -> std::string {
        const std::string given = lowerCase(std::filesystem::path(text).extension().string());
        std::string names;
        for (const std::string& extension : extensions) {
          if (given == lowerCase(extension)) return {};
          names += (names.empty() ? "" : " or ") + extension;
        }
        return "'" + text + "' does not end in " + names;
      },
      "");
}

CLI::Validator imageSize() {
  return CLI::Validator([](std::string& text) { return imageSizeProblem(text); }, "");
}

ImageSize checkedImageSize(const std::string& text) {
  const std::optional<ImageSize> size = parseImageSize(text);
  if (!size) throw Error("--size: " + imageSizeProblem(text));
  return *size;
}

void requireNotAnInput(const std::filesystem::path& output,
                       std::initializer_list<std::filesystem::path> inputs) {
  for (const std::filesystem::path& input : inputs) {
    std::error_code error;  // (a missing output, or input, is no clash)
    if (!input.empty() && std::filesystem::equivalent(output, input, error))
      throw Error(output.string(), 0, "is also an input of this command; write to another file");
  }
}

std::optional<std::string> givenOptionOf(const CLI::App& cmd, const std::string& group) {
  for (const CLI::Option* option : cmd.get_options()) {
    if (option->count() == 0) continue;
    if (option->get_group() == group) return option->get_name();
  }
  // An old flag (hidden, addFlagOf) stands in for its option.
  for (const CLI::Option* old : cmd.get_options()) {
    const std::string& about = old->get_description();
    if (old->count() == 0 || about.rfind(kOldNameOf, 0) != 0) continue;
    if (const CLI::Option* current = cmd.get_option_no_throw(about.substr(kOldNameOf.size()));
        current && current->get_group() == group)
      return old->get_name();
  }
  return std::nullopt;
}

std::optional<std::string> givenName(const CLI::App& cmd, const NumberOption& option) {
  if (*option.flag && cmd.count(option.flag) > 0) return option.flag;
  if (*option.oldFlag && cmd.count(option.oldFlag) > 0) return option.oldFlag;
  return std::nullopt;
}

void warnOfOldName(const std::string& warning) {
  std::fprintf(stderr, "warning: %s\n", warning.c_str());
}

void addCompressOption(CLI::App& cmd) {
  auto name = std::make_shared<std::string>(toString(vtkCompression()));
  addEnumOption(cmd, kCompressOption, *name)->each([name](const std::string& given) {
    setVtkCompression(fromName<VtkCompression>(given));
  });
}

CLI::Option* addDatasetOrSceneArgument(CLI::App& cmd, std::filesystem::path& dataset,
                                       const std::string& sceneUse) {
  return cmd
      .add_option(
          "DATASET", dataset,
          std::string(kDatasetHelp) + "; or a scene (.json, format tetskin-scene): " + sceneUse)
      ->required()
      ->check(CLI::ExistingFile);
}

}  // namespace tetskin::cli
