#pragma once
// The study verbs of `saltus`: `study convergence`, `study mass`, `study merge` and `paper`.
// Argument parsing and printing only; the studies, their folders and the per-case processes are
// the library's (use_cases/study_runner.h).

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>

namespace saltus::cli {

class StudyVerbs {
 public:
  /// Registers the verbs on `app`. argv is kept for --emit-slurm, which repeats the command.
  StudyVerbs(CLI::App& app, int argc, char** argv);
  ~StudyVerbs();
  StudyVerbs(const StudyVerbs&) = delete;
  StudyVerbs& operator=(const StudyVerbs&) = delete;

  /// Runs the study verb that was parsed and returns its exit status; nullopt if none was.
  /// Library errors propagate (main turns them into exit statuses).
  std::optional<int> run() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace saltus::cli
