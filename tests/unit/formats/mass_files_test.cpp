// The mass study's files (formats/mass_files.h): a real study's folder read back (the joint
// wrenches to the ten digits mass.csv keeps) and malformed files refused naming the file and
// column; from a study with known joint loads, the CSV reads back to the wrenches and their
// magnitudes, the Markdown's ratios are those of the loads, and the folder holds both models.

#include "saltus/formats/mass_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/trajectory_csv.h"
#include "saltus/use_cases/result_folders.h"
#include "support/cli_runner.h"
#include "support/mass_study_fixture.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

class MassFilesTest : public test::MassStudyFolderFixture {
 protected:
  static void SetUpTestSuite() {
    MassStudyOptions options;
    options.load_segments = {"thigh_r", "upper_arm_r", "foot_l"};
    write_folder(
        std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json",
        options, 23, "saltus_mass_files_test");
  }
};

/// Equal to the ten significant digits mass.csv keeps.
void expect_ten_digits(double read, double written) {
  EXPECT_NEAR(read, written, 1e-9 * std::abs(written) + 1e-300);
}

TEST_F(MassFilesTest, FolderReadsBack) {
  ASSERT_TRUE(is_mass_study_folder(folder_.string()));
  EXPECT_FALSE(is_mass_study_folder("/nonexistent/folder"));
  EXPECT_FALSE(is_mass_study_folder(SALTUS_EXAMPLES_DIR));
  const MassStudyFolder f = read_mass_study_folder(folder_.string() + "/");
  EXPECT_EQ(f.name, "saltus_mass_files_test");
  EXPECT_EQ(f.motion, file_->motion.name);
  EXPECT_EQ(f.motion_file, file_->path);
  EXPECT_EQ(f.factor, options_->factor);
  EXPECT_EQ(f.scaled_segments, options_->scaled_segments);
  EXPECT_EQ(f.load_segments, options_->load_segments);
  for (std::size_t r = 0; r < 2; ++r) {
    const MassStudyRun& run = study_->runs[r];
    EXPECT_EQ(f.runs[r].label, run.label);
    EXPECT_EQ(f.runs[r].model, run.model.name);
    EXPECT_EQ(f.runs[r].status, "not run");
    EXPECT_EQ(f.runs[r].iterations, run.result.solve.iterations);
    EXPECT_EQ(f.runs[r].avg_force_after_N, run.result.after.metrics.avg_root_force);
  }
  const MassCsv& csv = f.loads;
  ASSERT_EQ(csv.time.size(), 23u);
  ASSERT_EQ(csv.load_segments, options_->load_segments);
  ASSERT_EQ(csv.loads.size(), 3u);
  for (std::size_t s = 0; s < csv.loads.size(); ++s) {
    for (std::size_t r = 0; r < 2; ++r) {
      const MassStudyRun& run = study_->runs[r];
      const int index = run.model.segment_index(csv.load_segments[s]);
      const MassLoads& loads = csv.loads[s][r];
      ASSERT_EQ(loads.wrench.size(), 23u);
      for (std::size_t k = 0; k < 23; ++k) {
        expect_ten_digits(csv.time[k], run.result.after.samples[k].time);
        const Vector6d& w = run.result.after.samples[k].joint_wrench.at(index);
        for (int i = 0; i < 6; ++i)
          expect_ten_digits(loads.wrench[k][i], w[i]);
        expect_ten_digits(loads.force_N[k], w.head<3>().norm());
        expect_ten_digits(loads.moment_Nm[k], w.tail<3>().norm());
      }
    }
  }
  // Heavier thighs need a larger force at the hip: the runs differ there.
  double diff = 0;
  for (std::size_t k = 0; k < 23; ++k)
    diff = std::max(diff, std::abs(csv.loads[0][1].force_N[k] - csv.loads[0][0].force_N[k]));
  EXPECT_GT(diff, 1.0);
}

TEST(MassCsv, MissingOrMisnamedColumnsAreNamed) {
  CsvTable table;
  table.columns = {"t"};
  for (const char* run : {"given", "scaled"})
    for (const char* q : {"fx", "fy", "fz", "mx", "my", "mz", "force_N", "moment_Nm"})
      table.columns.push_back(std::string(run) + ".thigh_r." + q);
  table.rows = {std::vector<double>(17, 1.0), std::vector<double>(17, 2.0)};
  const MassCsv ok = parse_mass_csv(table, "mass.csv");
  EXPECT_EQ(ok.load_segments, std::vector<std::string>{"thigh_r"});
  EXPECT_EQ(ok.loads[0][1].moment_Nm, (std::vector<double>{1.0, 2.0}));

  CsvTable renamed = table;
  renamed.columns[16] = "scaled.thigh_r.moment";
  try {
    parse_mass_csv(renamed, "mass.csv");
    ADD_FAILURE() << "a missing column was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mass.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("scaled.thigh_r.moment_Nm"), std::string::npos)
        << e.what();
  }
  CsvTable short_table = table;
  short_table.columns.pop_back();
  for (auto& row : short_table.rows)
    row.pop_back();
  EXPECT_THROW(parse_mass_csv(short_table, "mass.csv"), InputError);
  CsvTable no_time = table;
  no_time.columns[0] = "time";
  EXPECT_THROW(parse_mass_csv(no_time, "mass.csv"), InputError);
}

TEST(MassStudyFolder, RejectsOtherFolders) {
  EXPECT_THROW(read_mass_study_folder("/nonexistent/folder"), InputError);
  EXPECT_THROW(read_mass_study_folder(SALTUS_EXAMPLES_DIR), InputError);
}

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
