#include "core/capture_fixes.h"

#include "saltus/base/text_format.h"

namespace saltus::gui {

std::vector<CaptureFix> capture_fixes(const CaptureFile& capture, const CaptureFileOptions& used) {
  std::vector<CaptureFix> fixes;
  const CaptureImport& im = capture.import;
  if (im.suggested_frame_time) {
    CaptureFix fix;
    fix.flag = "--frame-time";
    fix.label = format_number("Re-import at %.4g s per frame", *im.suggested_frame_time) +
                format_number(" (%.3g Hz)", 1.0 / *im.suggested_frame_time);
    for (const std::string& warning : im.warnings)
      if (warning.find("--frame-time") != std::string::npos) fix.reason = warning;
    fix.options = used;
    fix.options.import.frame_time = *im.suggested_frame_time;
    fixes.push_back(fix);
  }
  return fixes;
}

}  // namespace saltus::gui
