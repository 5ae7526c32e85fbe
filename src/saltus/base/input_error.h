#pragma once
/// @file
/// The one exception type for bad input. Front ends catch it, print what() and exit with
/// status 2; nothing else in the library throws for user mistakes.

#include <stdexcept>
#include <string>

#include "saltus/base/text_format.h"

namespace saltus {

/// Bad input from a file the user gave: syntax, types, values out of range.
/// what() reads "<file>: <json path>: <problem>", e.g.
/// "m1.motion.json: /keyframes/2/rotations/knee_l: quaternion norm 1.4 is not 1", always one
/// printable line: a file name, key or token from the user with a newline, an ESC or bytes
/// that are not UTF-8 is quoted with them as \xNN (printable()), so that it can neither split
/// the message nor reach the terminal. file(), json_path() and problem() are as given.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& json_path, const std::string& problem)
      : std::runtime_error(compose(file, json_path, problem)),
        file_(file),
        json_path_(json_path),
        problem_(problem) {}

  const std::string& file() const { return file_; }
  const std::string& json_path() const { return json_path_; }
  const std::string& problem() const { return problem_; }

 private:
  static std::string compose(const std::string& file, const std::string& json_path,
                             const std::string& problem) {
    std::string out = file;
    if (!json_path.empty()) out += ": " + json_path;
    return printable(out + ": " + problem);
  }
  std::string file_;
  std::string json_path_;
  std::string problem_;
};

}  // namespace saltus
