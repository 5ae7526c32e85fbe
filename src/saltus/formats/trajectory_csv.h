#pragma once
/// @file
/// The trajectory CSV of docs/formats.md: one row per sample; columns t; per segment S (model
/// order) S.x,S.y,S.z,S.qw,S.qx,S.qy,S.qz; com_x..z; root_fx..root_mz (F1..F6); res_fx..res_mz;
/// somersault_deg, tilt_deg, twist_deg (Yeadon's angles of the root, evaluation/yeadon_angles.h;
/// files written before them end at res_mz and still read).

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/formats/csv_table.h"

namespace saltus {

/// Column names in order.
std::vector<std::string> trajectory_csv_header(const BodyModel& model);

/// Writes header and rows, each double in the shortest text that reads back exactly: the file is
/// an exact record, and independent checks differentiate it numerically.
void write_trajectory_csv(std::ostream& out, const BodyModel& model,
                          const std::vector<SampleRecord>& samples);

/// A trajectory CSV read back.
struct TrajectoryCsv {
  std::vector<std::string> segments;  ///< segment names, in the file's (the model's) order
  /// One per row: time, segment positions and rotations, CoM, root wrench and residual as
  /// written; the quantities the file does not hold are left zero or empty.
  std::vector<SampleRecord> samples;
  /// Per row: somersault, tilt and twist (degrees, φ and ψ continuous); empty for older files.
  std::vector<Eigen::Vector3d> angles_deg;
};

/// Reads a trajectory CSV. Throws InputError naming the file and the line, or the column that
/// is not where docs/formats.md puts it.
TrajectoryCsv read_trajectory_csv(const std::string& path);
/// The same from a stream; `file` names it in errors.
TrajectoryCsv parse_trajectory_csv(std::istream& in, const std::string& file);

}  // namespace saltus
