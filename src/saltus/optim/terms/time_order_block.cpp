#include "saltus/optim/terms/time_order_block.h"

#include "saltus/optim/nlp.h"

namespace saltus {

void TimeOrderBlock::bounds(double* lower, double* upper) const {
  for (int r = 0; r < rows(); ++r) {
    lower[r] = gap_;
    upper[r] = kUnbounded;
  }
}

std::vector<std::vector<int>> TimeOrderBlock::sparsity() const {
  std::vector<std::vector<int>> rows_columns;
  for (int i = 0; i + 1 < layout_.keyframe_count; ++i) {
    std::vector<int> columns;
    if (layout_.time_variable(i) >= 0) columns.push_back(layout_.time_variable(i));
    if (layout_.time_variable(i + 1) >= 0) columns.push_back(layout_.time_variable(i + 1));
    rows_columns.push_back(columns);
  }
  return rows_columns;
}

void TimeOrderBlock::values(NlpEvaluations& at, double* g) {
  const std::vector<double>& t = at.keyframe_times();
  for (int i = 0; i + 1 < layout_.keyframe_count; ++i)
    g[i] = t[i + 1] - t[i];
}

void TimeOrderBlock::jacobian(NlpEvaluations&, double* values) {
  int entry = 0;
  for (int i = 0; i + 1 < layout_.keyframe_count; ++i) {
    if (layout_.time_variable(i) >= 0) values[entry++] = -1.0;
    if (layout_.time_variable(i + 1) >= 0) values[entry++] = 1.0;
  }
}

}  // namespace saltus
