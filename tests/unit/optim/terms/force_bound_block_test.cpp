// The strict model's bounds |F_i| <= ε at every sample (optim/terms/force_bound_block.h) against
// central finite differences, through the term and block interfaces (support/term_checks.h).

#include "saltus/optim/terms/force_bound_block.h"

#include <gtest/gtest.h>

#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(ForceBoundBlock, JacobianMatchesFiniteDifferencesAndItsSparsity) {
  test::RandomPoint p(Formulation::kStrict);
  test::check_block(p, p.block("force bounds"), p.x);
}

}  // namespace
}  // namespace saltus
