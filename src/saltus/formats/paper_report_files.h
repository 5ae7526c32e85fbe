#pragma once
/// @file
/// `saltus paper`: the reproduction report's folder. Loads the motions, runs them
/// (studies/paper_report.h) and writes DIR/report.md with everything side by side with the
/// paper: Table 1, the optimised M1-M7 (DIR/M1 ... DIR/M7, `saltus optimize` folders), the dive
/// (DIR/dive), the mass study (DIR/mass) and the convergence study (DIR/convergence), all or
/// nothing (OutputFolder). Figures are referenced from DIR/figures, which the desktop app's
/// --export-figures fills.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/studies/paper_report.h"

namespace saltus {

/// The motions of a paper folder: M1-…M7-….motion.json (Table 1's skills, in label order) and
/// dive-….motion.json. Throws InputError when the folder does not exist or holds no skill.
struct PaperMotions {
  std::vector<LabelledMotion> skills, dives;
};
PaperMotions load_paper_motions(const std::string& motions_dir);

/// Runs the paper's experiments on options.motions_dir and writes the report folder.
/// Returns its result.json.
nlohmann::json write_paper_report(const std::string& out_dir, const PaperReportOptions& options);

}  // namespace saltus
