// InputError (base/input_error.h): the message every front end prints for bad input reads
// "<file>: <json path>: <problem>" (docs/formats.md), and the parts stay available on their own.

#include "saltus/base/input_error.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace saltus {
namespace {

TEST(InputError, NamesFilePathAndProblemInOneLine) {
  const InputError e("m1.motion.json", "/keyframes/2/rotations/knee_l",
                     "quaternion norm 1.4 is not 1");
  EXPECT_STREQ(e.what(),
               "m1.motion.json: /keyframes/2/rotations/knee_l: quaternion norm 1.4 is not 1");
  EXPECT_EQ(e.file(), "m1.motion.json");
  EXPECT_EQ(e.json_path(), "/keyframes/2/rotations/knee_l");
  EXPECT_EQ(e.problem(), "quaternion norm 1.4 is not 1");
}

TEST(InputError, LeavesOutAnEmptyPathAndIsARuntimeError) {
  try {
    throw InputError("model.json", "", "cannot open file for reading");
  } catch (const std::runtime_error& e) {  // what the front ends catch besides InputError
    EXPECT_STREQ(e.what(), "model.json: cannot open file for reading");
  }
}

TEST(InputError, QuotesUserTextOnOnePrintableLine) {
  // A file name with a newline and an ESC, a key that is not UTF-8: one line, nothing raw.
  const InputError e("evil\n\x1b[31mname.json", "/joints/l\xFF", "unknown joint \"a\tb\"");
  EXPECT_STREQ(e.what(), "evil\\x0A\\x1B[31mname.json: /joints/l\\xFF: unknown joint \"a\\x09b\"");
  EXPECT_EQ(e.file(), "evil\n\x1b[31mname.json") << "the parts stay as given";
}

}  // namespace
}  // namespace saltus
