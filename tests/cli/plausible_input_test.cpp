// Validation that knows physics (issue 16, items 4-7): every absurd or malformed input the
// issue measured ends with exit status 2, one line naming the file and the field, nothing left
// behind; nothing is read that a motion file should not make Saltus read.

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>

#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;
using test::names_in;
using test::read_json;
using test::run_cli;
using test::TempDir;

/// How to spoil M1 (and the model beside it), and what the message must name.
struct Absurd {
  const char* name;
  std::function<void(nlohmann::json& motion, nlohmann::json& model)> spoil;
  std::vector<std::string> message_parts;
  /// Applied to the motion file's text after dumping (duplicate keys, 1e400).
  std::function<std::string(std::string)> edit_text = nullptr;
};

void PrintTo(const Absurd& input, std::ostream* os) {
  *os << input.name;
}

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

class CliAbsurdInput : public ::testing::TestWithParam<Absurd> {};

TEST_P(CliAbsurdInput, ExitsWithTwoNamingFileAndFieldLeavesNothing) {
  TempDir dir;
  nlohmann::json motion = read_json(test::m1_path());
  nlohmann::json model =
      read_json(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
  motion["model"] = "my-model.json";
  GetParam().spoil(motion, model);
  std::string text = motion.dump(1);
  if (GetParam().edit_text) text = GetParam().edit_text(text);
  test::write_text(dir / "bad.motion.json", text);
  test::write_text(dir / "my-model.json", model.dump(1));
  for (const char* verb : {"evaluate", "simulate"}) {
    const auto run =
        run_cli(std::string(verb) + " " + (dir / "bad.motion.json") + " --out " + (dir / "out"));
    EXPECT_EQ(run.status, 2) << verb << ": " << run.output;
    for (const std::string& part : GetParam().message_parts)
      EXPECT_NE(run.output.find(part), std::string::npos)
          << verb << ": expected \"" << part << "\" in: " << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"bad.motion.json", "my-model.json"}));
  }
}

const auto kSegment4 = [](nlohmann::json& model) -> nlohmann::json& {
  return model["segments"][4];
};

