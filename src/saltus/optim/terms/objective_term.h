#pragma once
/// @file
/// One piece of the optimiser's objective (Drake's costs as bindings): MotionNlp sums a list of
/// them and never looks inside. Every term is a sum of squared residuals f = Σ r², so one
/// interface serves them all: its value, its gradient 2·Jᵀr, its Gauss–Newton curvature 2·JᵀJ
/// (the natural exact-Hessian stand-in, exact where the residuals vanish) and, for tests, the
/// residuals themselves. Curvature goes into the HessianBand and must stay inside it.
///
/// Adding a term: a new file here with a class that implements this, its registration in
/// MotionNlp's constructor, and a finite-difference test (tests/unit/optim/terms).

#include <string>
#include <vector>

#include "saltus/optim/hessian_band.h"
#include "saltus/optim/nlp_evaluations.h"

namespace saltus {

class ObjectiveTerm {
 public:
  virtual ~ObjectiveTerm() = default;

  virtual std::string name() const = 0;
  /// f at the current point of `at`.
  virtual double value(NlpEvaluations& at) = 0;
  /// gradient += ∇f.
  virtual void add_gradient(NlpEvaluations& at, double* gradient) = 0;
  /// values += factor · (Gauss–Newton curvature of f), inside `band`.
  virtual void add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                             double* values) = 0;
  /// The residuals r with f = Σ r² (for tests: value, gradient and curvature follow from them).
  virtual std::vector<double> residuals(NlpEvaluations& at) = 0;
};

}  // namespace saltus
