// All-or-nothing output folders (formats/output_folder.h): nothing appears until commit, nothing
// is left when there is no commit, an earlier Saltus result is replaced whole, and a folder or
// file that Saltus did not write is never touched.

#include "saltus/formats/output_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include "saltus/base/input_error.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

std::set<std::string> names_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder))
    names.insert(entry.path().filename().string());
  return names;
}

TEST(OutputFolder, PublishesEveryFileAtOnceOnCommit) {
  test::TempDir dir;
  const fs::path target = dir.path() / "new" / "out";  // the parent does not exist yet either
  OutputFolder folder(target.string());
  write_text(folder.file("result.json"), "{}\n");
  write_text(folder.file("trajectory.csv"), "t\n0\n");
  EXPECT_FALSE(fs::exists(target));
  folder.commit();
  EXPECT_EQ(names_in(target), (std::set<std::string>{"result.json", "trajectory.csv"}));
  EXPECT_EQ(test::read_text((target / "trajectory.csv").string()), "t\n0\n");
  EXPECT_EQ(names_in(target.parent_path()), (std::set<std::string>{"out"}));  // no leftovers
  EXPECT_EQ(fs::path(folder.final_path()), fs::absolute(target));
}

TEST(OutputFolder, LeavesNothingWithoutACommit) {
  test::TempDir dir;
  {
    OutputFolder folder(dir / "out");
    write_text(folder.file("result.json"), "{}\n");
  }
  EXPECT_TRUE(names_in(dir.path()).empty());
}

TEST(OutputFolder, ReplacesAnEarlierResultWhole) {
  test::TempDir dir;
  fs::create_directories(dir.path() / "out");
  test::write_text(dir / "out/result.json", "{\"old\": true}\n");
  test::write_text(dir / "out/stale.csv", "old\n");
  OutputFolder folder(dir / "out");
  write_text(folder.file("result.json"), "{\"new\": true}\n");
  folder.commit();
  EXPECT_EQ(names_in(dir.path() / "out"), (std::set<std::string>{"result.json"}));
  EXPECT_EQ(test::read_text(dir / "out/result.json"), "{\"new\": true}\n");
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"out"}));
  // An empty folder is taken too.
  fs::create_directories(dir.path() / "empty");
  OutputFolder empty(dir / "empty");
  empty.commit();
  EXPECT_TRUE(fs::is_directory(dir.path() / "empty"));
}

TEST(OutputFolder, NeverTouchesWhatSaltusDidNotWrite) {
  test::TempDir dir;
  fs::create_directories(dir.path() / "thesis");
  test::write_text(dir / "thesis/chapter1.tex", "precious");
  EXPECT_THROW(OutputFolder(dir / "thesis"), InputError);
  EXPECT_EQ(names_in(dir.path() / "thesis"), (std::set<std::string>{"chapter1.tex"}));
  test::write_text(dir / "notes.txt", "precious");
  EXPECT_THROW(OutputFolder(dir / "notes.txt"), InputError);
  EXPECT_EQ(test::read_text(dir / "notes.txt"), "precious");
  EXPECT_THROW(OutputFolder(""), InputError);
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"thesis", "notes.txt"}));
}

TEST(WriteText, WritesTheBytesOrNamesTheFile) {
  test::TempDir dir;
  write_text(dir / "a.txt", std::string("line\n\0tail", 10));
  EXPECT_EQ(fs::file_size(dir.path() / "a.txt"), 10u);
  try {
    write_text(dir / "missing/a.txt", "x");
    FAIL() << "wrote into a folder that does not exist";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir / "missing/a.txt"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace saltus
