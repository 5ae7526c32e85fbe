#include "saltus/formats/bvh_file.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "saltus/base/input_error.h"
#include "saltus/formats/output_folder.h"

namespace saltus {

namespace {

struct Token {
  std::string text;
  int line = 0;
};

/// The text split into whitespace-separated tokens per line (CR, tabs and spaces alike).
std::vector<std::vector<Token>> tokenize_lines(const std::string& text) {
  std::vector<std::vector<Token>> lines;
  std::vector<Token> current;
  std::string word;
  int line = 1;
  auto flush_word = [&]() {
    if (!word.empty()) current.push_back({word, line}), word.clear();
  };
  for (char c : text) {
    if (c == '\n') {
      flush_word();
      lines.push_back(std::move(current));
      current.clear();
      ++line;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      flush_word();
    } else {
      word.push_back(c);
    }
  }
  flush_word();
  lines.push_back(std::move(current));
  return lines;
}

class Parser {
 public:
  Parser(const std::string& text, std::string file) : file_(std::move(file)) {
    lines_ = tokenize_lines(text);
  }

  MocapClip parse() {
    expect_keyword("HIERARCHY");
    MocapClip clip;
    const Token root = next("ROOT");
    if (root.text != "ROOT") fail(root.line, "expected ROOT, found \"" + root.text + "\"");
    parse_joint(clip, -1, root.line);
    const Token after = next("MOTION");
    if (after.text == "ROOT")
      fail(after.line, "a second ROOT: only one skeleton per file is supported");
    if (after.text != "MOTION") fail(after.line, "expected MOTION, found \"" + after.text + "\"");
    parse_motion(clip);
    return clip;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw InputError(file_, "line " + std::to_string(line), problem);
  }

  bool at_end() {
    skip_empty_lines();
    return line_index_ >= lines_.size();
  }

  void skip_empty_lines() {
    while (line_index_ < lines_.size() && token_index_ >= lines_[line_index_].size()) {
      ++line_index_;
      token_index_ = 0;
    }
  }

  int last_line() const { return static_cast<int>(lines_.size()); }

  Token next(const std::string& expected) {
    if (at_end()) fail(last_line(), "the file ends where " + expected + " was expected");
    return lines_[line_index_][token_index_++];
  }

  /// The rest of the current line (a joint name may contain spaces), without a trailing "{".
  std::string rest_of_line(int line) {
    std::string out;
    if (line_index_ < lines_.size()) {
      auto& tokens = lines_[line_index_];
      while (token_index_ < tokens.size() && tokens[token_index_].text != "{") {
        out += (out.empty() ? "" : " ") + tokens[token_index_].text;
        ++token_index_;
      }
    }
    if (out.empty()) fail(line, "a joint without a name");
    return out;
  }

  void expect_keyword(const std::string& keyword) {
    const Token t = next(keyword);
    if (t.text != keyword) fail(t.line, "expected \"" + keyword + "\", found \"" + t.text + "\"");
  }

  double number(const std::string& what) {
    const Token t = next(what);
    return to_number(t, what);
  }

  double to_number(const Token& t, const std::string& what) const {
    const char* begin = t.text.c_str();
    char* end = nullptr;
    const double v = std::strtod(begin, &end);
    if (end == begin || *end != '\0')
      fail(t.line, "expected a number (" + what + "), found \"" + t.text + "\"");
    if (!std::isfinite(v)) fail(t.line, what + " is not finite: \"" + t.text + "\"");
    return v;
  }

  Eigen::Vector3d parse_offset(const std::string& whose) {
    expect_keyword("OFFSET");
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i)
      v[i] = number("OFFSET of " + whose);
    return v;
  }

