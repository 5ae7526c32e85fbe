#pragma once
/// @file
/// Where the app's save dialogs start: never in a folder bundled with Saltus (its examples and
/// resources: read-only once installed, and a checkout's to keep clean), nor in one that is gone
/// or cannot be written.

#include <functional>
#include <string>

namespace saltus::gui {

/// Whether `folder` is, or lies under, a folder bundled with Saltus: a resource folder
/// (resource_directories(): the models, an install's share/saltus with its examples) or the
/// examples folder beside a source tree's resources/.
bool bundled_with_saltus(const std::string& folder);

/// The folder a save dialog proposes: `last_saved` (where something was last saved) when
/// `writable` says so; else `last_opened` when writable and not bundled_with_saltus; else
/// `fallback` (the app makes it: ~/saltus).
std::string save_folder(const std::string& last_saved, const std::string& last_opened,
                        const std::string& fallback,
                        const std::function<bool(const std::string&)>& writable);

}  // namespace saltus::gui
