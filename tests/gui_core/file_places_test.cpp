// Where save dialogs start (core/file_places.h): never in the bundled examples or resources,
// nor in a folder that cannot be written; the folder last saved into first.

#include "core/file_places.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "saltus/base/resources.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

namespace fs = std::filesystem;

/// The source tree's resources/ (the one resource folder a build-tree run always has).
fs::path source_resources() {
  for (const std::string& dir : resource_directories())
    if (fs::exists(fs::path(dir) / "models")) return dir;
  return {};
}

TEST(FilePlaces, TheBundledExamplesAndResourcesAreBundledAndAnotherFolderIsNot) {
  const fs::path resources = source_resources();
  ASSERT_FALSE(resources.empty());
  const fs::path examples = resources.parent_path() / "examples";
  ASSERT_TRUE(fs::exists(examples / "motions"));
  EXPECT_TRUE(bundled_with_saltus((examples / "motions").string()));
  EXPECT_TRUE(bundled_with_saltus(examples.string()));
  EXPECT_TRUE(bundled_with_saltus((resources / "models").string()));
  // The same folder written another way.
  EXPECT_TRUE(bundled_with_saltus((examples / "motions" / ".." / "captures").string()));
  // Beside them, or above them, is not bundled.
  EXPECT_FALSE(bundled_with_saltus(resources.parent_path().string()));
  EXPECT_FALSE(bundled_with_saltus((resources.parent_path() / "examples-mine").string()));
  const saltus::test::TempDir dir;
  EXPECT_FALSE(bundled_with_saltus(dir.path().string()));
  EXPECT_FALSE(bundled_with_saltus(""));
}

TEST(FilePlaces, ASaveDialogStartsWhereTheLastSaveWentElseWhereTheFileCameFromIfItMay) {
  const fs::path examples = source_resources().parent_path() / "examples" / "motions";
  std::set<std::string> writable = {"/home/coach/out", "/home/coach/motions", examples.string()};
  const auto can_write = [&](const std::string& path) { return writable.count(path) > 0; };
  const std::string fallback = "/home/coach/saltus";
  EXPECT_EQ(save_folder("/home/coach/out", examples.string(), fallback, can_write),
            "/home/coach/out");
  // Nothing saved yet: the folder opened from, unless it is the bundled examples.
  EXPECT_EQ(save_folder("", "/home/coach/motions", fallback, can_write), "/home/coach/motions");
  EXPECT_EQ(save_folder("", examples.string(), fallback, can_write), fallback);
  // A folder gone or read-only is passed over.
  writable.erase("/home/coach/out");
  EXPECT_EQ(save_folder("/home/coach/out", "/home/coach/motions", fallback, can_write),
            "/home/coach/motions");
  writable.erase("/home/coach/motions");
  EXPECT_EQ(save_folder("/home/coach/out", "/home/coach/motions", fallback, can_write), fallback);
}

}  // namespace
}  // namespace saltus::gui
