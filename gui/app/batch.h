#pragma once
/// @file
/// saltus-gui without user interaction: opens the motion in a real (unmapped) main window,
/// optionally optimises it, renders, writes the requested files, prints what it wrote and exits.

#include "core/command_line.h"

namespace saltus::gui {

/// Needs a QApplication. Returns the process exit status: 0 ok, 2 bad input, 1 other failure.
int run_batch(const CommandLine& command_line);

}  // namespace saltus::gui
