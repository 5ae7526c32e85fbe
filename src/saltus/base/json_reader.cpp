#include "saltus/base/json_reader.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace saltus {

nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open file for reading");
  std::stringstream buffer;
  buffer << in.rdbuf();
  try {
    return nlohmann::json::parse(buffer.str());
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() carries "line L, column C" which is what a user needs to find the typo.
    std::string what = e.what();
    const auto pos = what.find("parse error");
    throw InputError(path, "",
                     "invalid JSON: " + (pos == std::string::npos ? what : what.substr(pos)));
  }
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

double JsonNode::as_double() const {
  if (!value_->is_number()) fail("expected a number, found " + type_name(*value_));
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("expected a finite number");
  return v;
}

int JsonNode::as_int() const {
  if (!value_->is_number_integer()) fail("expected an integer, found " + type_name(*value_));
  return value_->get<int>();
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

}  // namespace saltus
