#pragma once
// A mass study without the optimisations (too slow for a unit test): each run's "after" is the
// interpolated motion evaluated with that run's model, which is all the mass study's writers
// read; and a test fixture holding one written to a folder for a whole test suite.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/motion_file.h"
#include "saltus/studies/mass_study.h"
#include "saltus/use_cases/result_folders.h"
#include "support/temp_path.h"

namespace saltus::test {

/// Runs labelled "table2" (the file's model) and "thighs x1.5" (options' segments scaled),
/// evaluated on `samples` times; run r reports 5 + 2r iterations.
inline MassStudyResult evaluated_mass_study(const MotionFile& file, const MassStudyOptions& options,
                                            int samples) {
  MassStudyResult study;
  study.load_segments = options.load_segments;
  EvaluateOptions evaluate;
  evaluate.samples = samples;
  BodyModel scaled = file.model;
  for (const std::string& s : options.scaled_segments)
    scaled = scale_segment_mass(scaled, s, options.factor);
  for (const BodyModel* model : {&file.model, static_cast<const BodyModel*>(&scaled)}) {
    MassStudyRun run;
    run.label = model == &scaled ? "thighs x1.5" : "table2";
    run.model = *model;
    run.result.before = run.result.after = evaluate_motion(file.motion, *model, evaluate);
    run.result.solve.status = "not run";
    run.result.solve.iterations = model == &scaled ? 7 : 5;
    study.runs.push_back(std::move(run));
  }
  return study;
}

/// The evaluated mass study of a motion, written by write_mass_outputs into a folder private to
/// the test process (temp_path) once per test suite (SetUpTestSuite calls write_folder).
class MassStudyFolderFixture : public ::testing::Test {
 protected:
  static void write_folder(const std::string& motion_path, const MassStudyOptions& options,
                           int samples, const std::string& folder_name) {
    file_ = std::make_unique<MotionFile>(load_motion_file(motion_path));
    options_ = std::make_unique<MassStudyOptions>(options);
    study_ = std::make_unique<MassStudyResult>(evaluated_mass_study(*file_, options, samples));
    folder_ = temp_path(folder_name);
    std::filesystem::remove_all(folder_);
    write_mass_outputs(folder_.string(), *file_, *study_, *options_);
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(folder_);
    study_.reset();
    options_.reset();
    file_.reset();
  }
  inline static std::unique_ptr<MotionFile> file_;
  inline static std::unique_ptr<MassStudyOptions> options_;
  inline static std::unique_ptr<MassStudyResult> study_;
  inline static std::filesystem::path folder_;
};

}  // namespace saltus::test
