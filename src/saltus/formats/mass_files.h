#pragma once
/// @file
/// The mass study's files: DIR/{result.json, mass.csv, mass.md, model.json, model_scaled.json},
/// written all or nothing (OutputFolder).

#include <nlohmann/json.hpp>
#include <string>

#include "saltus/studies/mass_study.h"

namespace saltus {

/// CSV: t, then per run and load segment the joint wrench (force N then moment N·m, segment
/// frame about the joint centre) and its force and moment magnitudes.
std::string mass_study_csv(const MassStudyResult& study);

/// Markdown: per run, RMS and peak joint force and moment of each load segment, and the ratio
/// scaled/given.
std::string mass_study_markdown(const MassStudyResult& study);

/// DIR/{result.json, mass.csv, mass.md, model.json (given), model_scaled.json}.
nlohmann::json write_mass_outputs(const std::string& out_dir, const MotionFile& file,
                                  const MassStudyResult& study, const MassStudyOptions& options);

}  // namespace saltus
