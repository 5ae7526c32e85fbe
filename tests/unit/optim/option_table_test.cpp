// The option table: defaults are the option structs' own, every entry writes and reads the same
// field, text round-trips, ranges and words are enforced with the flag named, and result.json
// records exactly the options it recorded before the table existed.

#include "saltus/optim/option_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <set>

namespace saltus {
namespace {

/// Values across an option's range (seeded), its bounds, and its word.
std::vector<OptionValue> sample_values(const OptionSpec& spec, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<OptionValue> out;
  switch (spec.kind) {
    case OptionKind::kSwitch:
      return {true, false};
    case OptionKind::kChoice:
      for (const std::string& c : spec.choices)
        out.emplace_back(c);
      return out;
    case OptionKind::kInteger: {
      std::uniform_int_distribution<int> pick(static_cast<int>(spec.min),
                                              static_cast<int>(spec.max));
      out = {static_cast<int>(spec.min), static_cast<int>(spec.max)};
      for (int i = 0; i < 20; ++i)
        out.emplace_back(pick(rng));
      break;
    }
    case OptionKind::kReal: {
      const double top = std::isinf(spec.max) ? spec.min + 1e4 : spec.max;
      std::uniform_real_distribution<double> pick(spec.min, top);
      std::uniform_real_distribution<double> exponent(-12, 4);
      if (!spec.min_exclusive) out.emplace_back(spec.min);
      if (!std::isinf(spec.max)) out.emplace_back(spec.max);
      for (int i = 0; i < 20; ++i) {
        out.emplace_back(pick(rng));
        const double tiny = spec.min + std::pow(10.0, exponent(rng));
        if (tiny <= top) out.emplace_back(tiny);
      }
      break;
    }
  }
  if (!spec.word.empty()) out.emplace_back(spec.word);
  return out;
}

TEST(OptionTable, EveryEntryIsComplete) {
  std::set<std::string> names, flags, keys;
  for (const OptionSpec& spec : option_table()) {
    SCOPED_TRACE(spec.name);
    EXPECT_TRUE(names.insert(spec.name).second) << "duplicate name";
    EXPECT_TRUE(flags.insert(spec.flag).second) << "duplicate flag";
    EXPECT_EQ(spec.flag.rfind("--", 0), 0u);
    EXPECT_FALSE(spec.label.empty());
    EXPECT_FALSE(spec.help.empty());
    EXPECT_TRUE(spec.read && spec.write);
    EXPECT_EQ(spec.recorded == ResultRecord::kNone, spec.result_key.empty());
    if (!spec.result_key.empty()) {
      EXPECT_TRUE(keys.insert(spec.result_key).second);
    }
    if (spec.kind == OptionKind::kChoice) {
      EXPECT_GE(spec.choices.size(), 2u);
      EXPECT_EQ(spec.choice_labels.size(), spec.choices.size());
    }
    if (spec.kind == OptionKind::kInteger || spec.kind == OptionKind::kReal) {
      EXPECT_LT(spec.min, spec.max);
    }
    // The default is a value of the option.
    EXPECT_NO_THROW(checked_option_value(spec, spec.default_value()));
    // A costly value lies inside the range, above the default, and says what it costs.
    if (std::isfinite(spec.costly_above)) {
      EXPECT_TRUE(spec.kind == OptionKind::kInteger || spec.kind == OptionKind::kReal);
      EXPECT_LT(spec.costly_above, spec.max);
      EXPECT_FALSE(spec.cost.empty());
      const OptionValue d = spec.default_value();
      if (std::holds_alternative<int>(d)) {
        EXPECT_LT(std::get<int>(d), spec.costly_above);
      }
      if (std::holds_alternative<double>(d)) {
        EXPECT_LT(std::get<double>(d), spec.costly_above);
      }
    } else {
      EXPECT_TRUE(spec.cost.empty());
    }
  }
}

TEST(OptionTable, DefaultsAreTheLibrarysOwn) {
  const OptionValues defaults;
  EXPECT_EQ(defaults.integer("samples"), kDefaultSamples);
  // Optimisations choose their knots (automatic resolution); evaluations take the
  // interpolation's own default.
  ASSERT_TRUE(OptimizeOptions{}.automatic_resolution);
  EXPECT_EQ(defaults.get("knots_per_interval"), OptionValue(std::string("auto")));
  EXPECT_EQ(OptionValues(OptionUse::kEvaluation).integer("knots_per_interval"),
            InterpolationOptions{}.knots_per_interval);
  EXPECT_EQ(option_spec("knots_per_interval").default_value(OptionUse::kEvaluation),
            OptionValue(InterpolationOptions{}.knots_per_interval));
  EXPECT_EQ(defaults.integer("max_iterations"), SolverOptions{}.max_iterations);
  EXPECT_EQ(defaults.real("tolerance"), SolverOptions{}.tolerance);
  EXPECT_EQ(defaults.real("objective_change_tolerance"),
            SolverOptions{}.objective_change_tolerance);
  EXPECT_EQ(defaults.real("epsilon"), MotionNlpOptions{}.epsilon);
  EXPECT_EQ(defaults.real("max_time_shift"), MotionNlpOptions{}.max_time_shift);
  EXPECT_EQ(defaults.real("min_time_gap"), MotionNlpOptions{}.min_time_gap);
  EXPECT_EQ(defaults.real("regularization"), MotionNlpOptions{}.regularization);
  EXPECT_EQ(defaults.real("max_joint_turn"), 180.0);  // half a turn, exactly
  EXPECT_EQ(defaults.integer("threads"), MotionNlpOptions{}.threads);
  EXPECT_TRUE(defaults.on("optimize_timing"));
  EXPECT_EQ(std::get<std::string>(defaults.get("formulation")), "relaxed");

  // Applying the defaults changes nothing, bit for bit (the CLI applies every option).
  const OptimizeOptions applied = defaults.optimize_options();
  const OptimizeOptions plain;
  EXPECT_EQ(applied.nlp.joint_turn_limit, plain.nlp.joint_turn_limit);
  EXPECT_EQ(applied.nlp.epsilon, plain.nlp.epsilon);
  EXPECT_EQ(applied.solver.tolerance, plain.solver.tolerance);
  EXPECT_EQ(applied.nlp.formulation, plain.nlp.formulation);
  EXPECT_EQ(applied.nlp.threads, plain.nlp.threads);
  EXPECT_EQ(applied.automatic_resolution, plain.automatic_resolution);
  EXPECT_EQ(applied.nlp.knots_per_interval, plain.nlp.knots_per_interval);
  const EvaluateOptions evaluate = defaults.evaluate_options();
  EXPECT_EQ(evaluate.samples, EvaluateOptions{}.samples);
  EXPECT_EQ(evaluate.interpolation.knots_per_interval,
            EvaluateOptions{}.interpolation.knots_per_interval);
}

/// Equal, or for reals equal to rounding (a unit conversion such as degrees to radians and back).
void expect_same(const OptionValue& got, const OptionValue& want) {
  if (std::holds_alternative<double>(want) && std::holds_alternative<double>(got))
    EXPECT_NEAR(std::get<double>(got), std::get<double>(want),
                4e-16 * std::abs(std::get<double>(want)));
  else
    EXPECT_EQ(got, want);
}

TEST(OptionTable, WriteThenReadGivesTheValueAndTextRoundTrips) {
  for (const OptionSpec& spec : option_table()) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      for (const OptionValue& value : sample_values(spec, seed)) {
        SCOPED_TRACE(spec.name + " = " + option_value_text(value));
        OptionValues values;
        values.set(spec.name, value);
        EXPECT_EQ(values.get(spec.name), value);
        expect_same(spec.read(values.optimize_options()), value);
        expect_same(OptionValues(values.optimize_options()).get(spec.name), value);
        EXPECT_EQ(parse_option_value(spec, option_value_text(value)), value);
      }
    }
  }
}

