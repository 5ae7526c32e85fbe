#pragma once
/// @file
/// BVH (Biovision Hierarchy) text: reading into a MocapClip and writing one back. Tolerant of
/// what real files contain (CRLF line endings, tabs, joint names with spaces, "End Site" blocks,
/// any channel order, frames wrapped over several lines); strict about what would change the
/// motion (unknown keywords or channels, missing or extra numbers, non-finite values), with an
/// InputError naming the file and the line.

#include <string>

#include "saltus/capture/mocap_clip.h"

namespace saltus {

/// Parses BVH text. `file` is used in messages: "<file>: line <n>: <problem>".
MocapClip parse_bvh(const std::string& text, const std::string& file);

/// Reads and parses a BVH file (InputError if it cannot be read).
MocapClip load_bvh_file(const std::string& path);

/// BVH text of a clip: tab-indented hierarchy, then one line per frame. Numbers are written in
/// the shortest form that reads back to the same double, so parse_bvh(bvh_text(c)) == c.
/// Throws std::invalid_argument if the clip is not valid (validate_clip).
std::string bvh_text(const MocapClip& clip);

/// Writes bvh_text(clip) as the new file `path` (write_new_file: never over an existing file,
/// complete or absent at every instant). Throws InputError if `path` exists, OutputError if the
/// system refuses.
void save_bvh_file(const std::string& path, const MocapClip& clip);

}  // namespace saltus
