#include "saltus/formats/flight_page.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "saltus/base/input_error.h"
#include "saltus/formats/flight_page_assets.h"
#include "saltus/formats/output_folder.h"

namespace saltus {

namespace {

namespace fs = std::filesystem;

/// The template's placeholders, each replaced once.
constexpr const char* kThreePlaceholder = "/*SALTUS_THREE_JS*/";
constexpr const char* kOrbitPlaceholder = "/*SALTUS_ORBIT_CONTROLS_JS*/";
constexpr const char* kDataPlaceholder = "/*SALTUS_DATA*/";
constexpr const char* kVersionPlaceholder = "SALTUS_VERSION";
/// How the data's script element opens, in the template and so in every page.
constexpr const char* kDataOpening = "<script id=\"flight-data\" type=\"application/json\">";

void replace_once(std::string& text, const std::string& placeholder, const std::string& value) {
  const std::size_t at = text.find(placeholder);
  if (at == std::string::npos)
    throw std::logic_error("the flight page template has no " + placeholder);
  text.replace(at, placeholder.size(), value);
}

/// The first non-finite number's JSON pointer, or "".
std::string non_finite_at(const nlohmann::json& value, const std::string& pointer) {
  if (value.is_number_float()) return std::isfinite(value.get<double>()) ? "" : pointer;
  if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      std::string at = non_finite_at(value[i], pointer + "/" + std::to_string(i));
      if (!at.empty()) return at;
    }
  }
  if (value.is_object()) {
    for (const auto& [key, item] : value.items()) {
      std::string at = non_finite_at(item, pointer + "/" + key);
      if (!at.empty()) return at;
    }
  }
  return "";
}

}  // namespace

std::string flight_page_html(const nlohmann::json& data) {
  const std::string bad = non_finite_at(data, "");
  if (!bad.empty()) throw std::invalid_argument("flight page data: " + bad + " is not finite");
  // JSON inside a script element: '<' only occurs in strings, where \u003c means the same.
  std::string json;
  for (char c : data.dump())
    json += c == '<' ? std::string("\\u003c") : std::string(1, c);
  // The placeholders are found in the template before anything is put in, so no inserted text
  // is searched.
  std::string page = embedded_text(kFlightPageTemplate);
  replace_once(page, kVersionPlaceholder, kSaltusVersion);
  const std::size_t three = page.find(kThreePlaceholder);
  const std::size_t orbit = page.find(kOrbitPlaceholder);
  const std::size_t data_at = page.find(kDataPlaceholder);
  if (three == std::string::npos || orbit == std::string::npos || data_at == std::string::npos ||
      !(three < orbit && orbit < data_at))
    throw std::logic_error("the flight page template lacks its placeholders, in order");
  std::string out;
  out.reserve(page.size() + json.size() + 1000000);
  out.append(page, 0, three);
  out += embedded_text(kThreeJs);
  out.append(page, three + std::strlen(kThreePlaceholder),
             orbit - three - std::strlen(kThreePlaceholder));
  out += embedded_text(kOrbitControlsJs);
  out.append(page, orbit + std::strlen(kOrbitPlaceholder),
             data_at - orbit - std::strlen(kOrbitPlaceholder));
  out += json;
  out.append(page, data_at + std::strlen(kDataPlaceholder), std::string::npos);
  return out;
}

nlohmann::json read_flight_page_data(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string page = text.str();
  const std::size_t open = page.find(kDataOpening);
  const std::size_t start = open == std::string::npos ? open : open + std::strlen(kDataOpening);
  const std::size_t end = start == std::string::npos ? start : page.find("</script>", start);
  if (end == std::string::npos) throw InputError(path, "", "holds no flight data");
  try {
    return nlohmann::json::parse(page.substr(start, end - start));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, "", std::string("its flight data is not JSON: ") + e.what());
  }
}

const FileKind& flight_page_kind() {
  static const FileKind kind = FileKind::commented("flight page", "<!--", "-->");
  return kind;
}

std::size_t save_flight_page(const std::string& path, const std::string& html) {
  return write_output_file(path, html, flight_page_kind());
}

}  // namespace saltus
