#include "saltus/formats/output_folder.h"

#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

#include "saltus/base/input_error.h"

namespace saltus {

namespace fs = std::filesystem;

namespace {
std::string random_suffix() {
  std::random_device rd;
  return std::to_string(rd() % 1000000000u);
}
}  // namespace

OutputFolder::OutputFolder(std::string final_path) : final_path_(std::move(final_path)) {
  if (final_path_.empty()) throw InputError("--out", "", "output folder path is empty");
  fs::path target = fs::absolute(final_path_).lexically_normal();
  if (target.filename().empty()) target = target.parent_path();
  if (fs::exists(target)) {
    if (!fs::is_directory(target)) throw InputError(final_path_, "", "exists and is not a folder");
    if (!fs::is_empty(target) && !fs::exists(target / "result.json"))
      throw InputError(final_path_, "",
                       "folder exists and holds no Saltus result (no result.json); not "
                       "overwriting it");
  }
  const fs::path parent = target.parent_path();
  if (!parent.empty() && !fs::exists(parent)) fs::create_directories(parent);
  final_path_ = target.string();
  temporary_path_ =
      (parent / ("." + target.filename().string() + ".tmp-" + random_suffix())).string();
  fs::create_directory(temporary_path_);
}

OutputFolder::~OutputFolder() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(temporary_path_, ec);
  }
}

std::string OutputFolder::file(const std::string& name) const {
  return (fs::path(temporary_path_) / name).string();
}

void OutputFolder::commit() {
  const fs::path target(final_path_);
  fs::path old;
  if (fs::exists(target)) {
    old = target.parent_path() / ("." + target.filename().string() + ".old-" + random_suffix());
    fs::rename(target, old);
  }
  fs::rename(temporary_path_, target);
  committed_ = true;
  if (!old.empty()) {
    std::error_code ec;
    fs::remove_all(old, ec);
  }
}

}  // namespace saltus

namespace saltus {

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  out << text;
  out.flush();
  if (!out) throw std::runtime_error(path + ": writing failed");
}

}  // namespace saltus
