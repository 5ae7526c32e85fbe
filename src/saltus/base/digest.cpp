#include "saltus/base/digest.h"

#include <cstdint>
#include <cstdio>

namespace saltus {

std::string text_digest(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a offset basis and prime, 64 bits
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

}  // namespace saltus
