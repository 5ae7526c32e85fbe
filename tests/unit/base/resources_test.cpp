// Finding body models (base/resources.h): a file beside the motion first, then a bundled model by
// name; $SALTUS_RESOURCE_DIR searched before everything else; nothing found gives "".

#include "saltus/base/resources.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/temp_path.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

/// A fresh folder for one test, removed afterwards.
struct Folder {
  fs::path path;
  explicit Folder(const std::string& name) : path(test::temp_path(name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Folder() { fs::remove_all(path); }
  std::string file(const std::string& name, const std::string& text = "{}") const {
    fs::create_directories((path / name).parent_path());
    std::ofstream(path / name) << text;
    return (path / name).string();
  }
};

TEST(ResolveModelPath, FindsABundledModelByName) {
  const std::string found = resolve_model_path("zatsiorsky-66kg", "/nowhere/m.motion.json");
  ASSERT_FALSE(found.empty());
  EXPECT_TRUE(fs::is_regular_file(found));
  EXPECT_EQ(fs::path(found).filename(), "zatsiorsky-66kg.json");
  EXPECT_EQ(fs::path(found).parent_path().filename(), "models");
  EXPECT_EQ(resolve_model_path("no-such-model", "/nowhere/m.motion.json"), "");
  EXPECT_EQ(resolve_model_path("", "/nowhere/m.motion.json"), "");
}

TEST(ResolveModelPath, PrefersAFileBesideTheMotion) {
  const Folder folder("saltus-resources-beside");
  const std::string motion = folder.file("m.motion.json");
  const std::string mine = folder.file("my-model.json");
  EXPECT_EQ(fs::path(resolve_model_path("my-model.json", motion)), fs::path(mine));
  const std::string nested = folder.file("models/other.json");
  EXPECT_EQ(fs::path(resolve_model_path("models/other.json", motion)), fs::path(nested));
  // A file named like a bundled model shadows it.
  const std::string shadow = folder.file("zatsiorsky-66kg");
  EXPECT_EQ(fs::path(resolve_model_path("zatsiorsky-66kg", motion)), fs::path(shadow));
  // Something that reads as a path but is not there is not looked up by name.
  EXPECT_EQ(resolve_model_path("missing.json", motion), "");
  EXPECT_EQ(resolve_model_path("sub/zatsiorsky-66kg", motion), "");
}

TEST(ResolveModelPath, SearchesTheResourceDirectoryVariableFirst) {
  const Folder folder("saltus-resources-env");
  const std::string own = folder.file("models/zatsiorsky-66kg.json");
  ASSERT_EQ(setenv("SALTUS_RESOURCE_DIR", folder.path.c_str(), 1), 0);
  const std::vector<std::string> dirs = resource_directories();
  const std::string found = resolve_model_path("zatsiorsky-66kg", "/nowhere/m.motion.json");
  unsetenv("SALTUS_RESOURCE_DIR");
  ASSERT_FALSE(dirs.empty());
  EXPECT_EQ(dirs.front(), folder.path.string());
  EXPECT_EQ(fs::path(found), fs::path(own));
  EXPECT_NE(resource_directories().front(), folder.path.string());
}

}  // namespace
}  // namespace saltus
