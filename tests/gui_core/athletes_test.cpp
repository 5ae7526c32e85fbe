// Athletes in the app: the New athlete dialog's model is the library's, bad sizes and files give
// the library's message naming the field, the figures line carries the library's numbers, and a
// run's athlete is named with its size and take-off rule.

#include <gtest/gtest.h>

#include <fstream>

#include "core/athletes.h"
#include "core/document.h"
#include "gui_core/test_motion.h"
#include "saltus/body/mass_properties.h"
#include "saltus/use_cases/athlete_models.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

AthleteRequest junior_request() {
  AthleteRequest r;
  r.name = "junior";
  r.height_m = 1.45;
  r.mass_kg = 38.0;
  r.sex = "female";
  return r;
}

TEST(Athletes, ASizeGivesTheLibrarysDeLevaModel) {
  const AthleteDraft draft = draft_athlete(junior_request());
  ASSERT_TRUE(draft.model) << draft.problem;
  EXPECT_TRUE(draft.problem.empty());
  AthleteSize size;
  size.height_m = 1.45;
  size.mass_kg = 38.0;
  size.sex = Sex::kFemale;
  size.name = "junior";
  const BodyModel expected = new_athlete_model(size);
  EXPECT_EQ(draft.model->name, "junior");
  EXPECT_DOUBLE_EQ(draft.model->total_mass(), expected.total_mass());
  EXPECT_NEAR(standing_body(*draft.model).height(), 1.45, 1e-9);
  // The other sex is another table: other segment masses.
  AthleteRequest male = junior_request();
  male.sex = "male";
  const AthleteDraft other = draft_athlete(male);
  ASSERT_TRUE(other.model);
  EXPECT_NE(other.model->segments.front().mass, draft.model->segments.front().mass);
}

TEST(Athletes, BadSizesGiveTheLibrarysMessageNamingTheField) {
  AthleteRequest tall = junior_request();
  tall.height_m = 3.5;
  const AthleteDraft a = draft_athlete(tall);
  EXPECT_FALSE(a.model);
  EXPECT_EQ(a.problem.rfind("Height: ", 0), 0u) << a.problem;
  EXPECT_NE(a.problem.find("3.5 m"), std::string::npos) << a.problem;
  AthleteRequest heavy = junior_request();
  heavy.mass_kg = 400;
  EXPECT_EQ(draft_athlete(heavy).problem.rfind("Mass: ", 0), 0u);
  // A body mass index no person has names the mass.
  AthleteRequest odd = junior_request();
  odd.mass_kg = 200;
  EXPECT_EQ(draft_athlete(odd).problem.rfind("Mass: ", 0), 0u) << draft_athlete(odd).problem;
  AthleteRequest nosex = junior_request();
  nosex.sex = "";
  EXPECT_EQ(draft_athlete(nosex).problem.rfind("Sex: ", 0), 0u);
}

TEST(Athletes, AYeadonFileBuildsAndABrokenOneSaysWhy) {
  AthleteRequest r;
  r.source = AthleteRequest::Source::kYeadon;
  r.measurements = std::string(SALTUS_EXAMPLES_DIR) + "/athletes/yeadon-male1.txt";
  r.densities = "dempster";
  const AthleteDraft made = draft_athlete(r);
  ASSERT_TRUE(made.model) << made.problem;
  EXPECT_EQ(made.model->name, "yeadon-male1");
  EXPECT_FALSE(made.warnings.empty());  // La5L against Lb5L (examples/athletes/README.md)
  // A given mass scales the densities to it.
  r.yeadon_mass_kg = 70.0;
  const AthleteDraft scaled = draft_athlete(r);
  ASSERT_TRUE(scaled.model) << scaled.problem;
  EXPECT_NEAR(scaled.model->total_mass(), 70.0, 1e-6);
  for (const std::string& densities : yeadon_density_names()) {
    r.densities = densities;
    EXPECT_TRUE(draft_athlete(r).model) << densities;
  }

  saltus::test::TempDir dir;
  const std::string broken = dir / "broken.txt";
  std::ofstream(broken) << "Ls1L: 15.2\nLa2L: oops\n";
  r.measurements = broken;
  const AthleteDraft bad = draft_athlete(r);
  EXPECT_FALSE(bad.model);
  EXPECT_NE(bad.problem.find("broken.txt"), std::string::npos) << bad.problem;
  r.measurements.clear();
  EXPECT_FALSE(draft_athlete(r).problem.empty());
}

TEST(Athletes, FiguresAreTheLibrarysStandingNumbers) {
  const BodyModel model = *draft_athlete(junior_request()).model;
  const std::string figures = athlete_figures(model);
  const ModelSummary s = summarize_model(model);
  char mass[32], height[32], somersault[32];
  std::snprintf(mass, sizeof mass, "%.1f kg", s.total_mass);
  std::snprintf(height, sizeof height, "standing height %.3f m", s.standing.height());
  std::snprintf(somersault, sizeof somersault, "%.2f kg·m² somersault",
                s.standing.body.inertia(0, 0));
  EXPECT_NE(figures.find("38.0 kg"), std::string::npos) << figures;
  EXPECT_NE(figures.find(mass), std::string::npos) << figures;
  EXPECT_NE(figures.find("standing height 1.450 m"), std::string::npos) << figures;
  EXPECT_NE(figures.find(height), std::string::npos) << figures;
  EXPECT_NE(figures.find(somersault), std::string::npos) << figures;
}

TEST(Athletes, TheLabelNamesTheAthletesSizeAndTakeoffRule) {
  saltus::test::TempDir dir;
  const std::string model = dir / "junior.model.json";
  write_athlete_model(model, *draft_athlete(junior_request()).model);
  Document own;
  own.load(test::gui_test_motion_path(), "", 11);
  EXPECT_EQ(athlete_label(own.file()), "zatsiorsky-66kg 1.70 m 65.5 kg");
  // Flown by the junior as the CLI flies it: the same take-off spin.
  Document other;
  other.load(test::gui_test_motion_path(), model, 11);
  EXPECT_EQ(athlete_label(other.file()), "junior 1.45 m 38 kg, same take-off spin");
}

}  // namespace
}  // namespace saltus::gui
