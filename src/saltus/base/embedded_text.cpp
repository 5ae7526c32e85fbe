#include "saltus/base/embedded_text.h"

namespace saltus {

std::string embedded_text(const char* const chunks[]) {
  std::string out;
  for (int i = 0; chunks[i] != nullptr; ++i)
    out += chunks[i];
  return out;
}

}  // namespace saltus
