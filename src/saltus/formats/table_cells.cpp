#include "saltus/formats/table_cells.h"

#include "saltus/base/text_format.h"

namespace saltus {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string markdown_cell(const std::string& text) {
  std::string out;
  for (const char c : printable(text)) {
    if (c == '\\' || c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace saltus
