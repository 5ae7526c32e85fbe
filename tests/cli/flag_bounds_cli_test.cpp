// The bounds of every number flag on the command line (use_cases/flag_bounds.h through
// src/cli/flags/flag_bound_checks.h): every number flag of every verb's --help has its row, one
// step past each edge of every row (and NaN) is refused by `saltus` with exit status 2 naming the
// flag before anything is written, and the edges themselves are taken on paths that do no work
// (model new, a study's --emit-slurm).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "saltus/base/text_format.h"
#include "saltus/use_cases/flag_bounds.h"
#include "support/cli_runner.h"

namespace saltus {
namespace flag_bounds_cli {
namespace {

const std::string kMotion =
    std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json";

/// Every verb of `saltus` (each one's --help is read below).
const std::vector<std::string> kVerbs{"evaluate",      "simulate",        "optimize",
                                      "analyse twist", "analyse what-if", "study convergence",
                                      "study mass",    "study athletes",  "study merge",
                                      "paper",         "import",          "export",
                                      "model new",     "model scale",     "model yeadon",
                                      "model info"};

/// The verb's command line with its required arguments, writing to `out`, `flag` left out (the
/// test gives it).
std::string command_for(const std::string& verb, const std::string& flag, const std::string& out) {
  const std::map<std::string, std::string> required{
      {"study athletes", kMotion + " --models zatsiorsky-66kg"},
      {"paper", std::string(SALTUS_EXAMPLES_DIR) + "/motions"},
      {"import", std::string(SALTUS_CAPTURES_DIR) + "/mass-backflip.bvh"},
      {"export", kMotion + " --format bvh"},
      {"model scale", "zatsiorsky-66kg"},
      {"model yeadon", std::string(SALTUS_EXAMPLES_DIR) + "/athletes/yeadon-male1.txt"},
      {"model new", "--sex male"}};
  std::string command = verb + " ";
  const auto found = required.find(verb);
  command += found != required.end() ? found->second : kMotion;
  if (verb == "model new" || verb == "model scale")
    for (const char* size : {"--height 1.8", "--mass 70"})
      if (std::string(size).rfind(flag + " ", 0) != 0) command += std::string(" ") + size;
  return command + " --out '" + out + "'";
}

/// The number flags a verb's --help lists (type FLOAT, INT or UINT, or INT|auto).
std::set<std::string> number_flags_in_help(const std::string& verb) {
  const test::CliRun help = test::run_cli(verb + " --help");
  EXPECT_EQ(help.status, 0) << help.output;
  std::set<std::string> flags;
  const std::regex option(R"(^\s+(?:-\w,)?(--[\w-]+) (?:FLOAT|INT|UINT)\b)");
  std::smatch m;
  std::size_t start = 0;
  while (start < help.output.size()) {
    std::size_t end = help.output.find('\n', start);
    if (end == std::string::npos) end = help.output.size();
    const std::string line = help.output.substr(start, end - start);
    if (std::regex_search(line, m, option)) flags.insert(m[1]);
    start = end + 1;
  }
  return flags;
}

TEST(FlagBoundsCli, EveryNumberFlagOfEveryVerbHasItsRowAndEveryRowItsFlag) {
  std::map<std::string, std::string> helps;
  for (const std::string& verb : kVerbs) {
    for (const std::string& flag : number_flags_in_help(verb))
      EXPECT_NO_THROW(flag_bound(flag, verb)) << verb << " " << flag << " has no row";
    helps[verb] = test::run_cli(verb + " --help").output;
  }
  for (const FlagBound& row : flag_bounds())
    for (const std::string& verb : row.verbs) {
      if (verb == "saltus-gui") continue;  // tests/gui_core/command_line_test.cpp
      ASSERT_TRUE(helps.count(verb)) << verb << " is not a verb of saltus";
      EXPECT_NE(helps[verb].find(row.flag + " "), std::string::npos)
          << row.flag << " is not a flag of " << verb << ":\n"
          << helps[verb];
    }
}

/// One step past the end `end` of `row` (outward: -1 below, +1 above), as text.
std::string past(const FlagBound& row, double end, bool open, double outward) {
  if (open) return exact_number(end);
  if (row.bound.whole) return format_number("%.0f", end + outward);
  return exact_number(std::nextafter(end, outward * std::numeric_limits<double>::infinity()));
}

TEST(FlagBoundsCli, OneStepPastEachEdgeAndNaNAreRefusedNamingTheFlagBeforeAnyWork) {
  test::TempDir dir;
  int runs = 0;
  for (const FlagBound& row : flag_bounds()) {
    const std::string verb = row.verbs.front();
    if (verb == "saltus-gui") continue;
    std::vector<std::string> values{"nan"};
    if (std::isfinite(row.bound.lower))
      values.push_back(past(row, row.bound.lower, row.bound.lower_open, -1.0));
    if (std::isfinite(row.bound.upper))
      values.push_back(past(row, row.bound.upper, row.bound.upper_open, 1.0));
    for (const std::string& value : values) {
      const std::string out = dir / ("out" + std::to_string(runs++));
      const test::CliRun run =
          test::run_cli(command_for(verb, row.flag, out) + " " + row.flag + " " + value);
      EXPECT_EQ(run.status, 2) << verb << " " << row.flag << " " << value << ": " << run.output;
      // One line, "saltus: error: --flag: ..."; the option table's reader says "\"nan\" is not
      // a number (allowed: > 0)", --keyframes' "expected a number, found \"nan\"".
      EXPECT_EQ(run.output.rfind("saltus: error: " + row.flag + ": ", 0), 0u)
          << verb << " " << value << ": " << run.output;
      EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
      const std::size_t named = run.output.find(row.flag + ": ");
      EXPECT_TRUE(run.output.find(" is outside ", named) != std::string::npos ||
                  run.output.find(" is not a ", named) != std::string::npos ||
                  run.output.find("expected a number", named) != std::string::npos)
          << verb << " " << row.flag << " " << value << ": " << run.output;
      EXPECT_FALSE(std::filesystem::exists(out)) << out;
    }
  }
}

TEST(FlagBoundsCli, TheEdgesAreTaken) {
  test::TempDir dir;
  const std::string small = dir / "small.model.json";
  const std::string big = dir / "big.model.json";
  for (const std::string& size : {"--height 0.5 --mass 10 --age 5 --sex female --out " + small,
                                  "--height 2.8 --mass 300 --age 100 --sex male --out " + big}) {
    const test::CliRun run = test::run_cli("model new -q " + size);
    EXPECT_EQ(run.status, 0) << size << ": " << run.output;
  }
  // Every number option of study athletes at its lower edges, then at its upper ones: the
  // Slurm script is written without solving anything.
  std::string lower;
  std::string upper;
  for (const FlagBound& row : flag_bounds()) {
    if (std::find(row.verbs.begin(), row.verbs.end(), "study athletes") == row.verbs.end())
      continue;
    const double tiny = std::numeric_limits<double>::denorm_min();
    const double low = row.bound.lower_open ? row.bound.lower + tiny : row.bound.lower;
    const double high =
        std::isinf(row.bound.upper) ? std::numeric_limits<double>::max() : row.bound.upper;
    lower += " " + row.flag + " " + exact_number(low);
    upper +=
        " " + row.flag + " " + (row.bound.whole ? format_number("%.0f", high) : exact_number(high));
  }
  const std::string athletes = "study athletes " + kMotion + " -q --out " + (dir / "o");
  const test::CliRun at_lower =
      test::run_cli(athletes + " --models " + small + " --emit-slurm " + (dir / "low.sh") + lower);
  EXPECT_EQ(at_lower.status, 0) << lower << ": " << at_lower.output;
  const test::CliRun at_upper =
      test::run_cli(athletes + " --models " + big + " --emit-slurm " + (dir / "high.sh") + upper);
  EXPECT_EQ(at_upper.status, 0) << upper << ": " << at_upper.output;
  const std::string convergence = "study convergence " + kMotion + " -q --out " + (dir / "c") +
                                  " --emit-slurm " + (dir / "c.sh") + " --shards 1";
  const test::CliRun lists = test::run_cli(
      convergence +
      " --epsilons 5e-324,1.7976931348623157e308 --mass-errors -90,1000 --timing-errors 0,1 "
      "--seed 4294967295");
  EXPECT_EQ(lists.status, 0) << lists.output;
  EXPECT_EQ(test::run_cli(convergence + " --seed 0").status, 0);
  EXPECT_FALSE(std::filesystem::exists(dir / "o"));
}

}  // namespace
}  // namespace flag_bounds_cli
}  // namespace saltus
