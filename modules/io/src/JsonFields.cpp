// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/JsonFields.h"

#include <algorithm>
#include <cmath>

#include "TextLines.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/NumberText.h"

namespace tetskin {

using nlohmann::json;

json parseJsonText(std::string_view content, const std::string& sourceName) {
  try {
    return json::parse(content);
  } catch (const json::parse_error& e) {
    // Turn nlohmann's byte offset into the line a person looks for.
    const std::size_t byte = std::min<std::size_t>(e.byte, content.size());
    const long line =
        1 + std::count(content.begin(), content.begin() + static_cast<long>(byte), '\n');
    std::string what = e.what();
    if (const auto pos = what.find("parse error"); pos != std::string::npos)
      what = what.substr(pos);
    throw Error(sourceName, line, "invalid JSON: " + what);
  } catch (const json::exception& e) {
    // A number beyond a double ("number overflow parsing '1e999'", found by
    // fuzz_config): the line of the text it quotes.
    const std::string what = e.what();
    const std::size_t open = what.find('\''), close = what.rfind('\'');
    long line = 0;
    if (open != std::string::npos && close > open + 1)
      if (const std::size_t at = content.find(what.substr(open + 1, close - open - 1));
          at != std::string_view::npos)
        line = 1 + std::count(content.begin(), content.begin() + static_cast<long>(at), '\n');
    const std::size_t bracket = what.find("] ");
    throw Error(
        sourceName, line,
        "invalid JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  }
}

json readJsonFile(const std::filesystem::path& path) {
  return parseJsonText(detail::readWholeFile(path), path.string());
}

JsonFields::JsonFields(const json& object, std::string pointer, std::string file)
    : object_(object), pointer_(std::move(pointer)), file_(std::move(file)) {
  if (!object_.is_object()) fail(pointer_.empty() ? "/" : pointer_, "must be an object");
}

void JsonFields::fail(const std::string& where, const std::string& what) const {
  throw Error(file_, 0, (where.empty() ? "/" : where) + ": " + what);
}

const json& JsonFields::get(const char* key) const {
  seen_.insert(key);
  if (!object_.contains(key)) fail(where(key), "is missing");
  return object_[key];
}

double JsonFields::number(const char* key, double min, double max, bool minExclusive) const {
  const json& v = get(key);
  if (!v.is_number()) fail(where(key), "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < min || x > max || (minExclusive && x == min))
    fail(where(key), outOfRange(min, max, minExclusive, v.dump()));
  return x;
}

long long JsonFields::integer(const char* key, long long min, long long max) const {
  const json& v = get(key);
  if (!v.is_number_integer()) fail(where(key), "must be an integer");
  const long long x = v.get<long long>();
  if (x < min || x > max)
    fail(where(key), "must lie in [" + std::to_string(min) + ", " + std::to_string(max) +
                         "], found " + std::to_string(x));
  return x;
}

bool JsonFields::boolean(const char* key) const {
  const json& v = get(key);
  if (!v.is_boolean()) fail(where(key), "must be true or false");
  return v.get<bool>();
}

std::string JsonFields::string(const char* key) const {
  const json& v = get(key);
  if (!v.is_string() || v.get<std::string>().empty())
    fail(where(key), "must be a non-empty string");
  return v.get<std::string>();
}

std::optional<std::string> JsonFields::optionalString(const char* key) const {
  seen_.insert(key);
  if (!has(key)) return std::nullopt;
  return string(key);
}

Eigen::VectorXd JsonFields::numbers(const char* key, int size) const {
  const json& v = get(key);
  const auto wrong = [&] {
    fail(where(key),
         "must be an array of " + std::to_string(size) + " finite numbers, found " + v.dump());
  };
  if (!v.is_array() || v.size() != static_cast<std::size_t>(size)) wrong();
  Eigen::VectorXd out(size);
  for (int i = 0; i < size; ++i) {
    if (!v[static_cast<std::size_t>(i)].is_number()) wrong();
    out[i] = v[static_cast<std::size_t>(i)].get<double>();
    if (!std::isfinite(out[i])) wrong();
  }
  return out;
}

void JsonFields::rejectUnknown() const {
  for (const auto& [key, value] : object_.items())
    if (!seen_.contains(key)) fail(pointer_ + "/" + key, "is not a known field");
}

}  // namespace tetskin
