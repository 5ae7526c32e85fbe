#include "core/file_places.h"

#include <filesystem>

#include "saltus/base/resources.h"

namespace saltus::gui {

namespace {

namespace fs = std::filesystem;

/// `path` made absolute and normal, symbolic links resolved where they exist.
fs::path normal_folder(const std::string& path) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return (ec ? fs::absolute(path) : canonical).lexically_normal();
}

bool within(const fs::path& folder, const fs::path& root) {
  const fs::path relative = folder.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

}  // namespace

bool bundled_with_saltus(const std::string& folder) {
  if (folder.empty()) return false;
  const fs::path where = normal_folder(folder);
  for (const std::string& dir : resource_directories()) {
    const fs::path resources = normal_folder(dir);
    if (within(where, resources) || within(where, resources.parent_path() / "examples"))
      return true;
  }
  return false;
}

std::string save_folder(const std::string& last_saved, const std::string& last_opened,
                        const std::string& fallback,
                        const std::function<bool(const std::string&)>& writable) {
  if (!last_saved.empty() && writable(last_saved)) return last_saved;
  if (!last_opened.empty() && writable(last_opened) && !bundled_with_saltus(last_opened))
    return last_opened;
  return fallback;
}

}  // namespace saltus::gui
