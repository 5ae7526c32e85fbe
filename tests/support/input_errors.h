#pragma once
/// What a reader says when it refuses an input, for the tests of its messages.

#include <string>

#include "saltus/base/input_error.h"

namespace saltus::test {

/// The message of the InputError `f` throws ("" if it throws none).
template <typename F>
std::string input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace saltus::test
