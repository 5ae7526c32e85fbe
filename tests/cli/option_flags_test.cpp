// The option table's flags (src/cli/flags): every option parses through the table with the
// same values and messages on any CLI11 command, and the `saltus` verbs offer, accept and
// refuse them accordingly.

#include "flags/option_flags.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

/// Parses `args` (program name excluded) on a command carrying every option's flag.
const cli::OptionFlags& parse(CLI::App& app, cli::OptionFlags& flags,
                              std::vector<std::string> args) {
  flags.add(&app, cli::all_option_names());
  std::reverse(args.begin(), args.end());  // CLI11 takes them last first
  app.parse(args);
  return flags;
}

TEST(OptionFlags, EveryOptionParsesThroughTheTable) {
  for (const OptionSpec& spec : option_table()) {
    SCOPED_TRACE(spec.name);
    if (spec.kind == OptionKind::kSwitch) {
      CLI::App app;
      cli::OptionFlags flags;
      const OptionValue flagged = !std::get<bool>(spec.default_value());
      EXPECT_EQ(parse(app, flags, {spec.flag}).values().get(spec.name), flagged);
      ASSERT_EQ(flags.given().size(), 1u);
      EXPECT_EQ(flags.given()[0].first, spec.name);
      continue;
    }
    std::vector<std::string> texts;
    if (spec.kind == OptionKind::kChoice) texts = spec.choices;
    if (spec.kind != OptionKind::kChoice) {
      texts = {option_value_text(spec.default_value()), option_range_text(spec).substr(0, 1)};
      if (!std::isinf(spec.max) && spec.kind == OptionKind::kInteger)
        texts.push_back(std::to_string(static_cast<int>(spec.max)));
    }
    if (!spec.word.empty()) texts.push_back(spec.word);
    for (const std::string& text : texts) {
      if (text == ">") continue;  // "> 0": no bound value to try
      CLI::App app;
      cli::OptionFlags flags;
      const OptionValue expected = parse_option_value(spec, text);
      EXPECT_EQ(parse(app, flags, {spec.flag, text}).values().get(spec.name), expected) << text;
      OptionValues others = flags.values();
      others.set(spec.name, spec.default_value());
      EXPECT_EQ(others, OptionValues()) << "only " << spec.name << " changed";
    }
    for (const std::string& bad : {std::string("x"), std::string("1e400"), std::string("-7")}) {
      CLI::App app;
      cli::OptionFlags flags;
      try {
        parse(app, flags, {spec.flag, bad});
        ADD_FAILURE() << "accepted " << bad;
      } catch (const CLI::ParseError& e) {
        EXPECT_NE(std::string(e.what()).find(spec.flag), std::string::npos) << e.what();
      }
    }
  }
  CLI::App app;
  cli::OptionFlags flags;
  EXPECT_EQ(parse(app, flags, {}).values(), OptionValues());
  EXPECT_TRUE(flags.given().empty());
}

TEST(OptionFlags, EvaluationCommandsTakeNumberedKnotsOnly) {
  // auto knots are the optimiser's; evaluate and simulate start from the interpolation's K.
  CLI::App app;
  cli::OptionFlags flags;
  flags.add(&app, cli::option_names(OptionUse::kEvaluation), OptionUse::kEvaluation);
  EXPECT_EQ(flags.values(), OptionValues(OptionUse::kEvaluation));
  EXPECT_EQ(flags.values().integer("knots_per_interval"),
            EvaluateOptions{}.interpolation.knots_per_interval);
  try {
    app.parse(std::vector<std::string>{"auto", "--knots-per-interval"});
    ADD_FAILURE() << "an evaluation command took auto knots";
  } catch (const CLI::ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("--knots-per-interval"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("optimisations only"), std::string::npos) << e.what();
  }
  CLI::App numbered;
  cli::OptionFlags given;
  given.add(&numbered, cli::option_names(OptionUse::kEvaluation), OptionUse::kEvaluation);
  numbered.parse(std::vector<std::string>{"5", "--knots-per-interval"});
  EXPECT_EQ(given.values().evaluate_options().interpolation.knots_per_interval, 5);
}

TEST(CliOptions, HelpListsTheTablesFlagsWithTheirDefaults) {
  const auto optimize = test::run_cli("optimize --help");
  EXPECT_EQ(optimize.status, 0);
  for (const OptionSpec& spec : option_table()) {
    EXPECT_NE(optimize.output.find(spec.flag), std::string::npos) << spec.flag;
    if (spec.kind != OptionKind::kSwitch) {
      EXPECT_NE(optimize.output.find(spec.flag + " "), std::string::npos);
    }
  }
  EXPECT_NE(optimize.output.find("--samples INT=101"), std::string::npos) << optimize.output;
  EXPECT_NE(optimize.output.find("--max-joint-turn FLOAT=180"), std::string::npos);
  EXPECT_NE(optimize.output.find("--threads INT|auto=2"), std::string::npos);
  EXPECT_NE(optimize.output.find("--knots-per-interval INT|auto=auto"), std::string::npos);
  const auto evaluate = test::run_cli("evaluate --help");
  EXPECT_NE(evaluate.output.find("--knots-per-interval INT=1"), std::string::npos)
      << evaluate.output;
  EXPECT_EQ(evaluate.output.find("1-50 or auto"), std::string::npos) << evaluate.output;
  EXPECT_EQ(evaluate.output.find("--max-iter"), std::string::npos) << "an optimiser option";
  const auto study = test::run_cli("study mass --help");
  EXPECT_NE(study.output.find("--max-iter INT=300"), std::string::npos) << study.output;
  EXPECT_NE(study.output.find("(0-100000)"), std::string::npos) << study.output;
}

