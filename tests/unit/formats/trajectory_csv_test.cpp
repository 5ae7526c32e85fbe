// The trajectory CSV (DESIGN §6): seeded samples written and read back exactly, and files whose
// columns are not where the format puts them refused naming the file, line and column.

#include "saltus/formats/trajectory_csv.h"

#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/formats/model_file.h"

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

}  // namespace
}  // namespace saltus
