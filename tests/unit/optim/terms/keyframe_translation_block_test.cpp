// The keyframe translation constraints (eq. 2) (optim/terms/keyframe_translation_block.h) against
// central finite differences, through the term and block interfaces (support/term_checks.h).

#include "saltus/optim/terms/keyframe_translation_block.h"

#include <gtest/gtest.h>

#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(KeyframeTranslationBlock, JacobianMatchesFiniteDifferencesAndItsSparsity) {
  test::RandomPoint p(Formulation::kRelaxed);
  test::check_block(p, p.block("keyframe translation"), p.x);
}

}  // namespace
}  // namespace saltus
