#pragma once
/// @file
/// saltus-gui without user interaction: opens the motion in a real (unmapped) main window,
/// optionally optimises it, renders, writes the requested files, prints what it wrote and exits.

#include <QSize>
#include <QString>

#include "app/video_exporter.h"
#include "core/command_line.h"

namespace saltus::gui {

class MainWindow;

/// Needs a QApplication. Returns the process exit status: 0 ok, 2 bad input, 1 other failure.
int run_batch(const CommandLine& command_line);

// Batch jobs on a window with a motion open (what `--compare B --screenshot X` and
// `--export-video FILE` do). Each prints what it wrote, or the error on stderr, and returns
// the exit status.

/// The compare window of the open motion against `other` (a motion file or a result folder) at
/// `time`, `size` pixels, as PNG.
int write_compare_screenshot(MainWindow& window, const QString& other, double time,
                             const QSize& size, const QString& png);
/// The animation of the open motion as shown (.mp4 or .gif).
int write_video(MainWindow& window, const QString& path, const VideoOptions& options);

}  // namespace saltus::gui
