#pragma once
/// What a reader says when it refuses an input, for the tests of its messages.

#include <optional>
#include <string>

#include "saltus/base/input_error.h"

namespace saltus::test {

/// The InputError `f` throws, if it throws one.
template <typename F>
std::optional<InputError> thrown_input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

/// The message of the InputError `f` throws ("" if it throws none).
template <typename F>
std::string input_error(F f) {
  const std::optional<InputError> e = thrown_input_error(f);
  return e ? e->what() : "";
}

}  // namespace saltus::test
