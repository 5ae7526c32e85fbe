#include "saltus/formats/bvh_file.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "saltus/base/input_error.h"
#include "saltus/base/input_file.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/output_folder.h"

namespace saltus {

namespace {

/// One whitespace-separated word of the text (a view into it) and its line.
struct Token {
  std::string_view text;
  int line = 0;
};

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// A quoted word of the file for a message: control characters escaped, length capped.
std::string quote_word(std::string_view text) {
  return "\"" + message_text(std::string(text)) + "\"";
}

/// Reads the text word by word, in place: a 64 MiB capture is not copied into millions of
/// strings (the tokens of a 100 MB file once took 8.6 GB). The hierarchy is parsed with an
/// explicit stack of open joints, so its depth is bounded by kMaxBvhDepth, not by the C++ stack.
class Parser {
 public:
  Parser(const std::string& text, std::string file) : text_(text), file_(std::move(file)) {}

  MocapClip parse(BvhSourceLines* lines) {
    expect_keyword("HIERARCHY");
    MocapClip clip;
    const Token root = next("ROOT");
    if (root.text != "ROOT") fail(root.line, "expected ROOT, found " + quote_word(root.text));
    parse_hierarchy(clip, root.line);
    const Token after = next("MOTION");
    if (after.text == "ROOT")
      fail(after.line, "a second ROOT: only one skeleton per file is supported");
    if (after.text != "MOTION")
      fail(after.line, "expected MOTION, found " + quote_word(after.text));
    if (lines) {
      lines->skeleton = root.line;
      lines->motion = after.line;
    }
    parse_motion(clip, lines);
    return clip;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw InputError(file_, "line " + std::to_string(line), problem);
  }

