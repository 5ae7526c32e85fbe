#pragma once
/// @file
/// The progress line a study prints on stderr after every case, and reading it back: the app
/// runs a study through the `saltus` program and shows these lines as its progress bar, so the
/// line's form lives here, once.

#include <optional>
#include <string>

#include "saltus/formats/study_case_file.h"

namespace saltus {

/// Where a running study stands, after each case.
struct StudyProgress {
  int done = 0;            ///< cases of the shard with a record, those kept from before included
  int total = 0;           ///< cases of the shard
  int failed = 0;          ///< records whose process crashed or timed out
  int unsolved = 0;        ///< records that finished without solving
  double elapsed_s = 0.0;  ///< since this run started
  double eta_s = -1.0;     ///< remaining time at this run's pace; −1 before the first case
  const CaseRecord* last = nullptr;  ///< the record just written
};

/// "  [ 12/40] 0 failed, 3 not solved, 0:41 elapsed, ETA 1:02  M1 strict ε=10, …: solved, 37 it.,
/// 2.1 N" (the counts padded to the width of the total).
std::string study_progress_line(const StudyProgress& progress);

/// A progress line read back. eta_s is −1 where the line says "?".
struct StudyProgressLine {
  int done = 0;
  int total = 0;
  int failed = 0;
  int unsolved = 0;
  double elapsed_s = 0.0;
  double eta_s = -1.0;
  std::string last_case;    ///< the case just recorded, in words
  std::string last_result;  ///< what it came to ("solved, 37 it., 2.1 N", or why it failed)
};

/// The line's fields, or nothing when `line` is not a progress line (other messages).
std::optional<StudyProgressLine> parse_study_progress_line(const std::string& line);

/// Seconds as "m:ss" or, from an hour, "h:mm:ss".
std::string clock_text(double seconds);

}  // namespace saltus
