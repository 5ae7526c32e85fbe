#include "saltus/base/text_format.h"

#include <cstdio>
#include <sstream>

namespace saltus {

std::string format_number(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string message_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace saltus