TEST(CliOptions, BadValuesExitWithTwoNamingTheFlagAndWriteNothing) {
  test::TempDir dir;
  const std::vector<std::string> bad{"evaluate M --samples 100001",
                                     "simulate M --knots-per-interval 0",
                                     "evaluate M --knots-per-interval auto",
                                     "optimize M --knots-per-interval 51",
                                     "optimize M --knots-per-interval automatic",
                                     "optimize M --epsilon 0",
                                     "optimize M --formulation loose",
                                     "optimize M --threads none",
                                     "optimize M --max-joint-turn 400",
                                     "optimize M --tol -1",
                                     "study mass M --samples 1",
                                     "study mass M --max-iter -1"};
  for (std::string command : bad) {
    const std::string flag =
        command.substr(command.rfind("--"), command.rfind(' ') - command.rfind("--"));
    command.replace(command.find(" M "), 3, " " + test::m1_path() + " ");
    const auto run = test::run_cli(command + " --out " + (dir / "out"));
    EXPECT_EQ(run.status, 2) << command << "\n" << run.output;
    EXPECT_NE(run.output.find(flag + ": "), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << command;
  }
}

TEST(CliOptions, StudiesAndThreadsTakeTheTablesValues) {
  test::TempDir dir;
  // --max-iter 0 (evaluate the starting point only) is a value for every verb.
  const auto study = test::run_cli("study mass " + test::m1_path() + " --out " + (dir / "m") +
                                   " --samples 21 --max-iter 0 --quiet");
  EXPECT_EQ(study.status, 0) << study.output;
  EXPECT_EQ(test::read_json(dir / "m/result.json")["protocol"], "optimize");
  const auto paper = test::run_cli("study mass " + test::m1_path() + " --out " + (dir / "p") +
                                   " --samples 21 --max-iter 0 --paper-protocol --quiet");
  EXPECT_EQ(paper.status, 0) << paper.output;
  EXPECT_EQ(test::read_json(dir / "p/result.json")["protocol"], "paper");
  const auto threads = test::run_cli("optimize " + test::m1_path() + " --out " + (dir / "o") +
                                     " --samples 21 --max-iter 1 --threads auto --quiet");
  EXPECT_TRUE(threads.status == 0 || threads.status == 3) << threads.output;
  EXPECT_TRUE(fs::exists(dir / "o/result.json"));
}

/// The `variables` of a result.json, or of the CSV row of `formulation`.
int variables_in(const std::string& text, const std::string& formulation = "") {
  if (formulation.empty()) return nlohmann::json::parse(text)["variables"].get<int>();
  std::istringstream csv(text);
  std::string line;
  std::getline(csv, line);  // header: ...,variables,... is the 11th column
  while (std::getline(csv, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');)
      cells.push_back(cell);
    if (cells.size() > 10 && cells[1] == formulation) return std::stoi(cells[10]);
  }
  return -1;
}

TEST(CliOptions, OptimizeChoosesItsKnotsAndTheStudiesKeepThePapers) {
  // optimize's default is the automatic resolution, finer than the paper's knots on M1; the
  // studies run at the paper's resolution (knots at the keyframes) whatever the default.
  test::TempDir dir;
  const std::string settings = " --samples 21 --max-iter 1 --quiet";
  for (const auto& [name, knots] :
       {std::pair<std::string, std::string>{"o", ""}, {"o1", " --knots-per-interval 1"}}) {
    const auto run =
        test::run_cli("optimize " + test::m1_path() + " --out " + (dir / name) + settings + knots);
    EXPECT_TRUE(run.status == 0 || run.status == 3) << run.output;
  }
  const nlohmann::json automatic = nlohmann::json::parse(test::read_text(dir / "o/result.json"));
  EXPECT_TRUE(automatic["resolution"]["automatic"].get<bool>());
  const int paper = variables_in(test::read_text(dir / "o1/result.json"));
  EXPECT_GT(automatic["variables"].get<int>(), paper) << "M1's automatic knots are finer";
  const auto study =
      test::run_cli("study convergence " + test::m1_path() + " --out " + (dir / "c") + settings +
                    " --epsilons 100 --mass-errors 0 --timing-errors 0");
  EXPECT_EQ(study.status, 0) << study.output;
  EXPECT_EQ(variables_in(test::read_text(dir / "c/convergence.csv"), "relaxed"), paper);
}

}  // namespace
}  // namespace saltus
