#pragma once
/// @file
/// Whether an X server answers at DISPLAY. The 3D view and the charts draw with VTK's X11
/// OpenGL window whatever Qt's platform is (the VTK of Debian 12 has no EGL or OSMesa window),
/// and VTK aborts ("bad X server connection") when it finds no server, e.g. under
/// QT_QPA_PLATFORM=offscreen on a machine without a screen. A file of its own: Xlib's macros
/// (None, Bool, KeyPress, ...) clash with Qt's names.

namespace saltus::gui {

bool x_display_reachable();

}  // namespace saltus::gui
