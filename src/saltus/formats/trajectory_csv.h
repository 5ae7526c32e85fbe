#pragma once
/// @file
/// The trajectory CSV of DESIGN §6: one row per sample; columns t; per segment S (model order)
/// S.x,S.y,S.z,S.qw,S.qx,S.qy,S.qz; com_x..z; root_fx..root_mz (F1..F6); res_fx..res_mz.

#include <ostream>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"

namespace saltus {

/// Column names in order.
std::vector<std::string> trajectory_csv_header(const BodyModel& model);

/// Writes header and rows, each double in the shortest text that reads back exactly: the file is
/// an exact record, and independent checks differentiate it numerically.
void write_trajectory_csv(std::ostream& out, const BodyModel& model,
                          const std::vector<SampleRecord>& samples);

/// A parsed trajectory CSV: column names and rows of numbers.
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// Index of a column, -1 if absent.
  int column(const std::string& name) const;
};

/// Reads a numeric CSV with a header line. Throws InputError naming the file and line.
CsvTable read_csv_table(const std::string& path);

}  // namespace saltus
