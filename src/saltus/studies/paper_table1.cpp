#include "saltus/studies/paper_table1.h"

namespace saltus {

const PaperTableRow kPaperTable1[7] = {
    {"M1", 5, 264, 89, 3.88e3, 5.27e1, 25.4, 2.96},
    {"M2", 7, 350, 125, 8.66e4, 1.82e3, 120, 17.4},
    {"M3", 8, 393, 143, 6.40e4, 4.57e3, 103, 27.5},
    {"M4", 9, 436, 161, 1.44e5, 1.27e4, 154, 46.0},
    {"M5", 11, 522, 197, 4.48e5, 1.21e4, 273, 44.9},
    {"M6", 11, 522, 197, 1.61e5, 5.05e3, 163, 29.0},
    {"M7", 13, 595, 233, 4.15e5, 4.08e4, 262, 82.4},
};

const PaperTableRow* paper_table1(const std::string& skill) {
  for (const PaperTableRow& row : kPaperTable1)
    if (skill == row.label) return &row;
  return nullptr;
}

}  // namespace saltus
