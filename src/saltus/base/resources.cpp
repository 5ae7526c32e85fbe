#include "saltus/base/resources.h"

#include <cstdlib>
#include <filesystem>

namespace saltus {

namespace fs = std::filesystem;

std::vector<std::string> resource_directories() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("SALTUS_RESOURCE_DIR"); env && *env) dirs.emplace_back(env);
  // Installed anywhere (cmake --install --prefix P): P/bin/saltus finds P/share/saltus. In the
  // build tree that folder does not exist and the source tree's resources are used.
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back((exe.parent_path().parent_path() / "share" / "saltus").string());
  dirs.emplace_back(SALTUS_SOURCE_RESOURCE_DIR);
  dirs.emplace_back(SALTUS_INSTALL_RESOURCE_DIR);
  return dirs;
}

std::string resolve_model_path(const std::string& model_field, const std::string& motion_file) {
  if (model_field.empty()) return "";
  const fs::path base = fs::path(motion_file).parent_path();
  const fs::path relative = base / model_field;
  const bool looks_like_path =
      model_field.find('/') != std::string::npos || fs::path(model_field).extension() == ".json";
  // error_code forms: a name too long for the file system is "not found", not an exception.
  std::error_code ec;
  if (looks_like_path || fs::exists(relative, ec)) {
    // Whatever is there (a folder, a pipe): the reader says what it is, not "not found".
    return fs::exists(relative, ec) ? relative.string() : "";
  }
  for (const auto& dir : resource_directories()) {
    const fs::path candidate = fs::path(dir) / "models" / (model_field + ".json");
    if (fs::exists(candidate, ec)) return candidate.string();
  }
  return "";
}

}  // namespace saltus
