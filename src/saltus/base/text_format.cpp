#include "saltus/base/text_format.h"

#include <cstdio>
#include <sstream>

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

}  // namespace saltus