  /// Skips blanks and line ends; false at the end of the text.
  bool skip_space() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
      } else if (!is_blank(c)) {
        return true;
      }
      ++pos_;
    }
    return false;
  }

  /// Skips blanks on the current line; false at its end (or the text's).
  bool skip_blanks_on_line() {
    while (pos_ < text_.size() && is_blank(text_[pos_]))
      ++pos_;
    return pos_ < text_.size() && text_[pos_] != '\n';
  }

  /// The word at pos_ (which is not blank).
  Token word() {
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n' && !is_blank(text_[pos_]))
      ++pos_;
    return {std::string_view(text_).substr(begin, pos_ - begin), line_};
  }

  Token next(const std::string& expected) {
    if (!skip_space()) fail(line_, "the file ends where " + expected + " was expected");
    return word();
  }

  /// The rest of the current line (a joint name may contain spaces), without a trailing "{".
  std::string rest_of_line(int line) {
    std::string out;
    while (skip_blanks_on_line()) {
      const std::size_t mark = pos_;
      const Token t = word();
      if (t.text == "{") {
        pos_ = mark;  // read again by expect_keyword
        break;
      }
      if (!out.empty()) out += ' ';
      out += t.text;
    }
    if (out.empty()) fail(line, "a joint without a name");
    return out;
  }

  void expect_keyword(const std::string& keyword) {
    const Token t = next(keyword);
    if (t.text != keyword)
      fail(t.line, "expected \"" + keyword + "\", found " + quote_word(t.text));
  }

  double number(const std::string& what) {
    const Token t = next(what);
    return to_number(t, what);
  }

  double to_number(const Token& t, const std::string& what) const {
    char buffer[64];
    std::string long_token;
    const char* begin = buffer;
    if (t.text.size() < sizeof buffer) {
      t.text.copy(buffer, t.text.size());
      buffer[t.text.size()] = '\0';
    } else {
      long_token = std::string(t.text);
      begin = long_token.c_str();
    }
    char* end = nullptr;
    const double v = std::strtod(begin, &end);
    if (end == begin || *end != '\0')
      fail(t.line, "expected a number (" + what + "), found " + quote_word(t.text));
    if (!std::isfinite(v)) fail(t.line, what + " is not finite: " + quote_word(t.text));
    return v;
  }

  Eigen::Vector3d parse_offset(const std::string& whose) {
    expect_keyword("OFFSET");
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i)
      v[i] = number("OFFSET of " + whose);
    return v;
  }

  static bool channel_from_name(std::string_view name, MocapChannel& out) {
    static const std::map<std::string, MocapChannel> kNames{
        {"xposition", MocapChannel::kXposition}, {"yposition", MocapChannel::kYposition},
        {"zposition", MocapChannel::kZposition}, {"xrotation", MocapChannel::kXrotation},
        {"yrotation", MocapChannel::kYrotation}, {"zrotation", MocapChannel::kZrotation}};
    std::string lower;
    for (char c : name)
      lower.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    auto it = kNames.find(lower);
    if (it == kNames.end()) return false;
    out = it->second;
    return true;
  }

  void parse_channels(MocapJoint& joint, int columns_so_far) {
    const std::string whose = "joint " + quote_word(joint.name);
    const Token count_token = next("CHANNELS");
    if (count_token.text != "CHANNELS")
      fail(count_token.line,
           "expected CHANNELS of " + whose + ", found " + quote_word(count_token.text));
    const Token n_token = next("the channel count");
    const double n = to_number(n_token, "channel count");
    if (n < 0 || n > 6 || n != std::floor(n))
      fail(n_token.line, whose + ": the channel count must be 0 to 6, found " +
                             message_text(std::string(n_token.text)));
    if (columns_so_far + static_cast<int>(n) > kMaxBvhChannels)
      fail(n_token.line, whose + ": more than " + std::to_string(kMaxBvhChannels) +
                             " channels in the skeleton, the most Saltus reads (a human skeleton "
                             "has a few hundred at most)");
    bool seen[6] = {false, false, false, false, false, false};
    for (int i = 0; i < static_cast<int>(n); ++i) {
      const Token c = next("a channel name");
      MocapChannel channel;
      if (!channel_from_name(c.text, channel))
        fail(c.line, whose + ": unknown channel " + quote_word(c.text) +
                         " (expected Xposition, Yposition, Zposition, Xrotation, Yrotation or "
                         "Zrotation)");
      if (seen[static_cast<int>(channel)])
        fail(c.line, whose + ": channel " + message_text(std::string(c.text)) + " appears twice");
      seen[static_cast<int>(channel)] = true;
      joint.channels.push_back(channel);
    }
  }

  /// A ROOT or JOINT block from its name to its channels; appends the joint, returns its index.
  int parse_joint_header(MocapClip& clip, int parent, int line) {
    if (clip.joint_count() >= kMaxBvhJoints)
      fail(line, "more than " + std::to_string(kMaxBvhJoints) +
                     " joints, the most Saltus reads (a human skeleton has a few dozen, a few "
                     "hundred with fingers and face)");
    MocapJoint joint;
    joint.name = rest_of_line(line);
    if (!names_.insert(joint.name).second)
      fail(line, "joint name " + quote_word(joint.name) + " is used twice");
    joint.parent = parent;
    expect_keyword("{");
    joint.offset = parse_offset("joint " + quote_word(joint.name));
    parse_channels(joint, clip.column_count());
    joint.first_column = clip.column_count();
    clip.joints.push_back(std::move(joint));
    return clip.joint_count() - 1;
  }

  /// The ROOT block (after its keyword) and every joint inside it, depth-first as in the file.
  void parse_hierarchy(MocapClip& clip, int root_line) {
    std::vector<int> open{parse_joint_header(clip, -1, root_line)};  // the open joints
    while (!open.empty()) {
      const int index = open.back();
      const Token t = next("}");
      if (t.text == "}") {
        open.pop_back();
      } else if (t.text == "JOINT") {
        if (static_cast<int>(open.size()) >= kMaxBvhDepth)
          fail(t.line, "the hierarchy is deeper than " + std::to_string(kMaxBvhDepth) +
                           " joints, the most Saltus reads (a human skeleton nests a few "
                           "dozen)");
        open.push_back(parse_joint_header(clip, index, t.line));
      } else if (t.text == "End") {
        const Token site = next("Site");
        if (site.text != "Site") fail(site.line, "expected \"End Site\"");
        expect_keyword("{");
        const Eigen::Vector3d offset =
            parse_offset("the End Site of " + quote_word(clip.joints[index].name));
        clip.joints[index].end_sites.push_back(offset);
        expect_keyword("}");
      } else {
        fail(t.line, "expected JOINT, End Site or } in joint " +
                         quote_word(clip.joints[index].name) + ", found " + quote_word(t.text));
      }
    }
  }

  void parse_motion(MocapClip& clip, BvhSourceLines* lines) {
    const Token frames_token = next("Frames:");
    if (frames_token.text != "Frames:")
      fail(frames_token.line, "expected \"Frames:\", found " + quote_word(frames_token.text));
    const Token count_token = next("the frame count");
    const double count = to_number(count_token, "frame count");
    const std::string count_text = message_text(std::string(count_token.text));
    if (count < 1 || count != std::floor(count))
      fail(count_token.line,
           "Frames: the frame count must be a whole number >= 1, found " + count_text);
    if (count > kMaxBvhFrames)
      fail(count_token.line, "Frames: " + count_text + " frames; Saltus reads at most " +
                                 std::to_string(kMaxBvhFrames) +
                                 " (14 minutes at 120 Hz; cut the clip around the flight)");
    const Token frame_token = next("Frame Time:");
    const Token time_token = next("Frame Time:");
    if (frame_token.text != "Frame" || time_token.text != "Time:")
      fail(frame_token.line,
           "expected \"Frame Time:\", found " +
               quote_word(std::string(frame_token.text) + " " + std::string(time_token.text)));
    const Token dt_token = next("the frame time");
    clip.frame_time = to_number(dt_token, "Frame Time");
    if (!(clip.frame_time > 0))
      fail(dt_token.line, "Frame Time: the frame time must be > 0 s, found " +
                              message_text(std::string(dt_token.text)));
    if (lines) {
      lines->frames = count_token.line;
      lines->frame_time = dt_token.line;
    }
    // The frame data: usually one line per frame (then a line with another count is reported as
    // such), but some writers wrap a frame over several lines; then the numbers are a stream.
    const std::size_t columns = static_cast<std::size_t>(clip.column_count());
    const std::size_t expected = static_cast<std::size_t>(count);
    clip.frames.reserve(std::min<std::size_t>(expected, text_.size() / (2 * columns + 1) + 1));
    std::vector<double> row;
    row.reserve(columns);
    bool one_line_per_frame = true;
    bool first_data_line = true;
    for (;;) {
      if (!skip_blanks_on_line()) {  // an empty line, or the end of one
        if (pos_ >= text_.size()) break;
        ++pos_;
        ++line_;
        continue;
      }
      // Count the words of this line first: a line of another length is reported as such.
      std::size_t words = 0;
      for (std::size_t i = pos_; i < text_.size() && text_[i] != '\n';) {
        while (i < text_.size() && is_blank(text_[i]))
          ++i;
        if (i >= text_.size() || text_[i] == '\n') break;
        ++words;
        while (i < text_.size() && text_[i] != '\n' && !is_blank(text_[i]))
          ++i;
      }
      if (first_data_line) one_line_per_frame = words == columns;
      first_data_line = false;
      // A line longer than a frame is never a wrapped frame.
      if ((one_line_per_frame || words > columns) && words != columns)
        fail(line_, "frame " + std::to_string(clip.frames.size()) + " has " +
                        std::to_string(words) + " values, expected " + std::to_string(columns) +
                        " (one per channel)");
      while (skip_blanks_on_line()) {
        const Token t = word();
        if (clip.frames.size() == expected)
          fail(t.line, "more frame data than \"Frames: " + count_text + "\" announces");
        row.push_back(to_number(t, "frame " + std::to_string(clip.frames.size()) + " value " +
                                       std::to_string(row.size() + 1)));
        if (row.size() == columns) {
          clip.frames.push_back(row);
          row.clear();
        }
      }
    }
    if (!row.empty())
      fail(line_, "the last frame has " + std::to_string(row.size()) + " values, expected " +
                      std::to_string(columns));
    if (columns == 0)
      clip.frames.assign(expected, {});  // a skeleton without channels: rest pose frames
    if (clip.frames.size() != expected)
      fail(line_, "the file ends after " + std::to_string(clip.frames.size()) +
                      " frames; \"Frames: " + count_text + "\" announces " +
                      std::to_string(expected));
  }

  const std::string& text_;
  std::string file_;
  std::size_t pos_ = 0;
  int line_ = 1;
  std::set<std::string> names_;  ///< joint names seen, to refuse a second use
};

