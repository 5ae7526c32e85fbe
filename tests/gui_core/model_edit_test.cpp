// Mass-parameter editing: factors scale mass and inertia like the library's scale_segment_mass,
// the library's parser judges the result, and the document re-evaluates with the new model.

#include <gtest/gtest.h>

#include "core/document.h"
#include "core/model_edit.h"
#include "gui_core/test_motion.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/motion_file.h"

namespace saltus::gui {
namespace {

TEST(ModelEdit, FactorsScaleMassAndInertiaLikeTheLibrary) {
  const MotionFile file = load_motion_file(test::gui_test_motion_path());
  const BodyModel& original = file.model;
  std::vector<double> factors(static_cast<std::size_t>(original.size()), 1.0);
  const int thigh = original.segment_index("thigh_r");
  ASSERT_GE(thigh, 0);
  factors[static_cast<std::size_t>(thigh)] = 1.5;
  const BodyModel edited = model_with_mass_factors(original, factors, "heavy thigh");
  const BodyModel library = scale_segment_mass(original, "thigh_r", 1.5);
  EXPECT_EQ(edited.name, "heavy thigh");
  for (int i = 0; i < original.size(); ++i) {
    EXPECT_DOUBLE_EQ(edited.segments[i].mass, library.segments[i].mass) << i;
    EXPECT_TRUE(edited.segments[i].inertia.isApprox(library.segments[i].inertia)) << i;
  }
  EXPECT_NEAR(edited.total_mass() - original.total_mass(), 0.5 * original.segments[thigh].mass,
              1e-12);
  EXPECT_DOUBLE_EQ(mass_factor_for(original, thigh, 2.0 * original.segments[thigh].mass), 2.0);

  // All ones: the same model.
  const BodyModel same =
      model_with_mass_factors(original, std::vector<double>(original.segments.size(), 1.0));
  EXPECT_EQ(same.name, original.name);
  EXPECT_DOUBLE_EQ(same.total_mass(), original.total_mass());

  factors[static_cast<std::size_t>(thigh)] = 0.0;
  EXPECT_THROW(model_with_mass_factors(original, factors), std::invalid_argument);
  factors[static_cast<std::size_t>(thigh)] = -1.0;
  EXPECT_THROW(model_with_mass_factors(original, factors), std::invalid_argument);
  EXPECT_THROW(model_with_mass_factors(original, {1.0}), std::invalid_argument);
}

TEST(ModelEdit, DocumentReevaluatesWithTheEditedModel) {
  Document document;
  document.load(test::gui_test_motion_path(), "", 41);
  const double force = document.evaluation(Stage::kBefore).metrics.avg_root_force;
  const BodyModel original = document.file().model;
  std::vector<double> factors(original.segments.size(), 1.0);
  factors[static_cast<std::size_t>(original.segment_index("thigh_l"))] = 1.5;
  factors[static_cast<std::size_t>(original.segment_index("thigh_r"))] = 1.5;
  document.set_model(model_with_mass_factors(original, factors));
  EXPECT_TRUE(document.edited());
  EXPECT_GT(document.file().model.total_mass(), original.total_mass());
  EXPECT_DOUBLE_EQ(document.loaded_model().total_mass(), original.total_mass());
  // The library's evaluation with the heavier model, not a copy of the old numbers.
  EvaluateOptions o;
  o.samples = 41;
  EXPECT_DOUBLE_EQ(
      document.evaluation(Stage::kBefore).metrics.avg_root_force,
      evaluate_motion(document.file().motion, document.file().model, o).metrics.avg_root_force);
  EXPECT_NE(document.evaluation(Stage::kBefore).metrics.avg_root_force, force);
}

}  // namespace
}  // namespace saltus::gui
