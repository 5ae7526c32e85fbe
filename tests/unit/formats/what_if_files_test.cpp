// The what-if analysis's files (formats/what_if_files.h): result.json carries the change, the tuck
// before and after it, the three landings and the words exactly as the library computed them,
// and what_if.csv one row per sample with Yeadon's angles of both flights, which end at the
// counts result.json gives.

#include "saltus/formats/what_if_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "saltus/formats/csv_table.h"
#include "saltus/formats/twist_files.h"

namespace saltus {
namespace {

TEST(WhatIfFiles, ResultJsonAndCsvSayWhatTheFlightDid) {
  const MotionFile file = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                           "/motions/M2-tucked-back-somersault.motion.json");
  EvaluateOptions options;
  options.samples = 41;
  const WhatIf prepared(file.motion, file.model, options);
  WhatIfChange change;
  change.open_later_s = 0.05;
  change.tuck_scale = 1.05;
  const WhatIfResult r = prepared.fly(change);

  const nlohmann::json j = what_if_result_json(file, prepared, r);
  EXPECT_EQ(j["format"], kAnalysisFormat);
  EXPECT_EQ(j["analysis"], "what-if");
  EXPECT_EQ(j["motion"], file.motion.name);
  EXPECT_DOUBLE_EQ(j["change"]["open_later_s"].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(j["change"]["tuck_scale"].get<double>(), 1.05);
  EXPECT_EQ(j["change_words"], r.change_words);
  EXPECT_EQ(j["tuck"]["found"], true);
  EXPECT_DOUBLE_EQ(j["tuck"]["tucked_s"].get<double>(), prepared.tuck().tucked_s);
  EXPECT_DOUBLE_EQ(j["tuck"]["open_later_range_s"][1].get<double>(),
                   prepared.tuck().open_later_max_s);
  EXPECT_DOUBLE_EQ(j["changed_tuck"]["open_start_s"].get<double>(), r.tuck.open_start_s);
  EXPECT_DOUBLE_EQ(j["landing"]["somersaults"].get<double>(), r.landing.somersaults);
  EXPECT_DOUBLE_EQ(j["as_is"]["somersaults"].get<double>(),
                   prepared.unchanged_landing().somersaults);
  EXPECT_DOUBLE_EQ(j["keyframed"]["somersaults"].get<double>(), prepared.target().somersaults);
  EXPECT_DOUBLE_EQ(j["somersault_over_deg"].get<double>(), r.somersault_over_deg);
  EXPECT_DOUBLE_EQ(j["somersault_vs_as_is_deg"].get<double>(), r.somersault_vs_unchanged_deg);
  EXPECT_EQ(j["within_tolerance"], r.within_tolerance);
  EXPECT_EQ(j["sentence"], r.sentence);
  EXPECT_DOUBLE_EQ(j["takeoff_angular_momentum"][0].get<double>(), prepared.angular_momentum().x());

  std::stringstream csv(what_if_csv(prepared, r));
  const CsvTable table = parse_csv_table(csv, "what_if.csv");
  EXPECT_EQ(table.columns,
            (std::vector<std::string>{"t", "what_if_somersault_deg", "what_if_tilt_deg",
                                      "what_if_twist_deg", "as_is_somersault_deg", "as_is_tilt_deg",
                                      "as_is_twist_deg"}));
  ASSERT_EQ(table.rows.size(), 41u);
  EXPECT_DOUBLE_EQ(table.rows.back()[0], file.motion.flight_time());
  // Each flight's somersault angle turns by its count: a back somersault, so negatively.
  const auto turned = [&](int column) {
    return (table.rows.back()[column] - table.rows.front()[column]) / 360.0;
  };
  EXPECT_NEAR(std::abs(turned(1)), std::abs(r.landing.somersaults), 1e-9);
  EXPECT_NEAR(std::abs(turned(4)), std::abs(prepared.unchanged_landing().somersaults), 1e-9);
  EXPECT_GT(std::abs(turned(1)), std::abs(turned(4)));  // opened later, tighter: further
}

TEST(WhatIfFiles, AMotionWithoutATuckSaysWhy) {
  const MotionFile file = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                           "/motions/M1-straight-back-somersault.motion.json");
  EvaluateOptions options;
  options.samples = 21;
  const WhatIf prepared(file.motion, file.model, options);
  const nlohmann::json j = what_if_result_json(file, prepared, prepared.fly(WhatIfChange{}));
  EXPECT_EQ(j["tuck"]["found"], false);
  EXPECT_EQ(j["tuck"]["reason"], prepared.tuck().reason);
  EXPECT_EQ(j["change_words"], "as keyframed");
}

}  // namespace
}  // namespace saltus