TEST(OptionTable, OptionsLandInTheirFields) {
  OptionValues v;
  v.set("formulation", std::string("strict"));
  v.set("epsilon", 40);  // a whole number for a real option is taken as a real
  v.set("optimize_timing", false);
  v.set("knots_per_interval", 3);
  v.set("samples", 51);
  v.set("max_iterations", 0);
  v.set("tolerance", 1e-6);
  v.set("objective_change_tolerance", 0.0);
  v.set("max_time_shift", 0.1);
  v.set("min_time_gap", 0.02);
  v.set("regularization", 2.5);
  v.set("max_joint_turn", 90.0);
  v.set("threads", std::string("auto"));
  const OptimizeOptions o = v.optimize_options();
  EXPECT_EQ(o.nlp.formulation, Formulation::kStrict);
  EXPECT_EQ(o.nlp.epsilon, 40.0);
  EXPECT_FALSE(o.nlp.optimize_timing);
  EXPECT_EQ(o.nlp.knots_per_interval, 3);
  EXPECT_FALSE(o.automatic_resolution);  // a number: the uniform knots of the paper's style
  EXPECT_EQ(o.nlp.samples, 51);
  EXPECT_EQ(o.solver.max_iterations, 0);
  EXPECT_EQ(o.solver.tolerance, 1e-6);
  EXPECT_EQ(o.solver.objective_change_tolerance, 0.0);
  EXPECT_EQ(o.nlp.max_time_shift, 0.1);
  EXPECT_EQ(o.nlp.min_time_gap, 0.02);
  EXPECT_EQ(o.nlp.regularization, 2.5);
  EXPECT_NEAR(o.nlp.joint_turn_limit, M_PI / 2, 1e-15);
  EXPECT_EQ(o.nlp.threads, 0);  // MotionNlpOptions: 0 = one per hardware thread
  const EvaluateOptions e = v.evaluate_options();
  EXPECT_EQ(e.samples, 51);
  EXPECT_EQ(e.interpolation.knots_per_interval, 3);
  EXPECT_TRUE(v.applies("epsilon"));
  EXPECT_FALSE(OptionValues().applies("epsilon"));  // relaxed: ε has no effect
  EXPECT_FALSE(v.applies("max_time_shift"));        // times fixed
}