INSTANTIATE_TEST_SUITE_P(
    Issue16, CliAbsurdInput,
    ::testing::Values(
        // Item 4: absurd numbers that became NaN results with exit 0.
        Absurd{"takeoff_speed",
               [](auto& m, auto&) {
                 m["takeoff"]["com_velocity"] = {0, -1e308, 0};
               },
               {"bad.motion.json", "/takeoff/com_velocity/1", "m/s"}},
        Absurd{"takeoff_position",
               [](auto& m, auto&) { m["takeoff"]["com_position"][0] = 1e308; },
               {"bad.motion.json", "/takeoff/com_position/0", "plausible"}},
        Absurd{"segment_mass_huge",
               [](auto&, auto& model) { kSegment4(model)["mass"] = 1e308; },
               {"my-model.json", "/segments/4/mass", "kg"}},
        Absurd{"segment_inertia_huge",
               [](auto&, auto& model) {
                 kSegment4(model)["inertia"] = {1e308, 1e308, 1e308};
               },
               {"my-model.json", "/segments/4/inertia", "radius of gyration"}},
        Absurd{"segment_offset_huge",
               [](auto&, auto& model) {
                 kSegment4(model)["com"] = {0, 1e308, 0};
               },
               {"my-model.json", "/segments/4/com/1"}},
        Absurd{"angular_momentum",
               [](auto& m, auto&) {
                 m["takeoff"]["angular_momentum"] = {1e4, 1e4, 1e4};
               },
               {"bad.motion.json", "/takeoff/angular_momentum", "rad/s"}},
        Absurd{"keyframe_at_1e-9",
               [](auto& m, auto&) { m["keyframes"][1]["time"] = 1e-9; },
               {"bad.motion.json", "/keyframes/1/time", "apart"}},
        Absurd{"flight_of_2.2e8_s",
               [](auto& m, auto&) { m["keyframes"][4]["time"] = 2.2e8; },
               {"bad.motion.json", "/keyframes/4/time", "flight"}},
        // Item 5: accepted where it should have been refused.
        Absurd{"duplicate_joint",
               [](auto&, auto&) {},
               {"bad.motion.json", "/keyframes/1/rotations/knee_l", "twice"},
               [](std::string text) {
                 // The second keyframe's knee_l given twice (the last used to win). Keys are
                 // written sorted, so keyframe 1's rotations follow keyframe 0's "time".
                 const auto knee = text.find("\"knee_l\":", text.find("\"time\""));
                 return text.substr(0, knee) + "\"knee_l\": [1, 0, 0, 0], " + text.substr(knee);
               }},
        Absurd{"duplicate_format",
               [](auto&, auto&) {},
               {"bad.motion.json", "/format", "twice"},
               [](std::string text) {
                 return replace_once(text, "{", "{\"format\": \"saltus-motion/1\",");
               }},
        Absurd{"misspelled_top_level_key",
               [](auto& m, auto&) {
                 m["tolerence"] = m["tolerances"];
                 m.erase("tolerances");
               },
               {"bad.motion.json", "/tolerence", "did you mean \"tolerances\""}},
        Absurd{"unknown_model_field",
               [](auto&, auto& model) { model["segments"][3]["mas"] = 1.9; },
               {"my-model.json", "/segments/3/mas", "did you mean \"mass\""}},
        Absurd{"inertia_violates_triangle_inequality",
               [](auto&, auto& model) {
                 kSegment4(model)["inertia"] = {0.01, 0.01, 1.0};
               },
               {"my-model.json", "/segments/4/inertia", "triangle inequality"}},
        Absurd{"mass_1e-320",
               [](auto&, auto& model) { kSegment4(model)["mass"] = 1e-320; },
               {"my-model.json", "/segments/4/mass"}},
        // Item 6: wrong exit class, or no file and field.
        Absurd{"number_overflow",
               [](auto&, auto&) {},
               {"bad.motion.json", "/takeoff/com_position/0", "1e400", "out of range"},
               [](std::string text) {
                 const auto at = text.find("[", text.find("\"com_position\""));
                 return text.substr(0, at + 1) + "1e400" + text.substr(text.find(",", at));
               }},
        Absurd{"last_keyframe_at_1e308",
               [](auto& m, auto&) { m["keyframes"][4]["time"] = 1e308; },
               {"bad.motion.json", "/keyframes/4/time"}},
        Absurd{"model_name_of_5000_characters",
               [](auto& m, auto&) { m["model"] = std::string(5000, 'm'); },
               {"bad.motion.json", "/model", "bytes"}},
        Absurd{"ill_formed_utf8",
               [](auto&, auto&) {},
               {"bad.motion.json", "invalid JSON", "UTF-8"},
               [](std::string text) { return replace_once(text, "M1 straight", "M1 \xC3\x28"); }},
        // Item 7: files a motion file must not make Saltus read.
        Absurd{"model_outside_the_motion_folder",
               [](auto& m, auto&) { m["model"] = "../../../../../../../../etc/passwd"; },
               {"bad.motion.json", "/model", "outside the motion file's folder", "--model"}},
        Absurd{"absolute_model_path",
               [](auto& m, auto&) { m["model"] = "/etc/passwd"; },
               {"bad.motion.json", "/model", "absolute", "--model"}}),
    [](const ::testing::TestParamInfo<Absurd>& param_info) {
      std::string name = param_info.param.name;
      std::replace(name.begin(), name.end(), '.', '_');
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

TEST(CliPlausibleInput, PasswdIsNeverParsed) {
  // Its field names appeared in the error: the file had been opened and parsed.
  TempDir dir;
  nlohmann::json motion = read_json(test::m1_path());
  motion["model"] = "../../../../../../../../etc/passwd";
  test::write_text(dir / "m.motion.json", motion.dump());
  const auto run = run_cli("evaluate " + (dir / "m.motion.json") + " --out " + (dir / "o"));
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.output.find("invalid JSON"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("root:"), std::string::npos) << run.output;
}

TEST(CliPlausibleInput, AModelBesideOrBelowTheMotionIsUsedAndAnyModelThroughDashDashModel) {
  TempDir dir;
  fs::create_directories(dir.path() / "motions/models");
  fs::copy_file(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json",
                dir / "motions/models/athlete.json");
  fs::copy_file(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json",
                dir / "elsewhere.json");
  nlohmann::json motion = read_json(test::m1_path());
  motion["model"] = "models/athlete.json";
  test::write_text(dir / "motions/m.motion.json", motion.dump());
  EXPECT_EQ(run_cli("evaluate " + (dir / "motions/m.motion.json") + " --out " + (dir / "a") + " -q")
                .status,
            0);
  motion["model"] = "../elsewhere.json";
  test::write_text(dir / "motions/m.motion.json", motion.dump());
  const auto refused =
      run_cli("evaluate " + (dir / "motions/m.motion.json") + " --out " + (dir / "b") + " -q");
  EXPECT_EQ(refused.status, 2) << refused.output;
  // A link inside the folder that leads outside it is outside too.
  fs::create_symlink(dir / "elsewhere.json", dir / "motions/link.json");
  motion["model"] = "link.json";
  test::write_text(dir / "motions/m.motion.json", motion.dump());
  EXPECT_EQ(run_cli("evaluate " + (dir / "motions/m.motion.json") + " --out " + (dir / "b") + " -q")
                .status,
            2);
  // The person running Saltus may name any model.
  EXPECT_EQ(run_cli("evaluate " + (dir / "motions/m.motion.json") + " --model " +
                    (dir / "elsewhere.json") + " --out " + (dir / "c") + " -q")
                .status,
            0);
}

TEST(CliPlausibleInput, FilesThatAreNotMotionFilesAreRefusedQuickly) {
  // Item 7: `saltus evaluate /dev/zero` read until memory ran out.
  TempDir dir;
  const auto start = std::chrono::steady_clock::now();
  const auto zero = run_cli("evaluate /dev/zero --out " + (dir / "o"));
  EXPECT_EQ(zero.status, 2) << zero.output;
  EXPECT_NE(zero.output.find("/dev/zero: is not a regular file"), std::string::npos) << zero.output;
  const auto folder = run_cli("evaluate " + dir.path().string() + " --out " + (dir / "o"));
  EXPECT_EQ(folder.status, 2) << folder.output;
  // Larger than any motion file (sparse: no disk space used).
  const std::string big = dir / "big.motion.json";
  { std::ofstream(big) << "{}"; }
  fs::resize_file(big, 65u * 1024u * 1024u);
  const auto oversized = run_cli("evaluate " + big + " --out " + (dir / "o"));
  EXPECT_EQ(oversized.status, 2) << oversized.output;
  EXPECT_NE(oversized.output.find("at most 64 MiB"), std::string::npos) << oversized.output;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20);
  EXPECT_FALSE(fs::exists(dir / "o"));
}

TEST(CliPlausibleInput, AFileNameThatIsNotUtf8IsBadInput) {
  // Item 6: exit 1 (the name went into result.json, which must be UTF-8).
  TempDir dir;
  const std::string name = dir / "m\xFF.motion.json";
  fs::copy_file(test::m1_path(), name);
  const auto run = run_cli("evaluate '" + name + "' --out " + (dir / "o"));
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("m\\xFF.motion.json"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("not valid UTF-8"), std::string::npos) << run.output;
}

TEST(CliPlausibleInput, AStoredSplineIsCheckedAgainstItsKeyframes) {
  // Item 4: sign-flipped controls or knots of 1e-320 printed NaN with exit 0.
  TempDir dir;
  const auto optimized = run_cli("optimize " + test::m1_path() + " --out " + (dir / "opt") +
                                 " --max-iter 3 --samples 31 -q");
  ASSERT_TRUE(optimized.status == 0 || optimized.status == 3) << optimized.output;
  const nlohmann::json good = read_json(dir / "opt/optimized.motion.json");
  fs::copy_file(dir / "opt/model.json", dir / "model.json");
  const auto check = [&](const std::function<void(nlohmann::json&)>& spoil,
                         const std::vector<std::string>& parts) {
    nlohmann::json motion = good;
    spoil(motion);
    test::write_text(dir / "m.motion.json", motion.dump());
    const auto run = run_cli("evaluate " + (dir / "m.motion.json") + " --out " + (dir / "o"));
    EXPECT_EQ(run.status, 2) << run.output;
    for (const std::string& part : parts)
      EXPECT_NE(run.output.find(part), std::string::npos) << part << " in " << run.output;
    EXPECT_FALSE(fs::exists(dir / "o"));
  };
  ASSERT_EQ(
      run_cli("evaluate " + (dir / "opt/optimized.motion.json") + " --out " + (dir / "o") + " -q")
          .status,
      0);
  fs::remove_all(dir / "o");
  const std::size_t controls = good["spline"]["knots"].size() - 4;
  const auto dot = [](const nlohmann::json& a, const nlohmann::json& b) {
    double sum = 0;
    for (std::size_t k = 0; k < 4; ++k)
      sum += a[k].get<double>() * b[k].get<double>();
    return sum;
  };
  // Every control of every joint that turns the short way to its neighbours, negated (the same
  // rotation, another curve: it now turns the long way round on both sides). Such a file is
  // refused naming the control, unless the new curve still meets every keyframe within its
  // tolerance: then it is a motion like any other, and its figures must be finite.
  int refused = 0, flips = 0;
  for (const auto& [joint, curve] : good["spline"]["joints"].items()) {
    for (std::size_t i = 0; i < controls; ++i) {
      if ((i > 0 && dot(curve[i - 1], curve[i]) < 0) ||
          (i + 1 < controls && dot(curve[i], curve[i + 1]) < 0))
        continue;
      nlohmann::json motion = good;
      for (auto& c : motion["spline"]["joints"][joint][i])
        c = -c.get<double>();
      test::write_text(dir / "m.motion.json", motion.dump());
      const auto run = run_cli("evaluate " + (dir / "m.motion.json") + " --out " + (dir / "o"));
      ++flips;
      if (run.status == 2) {
        ++refused;
        EXPECT_NE(run.output.find("m.motion.json"), std::string::npos) << run.output;
        EXPECT_NE(run.output.find("/spline/joints/" + joint + "/"), std::string::npos)
            << run.output;
        EXPECT_FALSE(fs::exists(dir / "o"));
        continue;
      }
      ASSERT_EQ(run.status, 0) << run.output;
      const nlohmann::json result = read_json(dir / "o/result.json");
      EXPECT_TRUE(std::isfinite(result["before"]["avg_root_force"].get<double>())) << joint << i;
      EXPECT_LE(result["max_quaternion_error"].get<double>(), 0.05 + 1e-4) << joint << i;
      fs::remove_all(dir / "o");
    }
  }
  EXPECT_GT(refused, flips / 2) << refused << " of " << flips << " flipped controls refused";
  check([](nlohmann::json& m) { m["spline"]["knots"][5] = 1e-320; },
        {"m.motion.json", "/spline/knots/"});
  check(
      [](nlohmann::json& m) {
        for (auto& k : m["spline"]["knots"])
          k = 1e-320;
      },
      {"m.motion.json", "/spline/knots/"});
  // Knots that end before the last keyframe (the spline used to be evaluated clamped).
  check(
      [](nlohmann::json& m) {
        auto& knots = m["spline"]["knots"];
        for (std::size_t i = knots.size() - 4; i < knots.size(); ++i)
          knots[i] = knots[i].get<double>() * 0.9;
      },
      {"m.motion.json", "/spline/knots/", "flight time"});
}

}  // namespace
}  // namespace saltus

