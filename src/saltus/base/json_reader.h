#pragma once
/// @file
/// Typed, path-tracking access to a parsed JSON document. Every loader (models, motions) reads
/// through JsonNode so that every error names the file and the JSON pointer of the bad value,
/// as DESIGN §4 requires.

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "saltus/base/input_error.h"

namespace saltus {

/// Parses a whole JSON file. Throws InputError naming the file (and line/column for syntax).
nlohmann::json read_json_file(const std::string& path);

/// A view of one JSON value plus where it sits (file label and JSON pointer).
class JsonNode {
 public:
  JsonNode(const nlohmann::json& value, std::string file, std::string path = "")
      : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

  const nlohmann::json& value() const { return *value_; }
  const std::string& file() const { return file_; }
  /// JSON pointer, "" for the document root, e.g. "/keyframes/3/time".
  const std::string& path() const { return path_; }
  std::string path_or_root() const { return path_.empty() ? std::string("/") : path_; }

  bool is_object() const { return value_->is_object(); }
  bool is_array() const { return value_->is_array(); }
  bool is_null() const { return value_->is_null(); }
  bool has(const std::string& key) const;

  /// Member `key` of an object; throws "missing field" if absent.
  JsonNode at(const std::string& key) const;
  /// Member `key` if present and not null.
  std::optional<JsonNode> find(const std::string& key) const;
  /// Element `index` of an array.
  JsonNode at(std::size_t index) const;
  std::size_t size() const;
  /// Object members in document order of the parser (nlohmann sorts keys).
  std::vector<std::pair<std::string, JsonNode>> members() const;

  /// Throw InputError("<file>: <path>: <problem>").
  [[noreturn]] void fail(const std::string& problem) const;

  void require_object() const;
  void require_array() const;
  /// Finite number (rejects NaN/inf, strings, booleans).
  double as_double() const;
  int as_int() const;
  std::string as_string() const;
  /// Array of exactly `n` finite numbers.
  std::vector<double> as_doubles(std::size_t n) const;
  /// Array of any length of finite numbers.
  std::vector<double> as_double_array() const;
  Eigen::Vector3d as_vector3() const;

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

/// Escapes a key for use in a JSON pointer (RFC 6901).
std::string json_pointer_escape(const std::string& key);

}  // namespace saltus