void append_number(std::string& out, double v) {
  char buffer[32];
  if (v == 0.0) v = 0.0;  // no "-0"
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  out.append(buffer, end);
}

void append_vector(std::string& out, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) {
    out.push_back(' ');
    append_number(out, v[i]);
  }
}

void write_joint(std::string& out, const MocapClip& clip, int j, int depth) {
  const MocapJoint& joint = clip.joints[j];
  const std::string indent(depth, '\t');
  out += indent + (joint.parent < 0 ? "ROOT " : "JOINT ") + joint.name + "\n";
  out += indent + "{\n";
  out += indent + "\tOFFSET";
  append_vector(out, joint.offset);
  out += "\n" + indent + "\tCHANNELS " + std::to_string(joint.channels.size());
  for (MocapChannel c : joint.channels)
    out += std::string(" ") + mocap_channel_name(c);
  out += "\n";
  for (int child : clip.children(j))
    write_joint(out, clip, child, depth + 1);
  for (const Eigen::Vector3d& site : joint.end_sites) {
    out += indent + "\tEnd Site\n" + indent + "\t{\n" + indent + "\t\tOFFSET";
    append_vector(out, site);
    out += "\n" + indent + "\t}\n";
  }
  out += indent + "}\n";
}

}  // namespace

MocapClip parse_bvh(const std::string& text, const std::string& file, BvhSourceLines* lines) {
  MocapClip clip = Parser(text, file).parse(lines);
  try {
    validate_clip(clip);  // what the parser checked as it read: a failure here is a bug
  } catch (const std::invalid_argument& e) {
    throw std::logic_error(file + ": the BVH reader accepted an invalid clip: " + e.what());
  }
  return clip;
}

MocapClip load_bvh_file(const std::string& path, BvhSourceLines* lines) {
  return parse_bvh(read_input_file(path, kMaxBvhFileBytes, "BVH captures"), path, lines);
}

std::string bvh_text(const MocapClip& clip) {
  validate_clip(clip);
  std::string out = "HIERARCHY\n";
  write_joint(out, clip, 0, 0);
  out += "MOTION\nFrames: " + std::to_string(clip.frames.size()) + "\nFrame Time: ";
  append_number(out, clip.frame_time);
  out += "\n";
  for (const std::vector<double>& row : clip.frames) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i) out.push_back(' ');
      append_number(out, row[i]);
    }
    out += "\n";
  }
  return out;
}

const FileKind& bvh_file_kind() {
  static const FileKind kind = FileKind::unmarked("BVH capture");
  return kind;
}

void save_bvh_file(const std::string& path, const MocapClip& clip) {
  write_output_file(path, bvh_text(clip), bvh_file_kind());
}

}  // namespace saltus