namespace saltus {
namespace {

/// One refusal of a flag or file: the command (after `saltus`), what the one line must hold.
struct FlagRefusal {
  std::string command;
  std::string message;
};

TEST(CliPlausibleInput, EmptyNumbersZeroRatesAndFilesThatAreNoFilesAreNamedForWhatTheyAre) {
  TempDir dir;
  const std::string m2 =
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M2-tucked-back-somersault.motion.json";
  fs::create_directories(dir / "folder.json");
  ASSERT_EQ(::mkfifo((dir / "pipe.json").c_str(), 0644), 0);
  const std::string out = " --out " + (dir / "out");
  const std::vector<FlagRefusal> refusals = {
      // CLI11 read "" as 0: a height of 0 m, no what-if change at all.
      {"model new --height '' --mass 60 --sex male --out " + (dir / "a.model.json"),
       "--height: is empty"},
      {"analyse what-if " + m2 + " --open-later ''" + out, "--open-later: is empty"},
      // 0 frames per second was the default rate.
      {"export " + m2 + " --format bvh --fps 0 --out " + (dir / "a.bvh"),
       "--fps: 0 fps is outside (0, ∞) fps"},
      {"analyse what-if " + m2 + " --open-later 1e308" + out, "--open-later: The opening can move"},
      // "no such model file" for what is a folder or a pipe.
      {"evaluate " + m2 + " --model " + (dir / "folder.json") + out, "is a folder, not a file"},
      {"model info " + (dir / "folder.json"), "is a folder, not a file"},
      {"model scale " + (dir / "pipe.json") + " --height 1.7 --mass 60 --out " +
           (dir / "b.model.json"),
       "pipe.json: is not a regular file"},
  };
  for (const FlagRefusal& r : refusals) {
    const auto run = run_cli(r.command);
    EXPECT_EQ(run.status, 2) << r.command << "\n" << run.output;
    EXPECT_NE(run.output.find(r.message), std::string::npos) << r.command << "\n" << run.output;
    EXPECT_LT(run.output.size(), 400u) << "short numbers (once 300 digits): " << run.output;
  }
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"folder.json", "pipe.json"}));
}

}  // namespace
}  // namespace saltus
