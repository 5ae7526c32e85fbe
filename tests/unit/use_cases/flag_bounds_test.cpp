// The bounds of every number flag (use_cases/flag_bounds.h): for each row, each end is taken
// and one step past it refused naming the flag (an option of the table by its own reader too),
// NaN and ±inf refused; docs/safety.md holds exactly the library's table.

#include "saltus/use_cases/flag_bounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "saltus/optim/option_table.h"

namespace saltus {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// What check_flag says of `value` for `row`: "" when it takes it.
std::string refusal(const FlagBound& row, double value) {
  try {
    check_flag(row.flag, value, row.verbs.front());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// The option table's own reader of `row`'s option agrees with check_flag on `value`.
void expect_option_reader_agrees(const FlagBound& row, double value) {
  if (!row.option_table) return;
  for (const OptionSpec& spec : option_table()) {
    if (spec.flag != row.flag) continue;
    const bool whole = std::abs(value) < 1e9 && value == std::floor(value);
    const std::string text = spec.kind == OptionKind::kInteger && whole
                                 ? std::to_string(static_cast<long long>(value))
                                 : exact_number(value);
    std::string problem;
    try {
      parse_option_value(spec, text);
    } catch (const OptionValueError& e) {
      problem = e.what();
    }
    if (refusal(row, value).empty())
      EXPECT_EQ(problem, "") << text;
    else
      EXPECT_EQ(problem.rfind(row.flag + ": ", 0), 0u) << problem;
  }
}

void expect_taken(const FlagBound& row, double value) {
  EXPECT_EQ(refusal(row, value), "") << row.flag << " " << exact_number(value);
  expect_option_reader_agrees(row, value);
}

void expect_refused(const FlagBound& row, double value) {
  const std::string problem = refusal(row, value);
  EXPECT_EQ(problem.rfind(row.flag + ": ", 0), 0u)
      << row.flag << " " << exact_number(value) << " taken: " << problem;
  EXPECT_TRUE(problem.find(" is outside ") != std::string::npos ||
              problem.find(" is not a whole number") != std::string::npos)
      << problem;
  expect_option_reader_agrees(row, value);
}

/// One end of the row's interval: taken at it (or, when open, just inside it), refused at it
/// when open and one step past it (a whole bound: one unit past, and a fraction past).
void expect_edge(const FlagBound& row, double end, bool open, double outward) {
  const double inward = -outward * kInf;
  if (std::isinf(end)) {
    expect_taken(row, std::copysign(std::numeric_limits<double>::max(), outward));
    expect_refused(row, end);
    return;
  }
  if (open) {
    expect_refused(row, end);
    expect_taken(row, std::nextafter(end, inward));
    return;
  }
  expect_taken(row, end);
  expect_refused(row, std::nextafter(end, outward * kInf));
  if (row.bound.whole) expect_refused(row, end + outward);
}

class FlagBoundEdges : public testing::TestWithParam<std::size_t> {};

TEST_P(FlagBoundEdges, EachEndIsTakenAndJustPastItIsRefusedNamingTheFlag) {
  const FlagBound& row = flag_bounds().at(GetParam());
  ASSERT_FALSE(row.verbs.empty()) << row.flag;
  expect_edge(row, row.bound.lower, row.bound.lower_open, -1.0);
  expect_edge(row, row.bound.upper, row.bound.upper_open, 1.0);
  for (double v : {std::nan(""), kInf, -kInf})
    expect_refused(row, v);
  // The message prints the table's interval, as docs/safety.md does.
  const std::string past = refusal(row, kInf);
  EXPECT_NE(past.find(bound_text(row.bound)), std::string::npos) << past;
  if (!row.why.empty()) EXPECT_NE(past.find("(" + row.why + ")"), std::string::npos) << past;
}

std::string row_name(const testing::TestParamInfo<std::size_t>& info) {
  const FlagBound& row = flag_bounds().at(info.param);
  std::string name = row.flag + "_" + row.verbs.front();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name.substr(name.find_first_not_of('_'));
}

INSTANTIATE_TEST_SUITE_P(EveryRow, FlagBoundEdges,
                         testing::Range<std::size_t>(0, flag_bounds().size()), row_name);

TEST(FlagBounds, EveryNumberOptionOfTheOptionTableHasItsRowWithTheSameBound) {
  for (const OptionSpec& spec : option_table()) {
    if (spec.kind != OptionKind::kInteger && spec.kind != OptionKind::kReal) continue;
    const FlagBound& row = flag_bound(spec.flag, "optimize");
    EXPECT_TRUE(row.option_table) << spec.flag;
    EXPECT_EQ(bound_text(row.bound), bound_text(option_bound(spec))) << spec.flag;
  }
}

TEST(FlagBounds, AFlagIsLookedUpForItsVerbAndAMissingRowIsAProgrammingError) {
  EXPECT_EQ(bound_text(flag_bound("--fps", "export").bound), "(0, ∞) fps");
  EXPECT_EQ(bound_text(flag_bound("--fps", "saltus-gui").bound), "(0, 120] fps");
  EXPECT_THROW(flag_bound("--fps", "evaluate"), std::logic_error);
  EXPECT_THROW(flag_bound("--frobnicate"), std::logic_error);
  try {
    check_flag("--height", 0.0, "model new", "Height");
    FAIL() << "a height of 0 m taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "Height");  // the app's form names its field
  }
}

TEST(FlagBounds, DocsSafetyHoldsTheLibrarysTable) {
  const std::string path = std::string(SALTUS_TOOLS_DIR) + "/../docs/safety.md";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::string begin = "<!-- flag bounds: begin -->\n";
  const std::string end = "<!-- flag bounds: end -->";
  const std::size_t from = doc.find(begin);
  const std::size_t to = doc.find(end);
  ASSERT_NE(from, std::string::npos) << path << " lacks " << begin;
  ASSERT_NE(to, std::string::npos) << path << " lacks " << end;
  const std::string table = doc.substr(from + begin.size(), to - from - begin.size());
  EXPECT_EQ(table, flag_bounds_markdown())
      << "docs/safety.md's table of flag bounds differs from the library's "
         "(use_cases/flag_bounds.cpp); put this between the markers:\n"
      << flag_bounds_markdown();
}

}  // namespace
}  // namespace saltus