TEST(OptionTable, KnotsPerIntervalIsAutoOrANumberAndAutoIsTheOptimisersOnly) {
  const OptionSpec& knots = option_spec("knots_per_interval");
  // auto: the automatic resolution, starting from one span per interval.
  OptionValues v;
  v.set("knots_per_interval", 4);
  v.set_text("knots_per_interval", "auto");
  OptimizeOptions o = v.optimize_options();
  EXPECT_TRUE(o.automatic_resolution);
  EXPECT_EQ(o.nlp.knots_per_interval, 1);
  EXPECT_EQ(v.evaluate_options().interpolation.knots_per_interval, 1);
  // Every number 1-50: uniform knots, no automatic resolution, the same K for evaluations.
  for (int k = 1; k <= 50; ++k) {
    v.set_text("knots_per_interval", std::to_string(k));
    o = v.optimize_options();
    EXPECT_FALSE(o.automatic_resolution) << k;
    EXPECT_EQ(o.nlp.knots_per_interval, k);
    EXPECT_EQ(v.evaluate_options().interpolation.knots_per_interval, k);
    EXPECT_EQ(OptionValues(o).get("knots_per_interval"), OptionValue(k));
  }
  // Options from elsewhere read back as they are.
  OptimizeOptions automatic;
  automatic.nlp.knots_per_interval = 1;
  EXPECT_EQ(OptionValues(automatic).get("knots_per_interval"), OptionValue(std::string("auto")));
  automatic.automatic_resolution = false;
  EXPECT_EQ(OptionValues(automatic).get("knots_per_interval"), OptionValue(1));
  // Evaluations have no automatic resolution: the word is refused there, naming the flag.
  EXPECT_EQ(option_range_text(knots), "1-50 or auto");
  EXPECT_EQ(option_range_text(knots, OptionUse::kEvaluation), "1-50");
  EXPECT_EQ(option_range_text(option_spec("threads"), OptionUse::kEvaluation), "1-64 or auto");
  try {
    parse_option_value(knots, "auto", OptionUse::kEvaluation);
    ADD_FAILURE() << "an evaluation took auto knots";
  } catch (const OptionValueError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--knots-per-interval: \"auto\" is for optimisations only (allowed here: 1-50)");
  }
  OptionValues evaluation(OptionUse::kEvaluation);
  EXPECT_THROW(evaluation.set_text("knots_per_interval", "auto"), OptionValueError);
  EXPECT_EQ(evaluation, OptionValues(OptionUse::kEvaluation));
  evaluation.set_text("knots_per_interval", "7");
  EXPECT_EQ(evaluation.evaluate_options().interpolation.knots_per_interval, 7);
  EXPECT_FALSE(with_evaluation_options(EvaluateOptions{}).automatic_resolution);
  // result.json's requested K stays the number the optimiser starts from (main's writer).
  v.set_text("knots_per_interval", "auto");
  for (const auto& [key, value] : recorded_options(v.optimize_options(), true)) {
    if (key == "knots_per_interval_requested") {
      EXPECT_EQ(value, OptionValue(1));
    }
  }
}

