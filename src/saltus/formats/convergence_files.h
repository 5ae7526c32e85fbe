#pragma once
/// @file
/// The convergence study's files: DIR/{result.json, convergence.csv, convergence.md}, written all
/// or nothing (OutputFolder), and the Markdown summary the CLI prints.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/studies/convergence_study.h"

namespace saltus {

/// The study as Markdown: success rate, iterations, time and residual per formulation; success
/// rate per formulation against motion, mass error and timing error.
std::string convergence_markdown(const std::vector<StudyOutcome>& outcomes);

/// CSV, one row per case (header first).
std::string convergence_csv(const std::vector<StudyOutcome>& outcomes);

/// DIR/{result.json, convergence.csv, convergence.md}. Returns result.json.
nlohmann::json write_convergence_outputs(const std::string& out_dir,
                                         const std::vector<StudyOutcome>& outcomes,
                                         const ConvergenceStudyOptions& options);

}  // namespace saltus
