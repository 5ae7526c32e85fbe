#pragma once
/// @file
/// The mass study's files: DIR/{result.json, mass.csv, mass.md, model.json, model_scaled.json}
/// (written by use_cases/result_folders.h), and result.json and mass.csv read back.

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/csv_table.h"
#include "saltus/studies/mass_study.h"

namespace saltus {

/// The two runs of a mass study as mass.csv prefixes its columns: the given model, the scaled.
inline constexpr std::array<const char*, 2> kMassRunPrefixes{"given", "scaled"};

/// CSV: t, then per run and load segment the joint wrench (force N then moment N·m, segment
/// frame about the joint centre) and its force and moment magnitudes, ten significant digits.
std::string mass_study_csv(const MassStudyResult& study);

/// One run's joint loads at one segment, one value per time of MassCsv::time.
struct MassLoads {
  std::vector<Vector6d> wrench;  ///< force (N) then moment (N·m), segment frame, joint centre
  std::vector<double> force_N;   ///< |force| as written
  std::vector<double> moment_Nm;
};

/// mass.csv read back.
struct MassCsv {
  std::vector<double> time;                     ///< s
  std::vector<std::string> load_segments;       ///< in column order
  std::vector<std::array<MassLoads, 2>> loads;  ///< [segment][run: 0 given, 1 scaled]
};

/// Reads mass.csv; its header names the load segments. Throws InputError naming the file and
/// the column or line that is not as mass_study_csv writes it.
MassCsv read_mass_csv(const std::string& path);
MassCsv parse_mass_csv(const CsvTable& table, const std::string& file);

/// Markdown: per run, RMS and peak joint force and moment of each load segment, and the ratio
/// scaled/given.
std::string mass_study_markdown(const MassStudyResult& study);

/// The mass study's result.json: the motion, the scaling, and per run its solve summary.
nlohmann::json mass_result_json(const MotionFile& file, const MassStudyResult& study,
                                const MassStudyOptions& options);

/// A `saltus study mass` folder read back: result.json's summary and mass.csv.
struct MassStudyFolder {
  struct Run {
    std::string label;  ///< e.g. "table2", "thigh_l+thigh_r x1.5"
    std::string model;
    std::string status;
    int iterations = 0;
    double avg_force_before_N = 0.0;
    double avg_force_after_N = 0.0;
  };
  std::string path;
  std::string name;  ///< the folder's own name
  std::string motion;
  std::string motion_file;
  double factor = 1.0;
  std::vector<std::string> scaled_segments;
  std::vector<std::string> load_segments;
  std::array<Run, 2> runs;  ///< given, scaled
  MassCsv loads;            ///< mass.csv
};

/// Whether DIR/result.json parses and says "study": "mass". Anything else is false, so that
/// read_mass_study_folder or another reader can say what is wrong.
bool is_mass_study_folder(const std::string& dir);
/// Throws InputError naming the file (and field) that is missing or malformed.
MassStudyFolder read_mass_study_folder(const std::string& dir);

}  // namespace saltus
