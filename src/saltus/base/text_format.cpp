#include "saltus/base/text_format.h"

#include <cstdio>
#include <sstream>

#include "saltus/base/json_reader.h"

namespace saltus {

std::string format_number(const char* pattern, double value) {
  char buffer[64];
  const int length = std::snprintf(buffer, sizeof buffer, pattern, value);
  if (length < 0) return "";
  if (static_cast<std::size_t>(length) < sizeof buffer) return buffer;
  std::string out(static_cast<std::size_t>(length) + 1, '\0');  // a pattern with long text
  std::snprintf(out.data(), out.size(), pattern, value);
  out.resize(static_cast<std::size_t>(length));
  return out;
}

std::string message_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string message_text(const std::string& text, std::size_t max_bytes) {
  std::string out = printable(text);
  if (out.size() <= max_bytes) return out;
  std::size_t cut = max_bytes;
  // Not inside a UTF-8 sequence (continuation bytes are 10xxxxxx) ...
  while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80)
    --cut;
  // ... nor inside a \xNN escape.
  for (std::size_t back = 1; back <= 3 && back <= cut; ++back)
    if (out.compare(cut - back, 2, "\\x") == 0) {
      cut -= back;
      break;
    }
  out.resize(cut);
  return out + "... (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace saltus
