#pragma once
// A temporary path private to this test process. CTest runs every test as its own process and
// several at once (-j), so a fixed name under /tmp would let two tests write, read and delete
// the same folder.

#include <unistd.h>

#include <filesystem>
#include <string>

namespace saltus::test {

/// <temp>/saltus-tests-<pid>/<name>. The parent folder is created on first use and removed,
/// with whatever the test left in it, when the process ends.
inline std::filesystem::path temp_path(const std::string& name) {
  struct ProcessFolder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("saltus-tests-" + std::to_string(::getpid()));
    ProcessFolder() { std::filesystem::create_directories(path); }
    ~ProcessFolder() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const ProcessFolder folder;
  return folder.path / name;
}

}  // namespace saltus::test
