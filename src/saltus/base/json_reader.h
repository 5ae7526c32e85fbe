#pragma once
/// @file
/// Typed, path-tracking access to a parsed JSON document. Every loader (models, motions) reads
/// through JsonNode so that every error names the file and the JSON pointer of the bad value,
/// as docs/formats.md requires.

#include <Eigen/Core>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"

namespace saltus {

/// The largest file read_json_file reads. A 500-keyframe motion is 0.5 MB and a model a few
/// kB; anything beyond this is the wrong file (or a device such as /dev/zero), refused before
/// it is read.
inline constexpr std::size_t kMaxJsonFileBytes = 64u * 1024u * 1024u;
/// The deepest nesting of arrays and objects accepted; Saltus's formats nest at most 5 deep.
inline constexpr std::size_t kMaxJsonDepth = 64;

/// Reads and parses a JSON file. Throws InputError naming the file (and the JSON pointer or
/// line/column) when the file name is not valid UTF-8, the file cannot be opened, is not a
/// regular file or is larger than kMaxJsonFileBytes, or its text is not JSON: syntax, ill-formed
/// UTF-8, a number beyond double's range (1e400), an object with the same key twice, nesting
/// deeper than kMaxJsonDepth.
nlohmann::json read_json_file(const std::string& path);

/// Parses JSON text with the checks of read_json_file; `file` names it in messages.
nlohmann::json parse_json_text(const std::string& text, const std::string& file);

/// The candidate closest to `name` by edit distance (case-insensitive) if it is close enough to
/// be a likely typo (at most a third of the name's length, at least 1, edits), else "".
std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates);

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
  /// Requires an object whose keys are all in `allowed`. A typo such as "tolerence" would
  /// otherwise be ignored silently and a default used; the message names the unknown key at its
  /// own path and suggests the nearest allowed one.
  void require_keys_within(const std::vector<std::string>& allowed) const;
  /// Finite number (rejects NaN/inf, strings, booleans).
  double as_double() const;
  /// Finite number in [low, high]; the message gives the range with `unit` (e.g. "kg").
  double as_double_within(double low, double high, const std::string& unit) const;
  int as_int() const;
  std::string as_string() const;
  /// Array of exactly `n` finite numbers.
  std::vector<double> as_doubles(std::size_t n) const;
  /// Array of any length of finite numbers.
  std::vector<double> as_double_array() const;
  Eigen::Vector3d as_vector3() const;
  /// Three finite numbers, each in [-limit, limit].
  Eigen::Vector3d as_vector3_within(double limit, const std::string& unit) const;

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

/// Escapes a key for use in a JSON pointer (RFC 6901).
std::string json_pointer_escape(const std::string& key);

}  // namespace saltus
