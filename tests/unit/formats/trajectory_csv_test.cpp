// The trajectory CSV (docs/formats.md): its header, seeded samples and awkward numbers written and
// read back exactly, and files whose columns are not where the format puts them refused naming
// the file, line and column.

#include "saltus/formats/trajectory_csv.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/evaluation/yeadon_angles.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/formats/model_file.h"
#include "saltus/motion/interpolate.h"
#include "support/temp_path.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

BodyModel model() {
  return load_body_model(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
}

std::vector<SampleRecord> random_samples(const BodyModel& m, unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> any(-50, 50);
  std::normal_distribution<double> gauss;
  std::vector<SampleRecord> out;
  for (int k = 0; k < count; ++k) {
    SampleRecord r;
    r.time = k * 0.0137 + any(rng) * 1e-9;
    for (int s = 0; s < m.size(); ++s) {
      r.segment_position.emplace_back(any(rng), any(rng), any(rng));
      // Any sign of w: the file keeps one hemisphere.
      r.segment_rotation.push_back(
          Eigen::Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized());
    }
    r.com = Eigen::Vector3d(any(rng), any(rng), any(rng));
    for (int i = 0; i < 6; ++i) {
      r.root_wrench[i] = any(rng) * std::pow(10.0, any(rng) / 5);
      r.residual[i] = any(rng) * 1e-13;
    }
    out.push_back(r);
  }
  return out;
}

TEST(TrajectoryCsv, SamplesReadBackExactly) {
  const BodyModel m = model();
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const std::vector<SampleRecord> samples = random_samples(m, seed, 7 + seed);
    std::stringstream file;
    write_trajectory_csv(file, m, samples);
    const TrajectoryCsv csv = parse_trajectory_csv(file, "t.csv");
    ASSERT_EQ(csv.samples.size(), samples.size());
    ASSERT_EQ(csv.segments.size(), static_cast<std::size_t>(m.size()));
    for (int s = 0; s < m.size(); ++s)
      EXPECT_EQ(csv.segments[s], m.segments[s].name);
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const SampleRecord &a = csv.samples[k], &b = samples[k];
      EXPECT_EQ(a.time, b.time);
      EXPECT_EQ(a.com, b.com);
      EXPECT_EQ(a.root_wrench, b.root_wrench);
      EXPECT_EQ(a.residual, b.residual);
      for (int s = 0; s < m.size(); ++s) {
        EXPECT_EQ(a.segment_position[s], b.segment_position[s]);
        const double sign = b.segment_rotation[s].w() < 0 ? -1.0 : 1.0;
        EXPECT_EQ(a.segment_rotation[s].coeffs(), sign * b.segment_rotation[s].coeffs());
      }
    }
  }
}

/// Rewrites the header cell `index` of a valid file.
std::string with_header_cell(const BodyModel& m, std::size_t index, const std::string& cell) {
  std::vector<std::string> header = trajectory_csv_header(m);
  header[index] = cell;
  std::stringstream file;
  write_trajectory_csv(file, m, random_samples(m, 3, 2));
  std::string text = file.str();
  std::string line;
  for (std::size_t i = 0; i < header.size(); ++i)
    line += (i ? "," : "") + header[i];
  return line + text.substr(text.find('\n'));
}

TEST(TrajectoryCsv, MisplacedColumnsAreNamed) {
  const BodyModel m = model();
  const std::size_t trailing_start = 1 + 7 * m.size();
  const std::vector<std::pair<std::size_t, std::string>> cases{
      {0, "time"},     {1, "pelvis"},           {3, "root.z2"},
      {8, "thorax.y"}, {trailing_start, "com"}, {trailing_start + 14, "res_mx"}};
  for (const auto& [index, cell] : cases) {
    std::stringstream file(with_header_cell(m, index, cell));
    try {
      parse_trajectory_csv(file, "t.csv");
      ADD_FAILURE() << "accepted " << cell << " at column " << index + 1;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("t.csv"), std::string::npos) << what;
      EXPECT_NE(what.find("column " + std::to_string(index + 1)), std::string::npos) << what;
    }
  }
  std::stringstream short_header("t,com_x\n0,1\n");
  EXPECT_THROW(parse_trajectory_csv(short_header, "t.csv"), InputError);
  std::stringstream ragged(with_header_cell(m, 0, "t") + "0,1,2\n");
  EXPECT_THROW(parse_trajectory_csv(ragged, "t.csv"), InputError);
  EXPECT_THROW(read_trajectory_csv("/nonexistent/t.csv"), InputError);
}

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = test::temp_path(name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(TrajectoryCsv, HeaderHasTimePosesCentreOfMassRootWrenchAndResidual) {
  const BodyModel model = test::bundled_model();
  const std::vector<std::string> h = trajectory_csv_header(model);
  ASSERT_EQ(h.size(), 1u + 7u * model.size() + 18u);
  EXPECT_EQ(h[0], "t");
  EXPECT_EQ(h[1], model.segments[0].name + ".x");
  EXPECT_EQ(h[7], model.segments[0].name + ".qz");
  EXPECT_EQ(h[8], model.segments[1].name + ".x");
  EXPECT_EQ(h[1 + 7 * model.size()], "com_x");
  EXPECT_EQ(h[h.size() - 10], "root_mz");
  EXPECT_EQ(h[h.size() - 4], "res_mz");
  EXPECT_EQ(h[h.size() - 3], "somersault_deg");
  EXPECT_EQ(h.back(), "twist_deg");
}

TEST(TrajectoryCsv, FilesWithoutTheAnglesStillReadAndTheAnglesReadBack) {
  const BodyModel m = model();
  std::stringstream file;
  write_trajectory_csv(file, m, random_samples(m, 3, 5));
  const TrajectoryCsv with = parse_trajectory_csv(file, "new.csv");
  ASSERT_EQ(with.angles_deg.size(), 5u);
  // The angles are Yeadon's of each row's root rotation.
  for (std::size_t k = 0; k < 5; ++k) {
    const Eigen::Vector3d raw = somersault_tilt_twist(with.samples[k].segment_rotation[0]);
    EXPECT_NEAR(with.angles_deg[k][1], raw[1] * 180.0 / M_PI, 1e-9);
    for (int i : {0, 2})
      EXPECT_NEAR(std::remainder(with.angles_deg[k][i] - raw[i] * 180.0 / M_PI, 360.0), 0.0, 1e-9);
  }
  // An older file: the same rows without the three last columns.
  std::string older;
  std::string line;
  std::stringstream again(file.str());
  while (std::getline(again, line)) {
    for (int cut = 0; cut < 3; ++cut)
      line.erase(line.rfind(','));
    older += line + "\n";
  }
  std::stringstream old_file(older);
  const TrajectoryCsv without = parse_trajectory_csv(old_file, "old.csv");
  EXPECT_TRUE(without.angles_deg.empty());
  ASSERT_EQ(without.samples.size(), 5u);
  EXPECT_EQ(without.samples[4].residual, with.samples[4].residual);
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

}  // namespace
}  // namespace saltus