TEST(OptionTable, ValuesOutsideTheOptionAreRejectedNamingTheFlag) {
  const std::vector<std::pair<std::string, std::string>> bad{
      {"samples", "1"},
      {"samples", "100001"},
      {"samples", "2.5"},
      {"samples", "many"},
      {"samples", ""},
      {"samples", "auto"},
      {"knots_per_interval", "0"},
      {"knots_per_interval", "51"},
      {"knots_per_interval", "Auto"},
      {"knots_per_interval", "2.0"},
      {"max_iterations", "-1"},
      {"max_iterations", "1e3"},
      {"epsilon", "0"},
      {"epsilon", "-3"},
      {"epsilon", "inf"},
      {"epsilon", "nan"},
      {"tolerance", "0"},
      {"objective_change_tolerance", "-0.1"},
      {"max_time_shift", "-1"},
      {"regularization", "1,5"},
      {"max_joint_turn", "361"},
      {"max_joint_turn", "-1"},
      {"threads", "0"},
      {"threads", "65"},
      {"threads", "Auto"},
      {"formulation", "loose"},
      {"formulation", ""},
      {"optimize_timing", "maybe"},
  };
  for (const auto& [name, text] : bad) {
    const OptionSpec& spec = option_spec(name);
    try {
      parse_option_value(spec, text);
      ADD_FAILURE() << name << " accepted \"" << text << "\"";
    } catch (const OptionValueError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(spec.flag + ": ", 0), 0u) << e.what();
      EXPECT_FALSE(e.problem().empty());
    }
  }
  OptionValues v;
  EXPECT_THROW(v.set("samples", 2.0), OptionValueError);  // a real for an integer option
  EXPECT_THROW(v.set("epsilon", std::string("auto")), OptionValueError);
  EXPECT_THROW(v.set("optimize_timing", 1), OptionValueError);
  EXPECT_THROW(v.set("formulation", true), OptionValueError);
  EXPECT_THROW(v.set("max_joint_turn", std::nan("")), OptionValueError);
  EXPECT_EQ(v, OptionValues());  // a rejected value leaves the values as they were
  EXPECT_THROW(v.get("no_such_option"), std::logic_error);
  // Text as people and stored settings write it.
  EXPECT_EQ(parse_option_value(option_spec("tolerance"), "1e-8"), OptionValue(1e-8));
  EXPECT_EQ(parse_option_value(option_spec("optimize_timing"), "false"), OptionValue(false));
  EXPECT_EQ(parse_option_value(option_spec("threads"), "auto"), OptionValue(std::string("auto")));
  EXPECT_EQ(option_range_text(option_spec("samples")), "2-100000");
  EXPECT_EQ(option_range_text(option_spec("epsilon")), "> 0");
  EXPECT_EQ(option_range_text(option_spec("threads")), "1-64 or auto");
  EXPECT_EQ(option_range_text(option_spec("formulation")), "relaxed|strict");
}

