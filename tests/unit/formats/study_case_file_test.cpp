// The per-case record (formats/study_case_file.h): every kind round-trips exactly, on a seeded
// family of records with numbers of every magnitude, NaN and infinities included; bad records
// are refused with the file and the field named.

#include "saltus/formats/study_case_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include "saltus/base/input_error.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

class RandomRecords {
 public:
  explicit RandomRecords(unsigned seed) : engine_(seed) {}

  double number() {
    switch (std::uniform_int_distribution<int>(0, 9)(engine_)) {
      case 0:
        return std::numeric_limits<double>::quiet_NaN();
      case 1:
        return std::numeric_limits<double>::infinity();
      case 2:
        return 0.0;
      default: {
        const double mantissa = std::uniform_real_distribution<double>(-1, 1)(engine_);
        return mantissa * std::pow(10.0, std::uniform_int_distribution<int>(-12, 12)(engine_));
      }
    }
  }
  int integer() { return std::uniform_int_distribution<int>(0, 100000)(engine_); }
  bool flag() { return engine_() & 1u; }
  std::string text() {
    static const char* words[] = {
        "M3",          "strict ε=50",   "±0.05 s", "dive-5m", "a \"quoted\" word",
        "line\nbreak", "max_iterations"};
    return words[std::uniform_int_distribution<int>(0, 6)(engine_)];
  }

  CaseRecord record(int index) {
    CaseRecord r;
    r.index = index;
    r.name = text();
    r.kind = static_cast<CaseKind>(std::uniform_int_distribution<int>(0, 2)(engine_));
    r.role = text();
    r.motion = text();
    r.folder = flag() ? "M" + std::to_string(index) : "";
    r.failure = flag() ? "" : text();
    StudyOutcome& o = r.convergence;
    o.study_case.motion = text();
    o.study_case.formulation = flag() ? Formulation::kRelaxed : Formulation::kStrict;
    o.study_case.epsilon = number();
    o.study_case.mass_segment = text();
    o.study_case.mass_error = number();
    o.study_case.timing_error_s = number();
    o.status = text();
    o.solved = flag();
    o.iterations = integer();
    o.seconds = number();
    o.variables = integer();
    o.constraints = integer();
    o.avg_force_before = number();
    o.avg_force_after = number();
    o.max_force_after = number();
    o.max_quaternion_error = number();
    o.knots_per_interval = integer();
    o.restarts = integer();
    RunSummary& s = r.run;
    s.motion_name = text();
    s.keyframes = integer();
    s.status = text();
    s.solved = flag();
    s.iterations = integer();
    s.seconds = number();
    s.variables = integer();
    s.constraints = integer();
    s.knots_per_interval = integer();
    s.objective_before = number();
    s.objective_after = number();
    s.avg_force_before = number();
    s.avg_force_after = number();
    for (int i = 0, n = integer() % 14; i < n; ++i) {
      s.keyframe_times_before.push_back(number());
      s.keyframe_times_after.push_back(number());
    }
    r.mass_markdown = text();
    return r;
  }

 private:
  std::mt19937 engine_;
};

/// Equal, with NaN equal to NaN and infinities read back as NaN (JSON has neither).
void expect_same_number(double written, double read, const char* what) {
  if (std::isfinite(written))
    EXPECT_EQ(written, read) << what;  // bit for bit: shortest round-trip digits
  else
    EXPECT_TRUE(std::isnan(read)) << what;
}

