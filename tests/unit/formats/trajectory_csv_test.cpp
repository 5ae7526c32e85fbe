// The trajectory CSV (formats/trajectory_csv.h, DESIGN §6): its columns, an exact round trip of
// every number (the file is a record that independent checks differentiate), and reading errors
// that name the file and the line.

#include "saltus/formats/trajectory_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/motion/interpolate.h"
#include "support/temp_path.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = test::temp_path(name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(TrajectoryCsv, HeaderHasTimePosesCentreOfMassRootWrenchAndResidual) {
  const BodyModel model = test::bundled_model();
  const std::vector<std::string> h = trajectory_csv_header(model);
  ASSERT_EQ(h.size(), 1u + 7u * model.size() + 15u);
  EXPECT_EQ(h[0], "t");
  EXPECT_EQ(h[1], model.segments[0].name + ".x");
  EXPECT_EQ(h[7], model.segments[0].name + ".qz");
  EXPECT_EQ(h[8], model.segments[1].name + ".x");
  EXPECT_EQ(h[1 + 7 * model.size()], "com_x");
  EXPECT_EQ(h[h.size() - 7], "root_mz");
  EXPECT_EQ(h.back(), "res_mz");
}

TEST(TrajectoryCsv, EveryNumberReadsBackExactly) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> t = interpolate_keyframes(test::twist_motion(model), model);
  std::vector<SampleRecord> samples = evaluate_trajectory(model, t, {0.0, 1.0 / 3.0, 1.7, 2.04});
  // Awkward values: tiny, huge, negative zero, a sum with no short decimal form.
  samples[1].com = Eigen::Vector3d(1e-300, -0.0, 0.1 + 0.2);
  samples[2].residual[4] = 123456789.123456789;
  samples[2].segment_rotation[3].coeffs() *= -1.0;  // written with w >= 0
  std::ostringstream text;
  write_trajectory_csv(text, model, samples);
  const std::string path = temp_file("trajectory-roundtrip.csv", text.str());
  const CsvTable table = read_csv_table(path);
  std::filesystem::remove(path);
  EXPECT_EQ(table.columns, trajectory_csv_header(model));
  ASSERT_EQ(table.rows.size(), samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const std::vector<double>& row = table.rows[k];
    const SampleRecord& s = samples[k];
    EXPECT_EQ(row[0], s.time);
    for (int seg = 0; seg < model.size(); ++seg) {
      Eigen::Quaterniond q = s.segment_rotation[seg];
      if (q.w() < 0) q.coeffs() *= -1.0;
      const int c = table.column(model.segments[seg].name + ".x");
      for (int i = 0; i < 3; ++i)
        EXPECT_EQ(row[c + i], s.segment_position[seg][i]);
      EXPECT_EQ(row[c + 3], q.w());
      EXPECT_EQ(row[c + 4], q.x());
      EXPECT_EQ(row[c + 5], q.y());
      EXPECT_EQ(row[c + 6], q.z());
    }
    const int com = table.column("com_x"), root = table.column("root_fx"),
              res = table.column("res_fx");
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(row[com + i], s.com[i]);
    for (int i = 0; i < 6; ++i) {
      EXPECT_EQ(row[root + i], s.root_wrench[i]);
      EXPECT_EQ(row[res + i], s.residual[i]);
    }
  }
  EXPECT_TRUE(std::signbit(table.rows[1][table.column("com_y")]));
  EXPECT_EQ(table.column("no such column"), -1);
}

/// The InputError reading `text` as a CSV file raises.
InputError read_error(const std::string& text) {
  const std::string path = temp_file("trajectory-bad.csv", text);
  try {
    read_csv_table(path);
  } catch (const InputError& e) {
    std::filesystem::remove(path);
    return e;
  }
  std::filesystem::remove(path);
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", "", "");
}

TEST(TrajectoryCsv, ReadingErrorsNameTheFileAndLine) {
  EXPECT_EQ(read_error("t,a\n0,1\n0.5,x1\n").json_path(), "line 3");
  EXPECT_EQ(read_error("t,a\n0,1\n0.5,x1\n").problem(), "not a finite number: \"x1\"");
  EXPECT_EQ(read_error("t,a\n0,1,2\n").json_path(), "line 2");
  EXPECT_EQ(read_error("t,a\n0,1,2\n").problem(), "expected 2 values, found 3");
  EXPECT_EQ(read_error("t,a\n0,inf\n").json_path(), "line 2");
  EXPECT_EQ(read_error("").json_path(), "line 1");
  const InputError missing = [] {
    try {
      read_csv_table("/nonexistent/saltus.csv");
    } catch (const InputError& e) {
      return e;
    }
    return InputError("", "", "");
  }();
  EXPECT_EQ(missing.file(), "/nonexistent/saltus.csv");
  EXPECT_EQ(missing.problem(), "cannot open file for reading");
}

}  // namespace
}  // namespace saltus
