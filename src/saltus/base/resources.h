#pragma once
/// @file
/// Finding bundled resources (body models) whether Saltus runs from its build tree or installed.

#include <string>
#include <vector>

namespace saltus {

/// Folders searched for resources, first match wins: $SALTUS_RESOURCE_DIR if set, share/saltus
/// beside the running executable's bin/ (an install under any prefix), the source tree's
/// resources/ (build-tree runs), the configured install prefix's share/saltus.
std::vector<std::string> resource_directories();

/// Resolves a motion file's "model" field: a path relative to the motion file's folder if such a
/// file exists (or the value ends in ".json"), otherwise a name under resources/models/.
/// Returns "" when nothing is found; an entry that is not a regular file (a folder, a pipe) is
/// returned too, so that the reader says what it is.
std::string resolve_model_path(const std::string& model_field, const std::string& motion_file);

}  // namespace saltus
