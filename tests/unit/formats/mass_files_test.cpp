// The mass study's files (formats/mass_files.h) from a study with known joint loads: the CSV reads
// back to the wrenches and their magnitudes, the Markdown's ratios are those of the loads, and the
// folder holds both models, the scaled one reloading to what was run.

#include "saltus/formats/mass_files.h"

#include <gtest/gtest.h>

#include <random>

#include "saltus/formats/model_file.h"
#include "saltus/formats/trajectory_csv.h"
#include "support/cli_runner.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// Two runs over 11 samples; every joint wrench is seeded-random in the given run and exactly
/// twice that in the scaled one.
MassStudyResult study_with_known_loads() {
  MassStudyResult study;
  study.load_segments = {"thigh_r", "upper_arm_r"};
  const BodyModel model = test::bundled_model();
  study.runs.push_back({"given", model, {}});
  study.runs.push_back({"scaled", scale_segment_mass(model, "thigh_r", 2.0), {}});
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-100.0, 100.0);
  for (int k = 0; k <= 10; ++k) {
    SampleRecord s;
    s.time = 0.2 * k;
    for (int seg = 0; seg < model.size(); ++seg) {
      Vector6d w;
      for (int i = 0; i < 6; ++i)
        w[i] = u(rng);
      s.joint_wrench.push_back(w);
    }
    study.runs[0].result.after.samples.push_back(s);
    for (Vector6d& w : s.joint_wrench)
      w *= 2.0;
    study.runs[1].result.after.samples.push_back(s);
  }
  return study;
}

TEST(MassFiles, CsvReadsBackToTheJointLoadsAndTheirMagnitudes) {
  const MassStudyResult study = study_with_known_loads();
  test::TempDir dir;
  test::write_text(dir / "mass.csv", mass_study_csv(study));
  const CsvTable table = read_csv_table(dir / "mass.csv");
  ASSERT_EQ(table.columns.size(), 1u + 2u * 2u * 8u);
  ASSERT_EQ(table.rows.size(), 11u);
  const char* runs[] = {"given", "scaled"};
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    EXPECT_NEAR(table.rows[k][0], 0.2 * k, 1e-12);
    for (int r = 0; r < 2; ++r) {
      for (const std::string& segment : study.load_segments) {
        const Vector6d& w = study.runs[r].result.after.samples[k].joint_wrench.at(
            study.runs[r].model.segment_index(segment));
        const std::string prefix = std::string(runs[r]) + "." + segment + ".";
        const char* parts[] = {"fx", "fy", "fz", "mx", "my", "mz"};
        for (int i = 0; i < 6; ++i) {
          const int c = table.column(prefix + parts[i]);
          ASSERT_GE(c, 0) << prefix + parts[i];
          EXPECT_NEAR(table.rows[k][c], w[i], 1e-9 * std::abs(w[i]));
        }
        EXPECT_NEAR(table.rows[k][table.column(prefix + "force_N")], w.head<3>().norm(), 1e-7);
        EXPECT_NEAR(table.rows[k][table.column(prefix + "moment_Nm")], w.tail<3>().norm(), 1e-7);
      }
    }
  }
}

TEST(MassFiles, MarkdownRatiosAreThoseOfTheLoads) {
  const std::string md = mass_study_markdown(study_with_known_loads());
  EXPECT_NE(md.find("| thigh_r | 2.00 | 2.00 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| upper_arm_r | 2.00 | 2.00 |"), std::string::npos) << md;
}

TEST(MassFiles, FolderHoldsBothModelsAndTheRuns) {
  const MassStudyResult study = study_with_known_loads();
  MotionFile file;
  file.model = study.runs[0].model;
  file.motion = test::tuck_motion(file.model);
  MassStudyOptions options;
  options.scaled_segments = {"thigh_r"};
  options.factor = 2.0;
  test::TempDir dir;
  const nlohmann::json result = write_mass_outputs(dir / "mass", file, study, options);
  EXPECT_EQ(result["study"], "mass");
  EXPECT_EQ(result["runs"].size(), 2u);
  const BodyModel scaled = load_body_model(dir / "mass/model_scaled.json");
  EXPECT_EQ(scaled.segments[scaled.segment_index("thigh_r")].mass,
            study.runs[1].model.segments[scaled.segment_index("thigh_r")].mass);
  EXPECT_EQ(load_body_model(dir / "mass/model.json").total_mass(), file.model.total_mass());
  EXPECT_EQ(nlohmann::json::parse(test::read_text(dir / "mass/result.json")), result);
  EXPECT_EQ(test::read_text(dir / "mass/mass.csv"), mass_study_csv(study));
}

}  // namespace
}  // namespace saltus