/// result.json's option keys as the writer recorded them before the table existed
/// (formats/result_json.cpp at aa271c3; at fecac7f the requested K is still the number the
/// optimiser starts from, 1 with automatic resolution).
std::map<std::string, OptionValue> recorded_before_the_table(const OptimizeOptions& o) {
  std::map<std::string, OptionValue> r;
  r["samples"] = o.nlp.samples;
  r["knots_per_interval_requested"] = o.nlp.knots_per_interval;
  r["formulation"] = std::string(o.nlp.formulation == Formulation::kRelaxed ? "relaxed" : "strict");
  if (o.nlp.formulation == Formulation::kStrict) r["epsilon"] = o.nlp.epsilon;
  // Added with the keyframe prior (issue 13): what brought the times back is on record.
  if (o.nlp.formulation == Formulation::kRelaxed && o.automatic_resolution)
    r["keyframe_weight"] = o.nlp.keyframe_weight;
  // Added with the joint-acceleration term (issue 24): relaxed model only.
  if (o.nlp.formulation == Formulation::kRelaxed) r["joint_effort"] = o.nlp.joint_effort;
  // Added with least joint effort (issue 24): relaxed model only.
  if (o.nlp.formulation == Formulation::kRelaxed) r["joint_load_weight"] = o.nlp.joint_load_weight;
  r["timing_optimized"] = o.nlp.optimize_timing;
  r["joint_turn_limit_deg"] =
      o.nlp.limits_joint_turns() ? o.nlp.joint_turn_limit * 180.0 / M_PI : 0.0;
  return r;
}

TEST(OptionTable, ResultJsonRecordsWhatItAlwaysRecorded) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    OptionValues v;
    for (const OptionSpec& spec : option_table()) {
      const std::vector<OptionValue> choices = sample_values(spec, 100 + trial);
      v.set(spec.name, choices[rng() % choices.size()]);
    }
    OptimizeOptions o = v.optimize_options();
    if (trial % 5 == 0) o.nlp.joint_turn_weight = 0;  // the limit is off however it is set
    std::map<std::string, OptionValue> recorded;
    for (const auto& [key, value] : recorded_options(o, true))
      EXPECT_TRUE(recorded.emplace(key, value).second) << key;
    const auto expected = recorded_before_the_table(o);
    ASSERT_EQ(recorded.size(), expected.size());
    for (const auto& [key, value] : expected) {
      ASSERT_EQ(recorded.count(key), 1u) << key;
      if (key == "joint_turn_limit_deg")
        EXPECT_NEAR(std::get<double>(recorded[key]), std::get<double>(value), 1e-12);
      else
        EXPECT_EQ(recorded[key], value) << key;
    }
    // Evaluations record the evaluation grid only.
    const auto evaluation = recorded_options(with_evaluation_options(v.evaluate_options()), false);
    ASSERT_EQ(evaluation.size(), 1u);
    EXPECT_EQ(evaluation[0].first, "samples");
    EXPECT_EQ(evaluation[0].second, v.get("samples"));
  }
}

TEST(OptionTable, WhenAnOptionAppliesIsItsEntrysAndRunsUseTheDeclaredInactiveValue) {
  // The keyframe prior acts with the automatic resolution of the relaxed model only: the entry
  // says so, --help and the app's tooltip show it, and a run on fixed knots takes 0.
  const OptionSpec& prior = option_spec("keyframe_weight");
  EXPECT_NE(option_description(prior).find("Applies with --knots-per-interval auto"),
            std::string::npos)
      << option_description(prior);
  EXPECT_NE(option_description(option_spec("epsilon")).find("Applies with --formulation strict"),
            std::string::npos);
  EXPECT_EQ(option_description(option_spec("samples")).find("Applies"), std::string::npos);

  OptionValues v;
  v.set("keyframe_weight", 7.0);
  EXPECT_TRUE(v.applies("keyframe_weight"));
  EXPECT_EQ(effective_options(v.optimize_options()).nlp.keyframe_weight, 7.0);
  v.set("knots_per_interval", 2);
  EXPECT_FALSE(v.applies("keyframe_weight"));
  EXPECT_EQ(effective_options(v.optimize_options()).nlp.keyframe_weight, 0.0);
  v.set("knots_per_interval", std::string("auto"));
  v.set("formulation", std::string("strict"));
  EXPECT_FALSE(v.optimize_options().resolution_is_automatic());
  EXPECT_EQ(effective_options(v.optimize_options()).nlp.keyframe_weight, 0.0);
  // An option that does not apply but declares no inactive value keeps its value (unused).
  v.set("formulation", std::string("relaxed"));
  v.set("epsilon", 3.0);
  EXPECT_EQ(effective_options(v.optimize_options()).nlp.epsilon, 3.0);
}