  static bool channel_from_name(const std::string& name, MocapChannel& out) {
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

  void parse_channels(MocapJoint& joint) {
    const Token count_token = next("CHANNELS");
    if (count_token.text != "CHANNELS")
      fail(count_token.line,
           "expected CHANNELS of joint \"" + joint.name + "\", found \"" + count_token.text + "\"");
    const Token n_token = next("the channel count");
    const double n = to_number(n_token, "channel count");
    if (n < 0 || n > 6 || n != std::floor(n))
      fail(n_token.line,
           "joint \"" + joint.name + "\": the channel count must be 0 to 6, found " + n_token.text);
    bool seen[6] = {false, false, false, false, false, false};
    for (int i = 0; i < static_cast<int>(n); ++i) {
      const Token c = next("a channel name");
      MocapChannel channel;
      if (!channel_from_name(c.text, channel))
        fail(c.line, "joint \"" + joint.name + "\": unknown channel \"" + c.text +
                         "\" (expected Xposition, Yposition, Zposition, Xrotation, Yrotation or "
                         "Zrotation)");
      if (seen[static_cast<int>(channel)])
        fail(c.line, "joint \"" + joint.name + "\": channel " + c.text + " appears twice");
      seen[static_cast<int>(channel)] = true;
      joint.channels.push_back(channel);
    }
  }

  /// JOINT/ROOT block after its keyword. Appends the joint and its subtree depth-first.
  void parse_joint(MocapClip& clip, int parent, int line) {
    MocapJoint joint;
    joint.name = rest_of_line(line);
    if (clip.joint_index(joint.name) >= 0)
      fail(line, "joint name \"" + joint.name + "\" is used twice");
    joint.parent = parent;
    expect_keyword("{");
    joint.offset = parse_offset("joint \"" + joint.name + "\"");
    parse_channels(joint);
    joint.first_column = clip.column_count();
    const int index = clip.joint_count();
    clip.joints.push_back(joint);
    for (;;) {
      const Token t = next("}");
      if (t.text == "}") return;
      if (t.text == "JOINT") {
        parse_joint(clip, index, t.line);
      } else if (t.text == "End") {
        const Token site = next("Site");
        if (site.text != "Site") fail(site.line, "expected \"End Site\"");
        expect_keyword("{");
        clip.joints[index].end_sites.push_back(
            parse_offset("the End Site of \"" + clip.joints[index].name + "\""));
        expect_keyword("}");
      } else {
        fail(t.line, "expected JOINT, End Site or } in joint \"" + clip.joints[index].name +
                         "\", found \"" + t.text + "\"");
      }
    }
  }

  void parse_motion(MocapClip& clip) {
    const Token frames_token = next("Frames:");
    if (frames_token.text != "Frames:")
      fail(frames_token.line, "expected \"Frames:\", found \"" + frames_token.text + "\"");
    const Token count_token = next("the frame count");
    const double count = to_number(count_token, "frame count");
    if (count < 1 || count != std::floor(count) || count > 1e8)
      fail(count_token.line,
           "the frame count must be a whole number >= 1, found " + count_token.text);
    const Token frame_token = next("Frame Time:");
    const Token time_token = next("Frame Time:");
    if (frame_token.text != "Frame" || time_token.text != "Time:")
      fail(frame_token.line,
           "expected \"Frame Time:\", found \"" + frame_token.text + " " + time_token.text + "\"");
    const Token dt_token = next("the frame time");
    clip.frame_time = to_number(dt_token, "frame time");
    if (!(clip.frame_time > 0))
      fail(dt_token.line, "the frame time must be > 0 s, found " + dt_token.text);
    // The frame data: usually one line per frame (then a line with another count is reported as
    // such), but some writers wrap a frame over several lines; then the numbers are a stream.
    const std::size_t columns = static_cast<std::size_t>(clip.column_count());
    const std::size_t expected = static_cast<std::size_t>(count);
    std::vector<double> row;
    row.reserve(columns);
    bool one_line_per_frame = true;
    bool first_data_line = true;
    for (std::size_t start = token_index_; line_index_ < lines_.size(); ++line_index_, start = 0) {
      const std::vector<Token>& tokens = lines_[line_index_];
      if (start >= tokens.size()) continue;
      if (first_data_line) one_line_per_frame = tokens.size() - start == columns;
      first_data_line = false;
      // A line longer than a frame is never a wrapped frame.
      if ((one_line_per_frame || tokens.size() - start > columns) &&
          tokens.size() - start != columns)
        fail(tokens[start].line, "frame " + std::to_string(clip.frames.size()) + " has " +
                                     std::to_string(tokens.size() - start) + " values, expected " +
                                     std::to_string(columns) + " (one per channel)");
      for (std::size_t k = start; k < tokens.size(); ++k) {
        const Token& t = tokens[k];
        if (clip.frames.size() == expected)
          fail(t.line, "more frame data than \"Frames: " + count_token.text + "\" announces");
        row.push_back(to_number(t, "frame " + std::to_string(clip.frames.size()) + " value " +
                                       std::to_string(row.size() + 1)));
        if (row.size() == columns) {
          clip.frames.push_back(row);
          row.clear();
        }
      }
    }
    if (!row.empty())
      fail(last_line(), "the last frame has " + std::to_string(row.size()) + " values, expected " +
                            std::to_string(columns));
    if (columns == 0)
      clip.frames.assign(expected, {});  // a skeleton without channels: rest pose frames
    if (clip.frames.size() != expected)
      fail(last_line(), "the file ends after " + std::to_string(clip.frames.size()) +
                            " frames; \"Frames: " + count_token.text + "\" announces " +
                            std::to_string(expected));
  }

  std::string file_;
  std::vector<std::vector<Token>> lines_;
  std::size_t line_index_ = 0;
  std::size_t token_index_ = 0;
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

MocapClip parse_bvh(const std::string& text, const std::string& file) {
  MocapClip clip = Parser(text, file).parse();
  try {
    validate_clip(clip);
  } catch (const std::invalid_argument& e) {
    throw InputError(file, "", e.what());
  }
  return clip;
}

MocapClip load_bvh_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (!in && !in.eof()) throw InputError(path, "", "cannot read the file");
  return parse_bvh(buffer.str(), path);
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

void save_bvh_file(const std::string& path, const MocapClip& clip) {
  write_new_file(path, bvh_text(clip));
}

}  // namespace saltus