TEST(StudyCaseFile, EveryKindRoundTripsExactly) {
  RandomRecords random(20261124);
  test::TempDir dir;
  std::filesystem::create_directories(dir / "cases");
  for (int i = 0; i < 300; ++i) {
    const CaseRecord r = random.record(i);
    const std::string path = dir / case_record_name(i);
    write_case_record(path, r);
    const CaseRecord back = read_case_record(path);
    EXPECT_EQ(back.index, r.index);
    EXPECT_EQ(back.name, r.name);
    EXPECT_EQ(back.kind, r.kind);
    EXPECT_EQ(back.role, r.role);
    EXPECT_EQ(back.motion, r.motion);
    EXPECT_EQ(back.folder, r.folder);
    EXPECT_EQ(back.failure, r.failure);
    EXPECT_EQ(back.finished(), r.finished());
    switch (r.kind) {
      case CaseKind::kConvergence: {
        const StudyOutcome &a = r.convergence, &b = back.convergence;
        EXPECT_EQ(b.study_case.motion, a.study_case.motion);
        EXPECT_EQ(b.study_case.formulation, a.study_case.formulation);
        expect_same_number(a.study_case.epsilon, b.study_case.epsilon, "epsilon");
        EXPECT_EQ(b.study_case.mass_segment, a.study_case.mass_segment);
        expect_same_number(a.study_case.mass_error, b.study_case.mass_error, "mass_error");
        expect_same_number(a.study_case.timing_error_s, b.study_case.timing_error_s, "timing");
        EXPECT_EQ(b.status, a.status);
        EXPECT_EQ(b.solved, a.solved);
        EXPECT_EQ(b.iterations, a.iterations);
        expect_same_number(a.seconds, b.seconds, "seconds");
        EXPECT_EQ(b.variables, a.variables);
        EXPECT_EQ(b.constraints, a.constraints);
        expect_same_number(a.avg_force_before, b.avg_force_before, "before");
        expect_same_number(a.avg_force_after, b.avg_force_after, "after");
        expect_same_number(a.max_force_after, b.max_force_after, "max force");
        expect_same_number(a.max_quaternion_error, b.max_quaternion_error, "quaternion");
        EXPECT_EQ(b.knots_per_interval, a.knots_per_interval);
        EXPECT_EQ(b.restarts, a.restarts);
        break;
      }
      case CaseKind::kOptimization: {
        const RunSummary &a = r.run, &b = back.run;
        EXPECT_EQ(b.motion_name, a.motion_name);
        EXPECT_EQ(b.keyframes, a.keyframes);
        EXPECT_EQ(b.status, a.status);
        EXPECT_EQ(b.solved, a.solved);
        EXPECT_EQ(b.iterations, a.iterations);
        expect_same_number(a.seconds, b.seconds, "seconds");
        EXPECT_EQ(b.variables, a.variables);
        EXPECT_EQ(b.constraints, a.constraints);
        EXPECT_EQ(b.knots_per_interval, a.knots_per_interval);
        expect_same_number(a.objective_before, b.objective_before, "J before");
        expect_same_number(a.objective_after, b.objective_after, "J after");
        expect_same_number(a.avg_force_before, b.avg_force_before, "before");
        expect_same_number(a.avg_force_after, b.avg_force_after, "after");
        ASSERT_EQ(b.keyframe_times_before.size(), a.keyframe_times_before.size());
        ASSERT_EQ(b.keyframe_times_after.size(), a.keyframe_times_after.size());
        for (std::size_t k = 0; k < a.keyframe_times_before.size(); ++k) {
          expect_same_number(a.keyframe_times_before[k], b.keyframe_times_before[k], "time");
          expect_same_number(a.keyframe_times_after[k], b.keyframe_times_after[k], "time");
        }
        break;
      }
      case CaseKind::kMassStudy:
        EXPECT_EQ(back.mass_markdown, r.mass_markdown);
        break;
      case CaseKind::kAthlete:  // not drawn here: athletes_files_test.cpp reads those back
        ADD_FAILURE() << "an athlete record in the report's kinds";
        break;
    }
    // Written again, the record is the same bytes: merging shards rewrites records unchanged.
    const std::string again = dir / "again.json";
    write_case_record(again, back);
    EXPECT_EQ(test::read_text(again), test::read_text(path)) << i;
  }
  // Atomic writes leave no temporary file behind.
  for (const auto& entry : std::filesystem::directory_iterator(dir / "cases"))
    EXPECT_EQ(entry.path().extension(), ".json") << entry.path();
}

TEST(StudyCaseFile, BadRecordsNameTheFileAndTheField) {
  test::TempDir dir;
  CaseRecord r;
  r.index = 3;
  r.name = "M1 relaxed";
  r.role = "convergence";
  r.motion = "M1";
  const nlohmann::json good = case_record_to_json(r);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"/format", "format"},
      {"/index", "index"},
      {"/kind", "kind"},
      {"/folder", "folder"},
      {"/convergence/iterations", "iterations"}};
  for (const auto& [pointer, what] : cases) {
    nlohmann::json bad = good;
    if (what == "format") bad["format"] = "saltus-study-case/9";
    if (what == "index") bad["index"] = -1;
    if (what == "kind") bad["kind"] = "dance";
    if (what == "folder") bad["folder"] = "../elsewhere";
    if (what == "iterations") bad["convergence"]["iterations"] = "many";
    const std::string path = dir / (what + ".json");
    test::write_text(path, bad.dump());
    try {
      read_case_record(path);
      ADD_FAILURE() << what << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path) << what;
      EXPECT_EQ(e.json_path(), pointer) << what;
    }
  }
  nlohmann::json missing = good;
  missing["convergence"].erase("status");
  test::write_text(dir / "missing.json", missing.dump());
  EXPECT_THROW(read_case_record(dir / "missing.json"), InputError);
  test::write_text(dir / "truncated.json", good.dump().substr(0, 40));
  EXPECT_THROW(read_case_record(dir / "truncated.json"), InputError);
}

TEST(StudyCaseFile, RecordNamesSortInCaseOrder) {
  EXPECT_EQ(case_record_name(7), "cases/0007.json");
  EXPECT_EQ(case_record_name(12345), "cases/12345.json");
}

}  // namespace
}  // namespace saltus
