// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Reading a JSON file a person wrote (the dataset config, a scene): the
// text parsed with errors that name its line, and one object's fields read
// by type, each error naming the file and the field's JSON pointer
// ("bowl.json: /obstacles/0/scale: must be a number"); keys nobody asked
// for are refused, so a typo does not pass silently.

#include <Eigen/Core>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace tetskin {

// `content` parsed; throws Error naming `sourceName` and the line of a
// syntax error or of a number beyond a double.
nlohmann::json parseJsonText(std::string_view content, const std::string& sourceName);
// The JSON file at `path`, parsed as parseJsonText parses; throws Error
// naming the file when it cannot be read.
nlohmann::json readJsonFile(const std::filesystem::path& path);

class JsonFields {
 public:
  // The object at `pointer` ("" for the root) of the file `file`; throws
  // Error when it is no object.
  JsonFields(const nlohmann::json& object, std::string pointer, std::string file);

  [[noreturn]] void fail(const std::string& where, const std::string& what) const;

  bool has(const char* key) const { return object_.contains(key) && !object_[key].is_null(); }
  // The field, marked as asked for; throws when it is missing.
  const nlohmann::json& get(const char* key) const;
  std::string where(const char* key) const { return pointer_ + "/" + key; }
  const std::string& pointer() const { return pointer_; }
  const std::string& file() const { return file_; }

  // A number in [min, max] (min excluded if `minExclusive`).
  double number(const char* key, double min, double max, bool minExclusive = false) const;
  long long integer(const char* key, long long min, long long max) const;
  // Any finite number; its range is checked elsewhere.
  double anyNumber(const char* key) const {
    constexpr double kLargest = std::numeric_limits<double>::max();
    return number(key, -kLargest, kLargest);
  }
  bool boolean(const char* key) const;
  // A non-empty string.
  std::string string(const char* key) const;
  std::optional<std::string> optionalString(const char* key) const;
  // An array of `size` finite numbers.
  Eigen::VectorXd numbers(const char* key, int size) const;
  Eigen::Vector3d vector3(const char* key) const { return numbers(key, 3); }

  // Marks `key` as known, present or not.
  void optional(const char* key) const { seen_.insert(key); }
  // Throws for the first key that was never asked for.
  void rejectUnknown() const;

 private:
  const nlohmann::json& object_;
  std::string pointer_;
  std::string file_;
  mutable std::set<std::string> seen_;
};

}  // namespace tetskin
