#pragma once
// Runs the `saltus` executable from tests and captures its exit status and output.

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <string>

#include "saltus/evaluation/joint_loads.h"

namespace saltus::test {

struct CliRun {
  int status = -1;
  std::string output;  ///< stdout and stderr together
};

/// Runs a shell command line, capturing stdout and stderr together.
inline CliRun run_command(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  CliRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe))
    run.output += buffer.data();
  const int raw = pclose(pipe);
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return run;
}

/// Runs `saltus ARGUMENTS`.
inline CliRun run_cli(const std::string& arguments) {
  return run_command(std::string(SALTUS_CLI_PATH) + " " + arguments);
}

/// A fresh empty folder under the system temp dir, removed when the object dies.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("saltus-test-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

/// The whole file as a string ("" if it cannot be read).
inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

/// A JSON file parsed (throws if it cannot be read or parsed).
inline nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

/// The largest rise of a joint's peak moment or force over its peak before, read from an
/// `optimize` result.json's joint_loads, each peak at least its floor (evaluation/joint_loads.h's
/// rule): issue 24's bar is 1.5.
inline double largest_joint_rise(const nlohmann::json& result) {
  double worst = 0.0;
  for (const auto& [joint, loads] : result["joint_loads"].items()) {
    const double floors[2] = {kJointForceFloorN, kJointMomentFloorNm};
    const char* keys[2] = {"peak_force_N", "peak_moment_Nm"};
    for (int k = 0; k < 2; ++k)
      worst = std::max(worst, std::max(loads["after"][keys[k]].get<double>(), floors[k]) /
                                  std::max(loads["before"][keys[k]].get<double>(), floors[k]));
  }
  return worst;
}

/// The names of the entries of `folder`, hidden ones included.
inline std::set<std::string> names_in(const std::filesystem::path& folder) {
  std::set<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    found.insert(entry.path().filename().string());
  return found;
}

inline std::string m1_path() {
  return std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json";
}

}  // namespace saltus::test
