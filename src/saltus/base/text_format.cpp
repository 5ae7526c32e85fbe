#include "saltus/base/text_format.h"

#include <charconv>
#include <cstdio>
#include <sstream>

namespace saltus {

namespace {

/// Length of the well-formed UTF-8 sequence starting at text[i], 0 if there is none
/// (Unicode 15, Table 3-7).
std::size_t utf8_sequence_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  unsigned char low = 0x80;
  unsigned char high = 0xBF;
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    if (b0 == 0xE0) low = 0xA0;
    if (b0 == 0xED) high = 0x9F;  // no surrogates
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    if (b0 == 0xF0) low = 0x90;
    if (b0 == 0xF4) high = 0x8F;  // nothing past U+10FFFF
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

std::string hex_byte(unsigned char c) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "\\x%02X", static_cast<unsigned>(c));
  return buffer;
}

}  // namespace

bool is_valid_utf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_sequence_length(text, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string printable(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_sequence_length(text, i);
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (n == 0 || (n == 1 && (c < 0x20 || c == 0x7F))) {
      out += hex_byte(c);
      ++i;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  return out;
}

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

std::string message_number_beside(double value, double low, double high) {
  const std::string text = message_number(value);
  if ((value != low && text == message_number(low)) ||
      (value != high && text == message_number(high)))
    return exact_number(value);
  return text;
}

std::string exact_number(double value) {
  char buffer[32];
  if (value == 0.0) value = 0.0;  // no "-0"
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

std::string xml_text(const std::string& text) {
  std::string out;
  for (char c : printable(text)) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out.push_back(c);
    }
  }
  return out;
}

std::string with_article(const std::string& noun) {
  if (noun.empty()) return noun;
  return (std::string("aeiouAEIOU").find(noun.front()) != std::string::npos ? "an " : "a ") + noun;
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
