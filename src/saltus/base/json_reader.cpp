#include "saltus/base/json_reader.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>

#include "saltus/base/input_file.h"
#include "saltus/base/text_format.h"

namespace saltus {

namespace {

/// Builds the document from nlohmann's SAX events while tracking where it is, so that a
/// duplicate key, a number out of range or too deep a nesting is reported with its JSON pointer.
/// (nlohmann's own DOM parser keeps the last of two equal keys and reports 1e400 as an
/// out_of_range exception without a position.)
class TrackingSax {
 public:
  using json = nlohmann::json;

  TrackingSax(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  json take() { return std::move(root_); }

  bool null() { return add(json(nullptr)); }
  bool boolean(bool v) { return add(json(v)); }
  bool number_integer(json::number_integer_t v) { return add(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return add(json(v)); }
  bool number_float(json::number_float_t v, const json::string_t&) { return add(json(v)); }
  bool string(json::string_t& v) { return add(json(std::move(v))); }
  bool binary(json::binary_t&) { return add(json(nullptr)); }  // not produced by JSON text

  bool start_object(std::size_t) { return open(json::object()); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(json::string_t& key) {
    json& object = *open_.back();
    if (object.contains(key))
      throw InputError(file_, pointer() + "/" + json_pointer_escape(key),
                       "the key \"" + printable(key) +
                           "\" appears twice in this object (JSON readers disagree on which "
                           "one counts; keep one)");
    keys_.back() = key;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& e) {
    if (e.id == 406) {  // out_of_range: number overflow, e.g. 1e400
      throw InputError(file_, pointer_of_next_value(),
                       "number " + printable(last_token) +
                           " is out of range (a double's magnitude is at most 1.8e308); at " +
                           line_and_column(position));
    }
    // e.what() carries "line L, column C" which is what a user needs to find the typo.
    const std::string what = e.what();
    const auto at = what.find("parse error");
    throw InputError(
        file_, "", "invalid JSON: " + printable(at == std::string::npos ? what : what.substr(at)));
  }

 private:
  json* place(json&& value) {
    if (open_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    json& parent = *open_.back();
    if (parent.is_array()) {
      parent.push_back(std::move(value));
      return &parent.back();
    }
    json& slot = parent[keys_.back()];
    slot = std::move(value);
    return &slot;
  }

  bool add(json&& value) {
    place(std::move(value));
    return true;
  }

  bool open(json&& container) {
    if (open_.size() >= kMaxJsonDepth)
      throw InputError(file_, pointer_of_next_value(),
                       "nested deeper than " + std::to_string(kMaxJsonDepth) +
                           " levels (Saltus files nest a few levels)");
    json* p = place(std::move(container));
    open_.push_back(p);
    keys_.emplace_back();
    return true;
  }

  bool close() {
    open_.pop_back();
    keys_.pop_back();
    return true;
  }

  /// JSON pointer of the innermost open container.
  std::string pointer() const {
    std::string out;
    for (std::size_t level = 0; level + 1 < open_.size(); ++level)
      out += "/" + component(level);
    return out;
  }

  /// The component that leads from open container `level` to the one inside it.
  std::string component(std::size_t level) const {
    const json& container = *open_[level];
    if (container.is_array()) return std::to_string(container.size() - 1);
    return json_pointer_escape(keys_[level]);
  }

  /// Where the value being parsed now goes.
  std::string pointer_of_next_value() const {
    if (open_.empty()) return "";
    const json& container = *open_.back();
    const std::string last =
        container.is_array() ? std::to_string(container.size()) : json_pointer_escape(keys_.back());
    return pointer() + "/" + last;
  }

  std::string line_and_column(std::size_t position) const {
    std::size_t line = 1;
    std::size_t column = 1;
    for (std::size_t i = 0; i < position && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
  }

  const std::string& text_;
  const std::string& file_;
  json root_;
  std::vector<json*> open_;        ///< open containers, outermost first
  std::vector<std::string> keys_;  ///< per open container: the current key (objects)
};

}  // namespace

std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates) {
  const auto lower = [](std::string s) {
    for (char& c : s)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  const std::string a = lower(name);
  std::string best;
  std::size_t best_distance = std::string::npos;
  for (const std::string& candidate : candidates) {
    const std::string b = lower(candidate);
    // Levenshtein distance, one row at a time.
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
      row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      std::size_t diagonal = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const std::size_t above = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diagonal = above;
      }
    }
    if (row[b.size()] < best_distance) {
      best_distance = row[b.size()];
      best = candidate;
    }
  }
  const std::size_t allowed = std::max<std::size_t>(1, name.size() / 3);
  return best_distance <= allowed ? best : std::string();
}

nlohmann::json parse_json_text(const std::string& text, const std::string& file) {
  TrackingSax sax(text, file);
  nlohmann::json::sax_parse(text, &sax);
  return sax.take();
}

nlohmann::json read_json_file(const std::string& path) {
  return parse_json_text(read_input_file(path, kMaxJsonFileBytes, "model and motion files"), path);
}

std::string json_pointer_escape(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

bool JsonNode::has(const std::string& key) const {
  return value_->is_object() && value_->contains(key);
}

JsonNode JsonNode::at(const std::string& key) const {
  require_object();
  auto it = value_->find(key);
  if (it == value_->end()) fail("missing field \"" + key + "\"");
  return JsonNode(*it, file_, path_ + "/" + json_pointer_escape(key));
}

std::optional<JsonNode> JsonNode::find(const std::string& key) const {
  require_object();
  auto it = value_->find(key);
  if (it == value_->end() || it->is_null()) return std::nullopt;
  return JsonNode(*it, file_, path_ + "/" + json_pointer_escape(key));
}

JsonNode JsonNode::at(std::size_t index) const {
  require_array();
  if (index >= value_->size()) fail("index " + std::to_string(index) + " out of range");
  return JsonNode((*value_)[index], file_, path_ + "/" + std::to_string(index));
}

std::size_t JsonNode::size() const {
  require_array();
  return value_->size();
}

std::vector<std::pair<std::string, JsonNode>> JsonNode::members() const {
  require_object();
  std::vector<std::pair<std::string, JsonNode>> out;
  for (auto it = value_->begin(); it != value_->end(); ++it)
    out.emplace_back(it.key(),
                     JsonNode(it.value(), file_, path_ + "/" + json_pointer_escape(it.key())));
  return out;
}

void JsonNode::fail(const std::string& problem) const {
  throw InputError(file_, path_or_root(), problem);
}

namespace {
std::string type_name(const nlohmann::json& v) {
  return v.type_name();
}
}  // namespace

void JsonNode::require_object() const {
  if (!value_->is_object()) fail("expected an object, found " + type_name(*value_));
}

void JsonNode::require_array() const {
  if (!value_->is_array()) fail("expected an array, found " + type_name(*value_));
}

void JsonNode::require_keys_within(const std::vector<std::string>& allowed) const {
  require_object();
  for (const auto& [key, child] : members()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (const std::string& a : allowed)
      list += (list.empty() ? "\"" : ", \"") + a + "\"";
    const std::string suggestion = nearest_name(key, allowed);
    child.fail("unknown field \"" + printable(key) + "\"" +
               (suggestion.empty() ? std::string() : " (did you mean \"" + suggestion + "\"?)") +
               "; allowed here: " + list);
  }
}

double JsonNode::as_double() const {
  if (!value_->is_number()) fail("expected a number, found " + type_name(*value_));
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("expected a finite number");
  return v;
}

double JsonNode::as_double_within(double low, double high, const std::string& unit) const {
  const double v = as_double();
  if (!(v >= low && v <= high)) {
    const std::string u = unit.empty() ? std::string() : " " + unit;
    fail(message_number_beside(v, low, high) + u + " is outside the plausible range [" +
         message_number(low) + ", " + message_number(high) + "]" + u);
  }
  return v;
}

int JsonNode::as_int() const {
  if (!value_->is_number_integer()) fail("expected an integer, found " + type_name(*value_));
  if (value_->is_number_unsigned()) {
    const auto v = value_->get<nlohmann::json::number_unsigned_t>();
    if (v > static_cast<nlohmann::json::number_unsigned_t>(INT_MAX))
      fail("integer " + std::to_string(v) + " is too large");
    return static_cast<int>(v);
  }
  const auto v = value_->get<nlohmann::json::number_integer_t>();
  if (v < INT_MIN || v > INT_MAX) fail("integer " + std::to_string(v) + " is out of range");
  return static_cast<int>(v);
}

std::string JsonNode::as_string() const {
  if (!value_->is_string()) fail("expected a string, found " + type_name(*value_));
  return value_->get<std::string>();
}

std::vector<double> JsonNode::as_double_array() const {
  require_array();
  std::vector<double> out;
  out.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i)
    out.push_back(at(i).as_double());
  return out;
}

std::vector<double> JsonNode::as_doubles(std::size_t n) const {
  require_array();
  if (value_->size() != n)
    fail("expected " + std::to_string(n) + " numbers, found " + std::to_string(value_->size()));
  return as_double_array();
}

Eigen::Vector3d JsonNode::as_vector3() const {
  const auto v = as_doubles(3);
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

Eigen::Vector3d JsonNode::as_vector3_within(double limit, const std::string& unit) const {
  as_doubles(3);  // shape and finiteness first
  Eigen::Vector3d out;
  for (std::size_t k = 0; k < 3; ++k)
    out[static_cast<Eigen::Index>(k)] = at(k).as_double_within(-limit, limit, unit);
  return out;
}

}  // namespace saltus
