#pragma once
/// @file
/// What the Capture panel offers when the import's advice names a flag of `saltus import`: the
/// fix with the value the library suggests, one click away (a frame time under which the flight
/// falls at g), as the import options with that fix applied. The flags the advice names without
/// a value (the flight, the mapping file, the keyframes) are the Import settings dialog's.

#include <string>
#include <vector>

#include "saltus/use_cases/captures.h"

namespace saltus::gui {

struct CaptureFix {
  std::string flag;  ///< the flag of `saltus import` it sets: "--frame-time"
  /// "Re-import at 0.02097 s per frame (47.7 Hz)".
  std::string label;
  /// Why, in the library's words (the import's warning it answers).
  std::string reason;
  CaptureFileOptions options;  ///< `used` with the fix applied
};

/// The fixes for `capture`, imported with `used`, that the library gives a value for.
std::vector<CaptureFix> capture_fixes(const CaptureFile& capture, const CaptureFileOptions& used);

}  // namespace saltus::gui