TEST(OptionTable, TheSettingsThatDecideAResultNameEveryOptionAndEveryInternalSetting) {
  const OptimizeOptions defaults;
  const nlohmann::json base = result_deciding_settings(defaults);
  for (const OptionSpec& spec : option_table())
    EXPECT_TRUE(base.contains(spec.name)) << spec.name;
  // Every option and every internal setting changes the record.
  std::mt19937 rng(11);
  for (const OptionSpec& spec : option_table()) {
    OptionValues v;
    for (const OptionValue& value : sample_values(spec, 5)) {
      v.set(spec.name, value);
      if (v.get(spec.name) != OptionValues().get(spec.name)) break;
    }
    EXPECT_NE(result_deciding_settings(v.optimize_options()), base) << spec.name;
  }
  std::vector<std::function<void(OptimizeOptions&)>> internal = {
      [](OptimizeOptions& o) {
        o.nlp.subdivisions = {2, 3};
      },
      [](OptimizeOptions& o) { o.nlp.quadrature_nodes += 1; },
      [](OptimizeOptions& o) { o.nlp.quadrature_spacing *= 2; },
      [](OptimizeOptions& o) {
        o.nlp.given_keyframe_times = {0.0, 1.0};
      },
      [](OptimizeOptions& o) { o.nlp.damping.initial *= 2; },
      [](OptimizeOptions& o) { o.nlp.damping.poor_ratio *= 0.5; },
      [](OptimizeOptions& o) { o.nlp.adapt_damping = !o.nlp.adapt_damping; },
      [](OptimizeOptions& o) { o.nlp.joint_turn_weight += 1; },
      [](OptimizeOptions& o) { o.solver.acceptable_iterations += 1; },
      [](OptimizeOptions& o) { o.solver.acceptable_constraint_violation *= 2; },
      [](OptimizeOptions& o) { o.solver.stall_iterations += 1; },
      [](OptimizeOptions& o) { o.solver.max_restarts += 1; },
      [](OptimizeOptions& o) {
        o.solver.feasibility_checkpoints.push_back({10, 1.0});
      },
      [](OptimizeOptions& o) { o.solver.warm_start = !o.solver.warm_start; },
      [](OptimizeOptions& o) { o.refine_when_keyframes_missed = !o.refine_when_keyframes_missed; },
  };
  for (std::size_t i = 0; i < internal.size(); ++i) {
    OptimizeOptions o;
    internal[i](o);
    EXPECT_NE(result_deciding_settings(o), base) << "internal setting " << i;
  }
  // An option that does not apply is recorded at the value the run uses: on fixed knots the
  // keyframe prior is 0 whatever it was set to.
  OptionValues fixed;
  fixed.set("knots_per_interval", 1);
  const nlohmann::json fixed_record = result_deciding_settings(fixed.optimize_options());
  fixed.set("keyframe_weight", 33.0);
  EXPECT_EQ(result_deciding_settings(fixed.optimize_options()), fixed_record);
  EXPECT_EQ(fixed_record["keyframe_weight"], 0.0);
  // What decides only the log does not.
  OptimizeOptions logged;
  logged.solver.verbose = true;
  logged.solver.derivative_test_file = "check.txt";
  EXPECT_EQ(result_deciding_settings(logged), base);
}

}  // namespace
}  // namespace saltus
