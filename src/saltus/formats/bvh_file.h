#pragma once
/// @file
/// BVH (Biovision Hierarchy) text: reading into a MocapClip and writing one back. Tolerant of
/// what real files contain (CRLF line endings, tabs, joint names with spaces, "End Site" blocks,
/// any channel order, frames wrapped over several lines); strict about what would change the
/// motion (unknown keywords or channels, missing or extra numbers, non-finite values), with an
/// InputError naming the file and the line. Bounded like the JSON readers: a regular file of at
/// most kMaxBvhFileBytes, the limits below checked as they are read (docs/motion-capture.md).

#include <cstddef>
#include <string>

#include "saltus/capture/mocap_clip.h"
#include "saltus/formats/output_kind.h"

namespace saltus {

/// The largest BVH file read: a 5-minute capture of a 60-joint skeleton at 120 Hz is 20 MB.
inline constexpr std::size_t kMaxBvhFileBytes = 64u * 1024u * 1024u;
/// The most joints (ROOT, JOINT) in a skeleton: a body has a few dozen, a few hundred with
/// fingers and face.
inline constexpr int kMaxBvhJoints = 1000;
/// The deepest nesting of joints: a finger tip is about 10-30 joints below the root.
inline constexpr int kMaxBvhDepth = 256;
/// The most channels (columns of a frame) in a skeleton.
inline constexpr int kMaxBvhChannels = 1000;
/// The most frames ("Frames:"): 14 minutes at 120 Hz.
inline constexpr int kMaxBvhFrames = 100000;

/// Where some fields were read (1-based lines), for messages about their values later.
struct BvhSourceLines {
  int skeleton = 0;    ///< the ROOT joint (the skeleton's first line)
  int motion = 0;      ///< the MOTION keyword (the frames' first line)
  int frames = 0;      ///< the "Frames:" count
  int frame_time = 0;  ///< the "Frame Time:" value
};

/// Parses BVH text. `file` is used in messages: "<file>: line <n>: <problem>". `lines`, if
/// given, receives where fields were read.
MocapClip parse_bvh(const std::string& text, const std::string& file,
                    BvhSourceLines* lines = nullptr);

/// Reads and parses a BVH file: InputError if it cannot be read, is not a regular file (a
/// device, a pipe: opened without waiting, then refused) or is larger than kMaxBvhFileBytes.
MocapClip load_bvh_file(const std::string& path, BvhSourceLines* lines = nullptr);

/// BVH text of a clip: tab-indented hierarchy, then one line per frame. Numbers are written in
/// the shortest form that reads back to the same double, so parse_bvh(bvh_text(c)) == c.
/// Throws std::invalid_argument if the clip is not valid (validate_clip).
std::string bvh_text(const MocapClip& clip);

/// A BVH file as Saltus writes it (output_kind.h): the format has no room for a mark, so Saltus
/// cannot tell its own from a user's and never replaces one.
const FileKind& bvh_file_kind();

/// Writes bvh_text(clip) as the new file `path` (write_output_file with bvh_file_kind(): never
/// over an existing file, complete or absent at every instant). Throws InputError if `path` exists,
/// OutputError if the system refuses.
void save_bvh_file(const std::string& path, const MocapClip& clip);

}  // namespace saltus
