#pragma once
/// @file
/// The paper's Table 1 (Wei, Xia & Wang 2008, §3.4): what every reproduction compares against.

#include <string>

namespace saltus {

/// A row of the paper's Table 1: keyframes, problem size, objective and average root force
/// before and after their optimisation.
struct PaperTableRow {
  const char* label;  ///< "M1" ... "M7"
  int keyframes, variables, constraints;
  double objective_before, objective_after;
  double force_before, force_after;  ///< N
};
extern const PaperTableRow kPaperTable1[7];

/// The paper's row for a skill label ("M3"), nullptr for any other motion.
const PaperTableRow* paper_table1(const std::string& skill);

}  // namespace saltus
