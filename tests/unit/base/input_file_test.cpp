// Reading a file the user named (base/input_file.h): a regular file's text whole; a pipe, a
// device, a folder, a file over the limit or a name that is not UTF-8 refused with one line
// naming the file, at once (a pipe with no writer is not waited on).

#include "saltus/base/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "support/cli_runner.h"
#include "support/input_errors.h"

namespace saltus {
namespace {

TEST(InputFile, ReadsARegularFileWhole) {
  const test::TempDir dir;
  std::string text(200000, 'a');
  text += "\n\r\t\x01 end";
  test::write_text(dir / "take.bvh", text);
  EXPECT_EQ(read_input_file(dir / "take.bvh", 1u << 20, "BVH captures"), text);
  // Exactly at the limit is read; one byte over is not.
  EXPECT_EQ(read_input_file(dir / "take.bvh", text.size(), "BVH captures").size(), text.size());
  EXPECT_EQ(test::input_error([&] {
              read_input_file(dir / "take.bvh", text.size() - 1, "x");
            }).find(dir / "take.bvh: the file is 0.19"),
            0u);
}

TEST(InputFile, RefusesWhatIsNotARegularFileAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  const test::TempDir dir;
  const std::string fifo = dir / "x.bvh";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(test::input_error([&] { read_input_file(fifo, 1000, "BVH captures"); }),
            fifo +
                ": is not a regular file (a device, pipe or socket); Saltus reads BVH "
                "captures only");
  std::filesystem::create_symlink("/dev/zero", dir / "zero.bvh");
  EXPECT_EQ(test::input_error([&] { read_input_file(dir / "zero.bvh", 1000, "BVH captures"); }),
            dir /
                "zero.bvh: is not a regular file (a device, pipe or socket); Saltus reads BVH "
                "captures only");
  EXPECT_EQ(test::input_error([&] { read_input_file(dir.path().string(), 1000, "x"); }),
            dir.path().string() + ": is a folder, not a file");
  const std::string big = dir / "big.bvh";
  test::write_text(big, "HIERARCHY");
  std::filesystem::resize_file(big, 65u << 20);  // sparse
  EXPECT_EQ(test::input_error([&] { read_input_file(big, 64u << 20, "x"); }),
            big + ": the file is 65 MiB; Saltus reads files of at most 64 MiB");
  EXPECT_NE(test::input_error([&] {
              read_input_file(dir / "missing.bvh", 1000, "x");
            }).find("missing.bvh: cannot open file for reading: No such file"),
            std::string::npos);
  const std::string latin1 = dir / "caf\xE9.bvh";
  test::write_text(latin1, "x");
  EXPECT_NE(test::input_error([&] {
              read_input_file(latin1, 1000, "x");
            }).find("caf\\xE9.bvh: the file name is not valid UTF-8"),
            std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5);
}

}  // namespace
}  // namespace saltus
