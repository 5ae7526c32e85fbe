/// Tests for motion files ("saltus-motion/1", docs/formats.md): parsing, defaults, normalisation,
/// the JSON round trip, and one test per kind of bad input. Every bad-input test starts from the
/// good document (which the GoodDocumentParses test proves valid), changes one thing, and checks
/// that the message names the file, the exact JSON pointer and the problem.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "saltus/base/input_error.h"
#include "saltus/base/resources.h"
#include "saltus/body/body_model.h"
#include "saltus/formats/motion_file.h"
#include "saltus/motion/motion.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFile = "test.motion.json";

/// A four-segment chain built in code so these tests do not depend on the bundled models.
BodyModel tiny_model() {
  BodyModel model;
  model.name = "tiny-4";
  const struct {
    const char* name;
    int parent;
    const char* joint;
    double mass;
  } parts[] = {{"abdomen", -1, "root", 10.0},
               {"pelvis", 0, "lumbar", 8.0},
               {"thigh_l", 1, "hip_l", 7.0},
               {"shank_l", 2, "knee_l", 3.0}};
  for (const auto& p : parts) {
    Segment s;
    s.name = p.name;
    s.parent = p.parent;
    s.joint = p.joint;
    s.mass = p.mass;
    s.inertia = Eigen::Vector3d(0.05, 0.02, 0.05).asDiagonal();
    model.segments.push_back(s);
  }
  return model;
}

/// A valid document using both rotation forms, root positions and a spline.
nlohmann::json good_motion_document() {
  return nlohmann::json::parse(R"({
    "format": "saltus-motion/1",
    "name": "test tuck",
    "model": "tiny-4",
    "description": "free text for people, kept and written back",
    "takeoff": { "com_position": [0, 1, 0], "com_velocity": [0.15, 10.0, 0.15],
                 "angular_momentum": [-40, 0, 0] },
    "tolerances": { "translation_m": 0.2, "quaternion": 0.04 },
    "keyframes": [
      { "time": 0.0,
        "rotations": { "root": [1, 0, 0, 0], "lumbar": [1, 0, 0, 0],
                       "hip_l": [1, 0, 0, 0], "knee_l": [1, 0, 0, 0] } },
      { "time": 0.47,
        "root_position": [0, 2, 0.1],
        "rotations": { "root": { "euler_deg": [90, 0, 0], "order": "XYZ" },
                       "lumbar": [0.6, 0.8, 0, 0],
                       "hip_l": { "euler_deg": [-45, 10, 5], "order": "ZYX" },
                       "knee_l": [0.70710678118654752, 0.70710678118654752, 0, 0] } },
      { "time": 1.0,
        "rotations": { "root": [0, 1, 0, 0], "lumbar": [1, 0, 0, 0],
                       "hip_l": [1, 0, 0, 0], "knee_l": [1, 0, 0, 0] } }
    ],
    "spline": {
      "knots": [0, 0, 0, 0, 0.5, 1, 1, 1, 1],
      "root_translation": [[0, 0, 0], [0, 1, 0], [0, 2, 0], [0, 1, 0], [0, 0, 0]],
      "joints": {
        "root": [[1, 0, 0, 0], [0.96, 0.28, 0, 0], [0.6, 0.8, 0, 0], [0.28, 0.96, 0, 0], [0, 1, 0, 0]],
        "lumbar": [[1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0]],
        "hip_l": [[1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0]],
        "knee_l": [[1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0]]
      }
    }
  })");
}

/// Runs `action`, requires an InputError, and checks what() = "<file>: <pointer>: ..." with the
/// pointer exact and `keyword` somewhere in the problem.
void expect_input_error(const std::function<void()>& action, const std::string& file,
                        const std::string& pointer, const std::string& keyword) {
  try {
    action();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), file) << what;
    EXPECT_EQ(e.json_path(), pointer) << what;
    const std::string prefix = pointer.empty() ? file + ": " : file + ": " + pointer + ": ";
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << "expected prefix \"" << prefix << "\" in: " << what;
    EXPECT_NE(e.problem().find(keyword), std::string::npos)
        << "expected \"" << keyword << "\" in: " << what;
    return;
  } catch (const std::exception& e) {
    FAIL() << "expected InputError, got another exception: " << e.what();
  }
  FAIL() << "expected InputError at " << pointer << " (" << keyword << "), nothing was thrown";
}

/// parse_motion of `document` must fail at `pointer` with `keyword`.
void expect_parse_error(const nlohmann::json& document, const std::string& pointer,
                        const std::string& keyword) {
  const BodyModel model = tiny_model();
  expect_input_error([&] { parse_motion(document, kFile, model); }, kFile, pointer, keyword);
}

bool same_rotation(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double tol) {
  return std::abs(std::abs(a.coeffs().dot(b.coeffs())) - 1.0) < tol;
}

/// A file in the test temp folder, removed when the object goes away.
class MotionTempFile {
 public:
  MotionTempFile(const std::string& stem, const std::string& contents) {
    std::random_device rd;
    path_ = (fs::path(::testing::TempDir()) / (stem + "-" + std::to_string(rd()) + ".motion.json"))
                .string();
    std::ofstream out(path_);
    out << contents;
  }
  ~MotionTempFile() {
    std::error_code ignored;
    fs::remove(path_, ignored);
  }
  MotionTempFile(const MotionTempFile&) = delete;
  MotionTempFile& operator=(const MotionTempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// ---------------------------------------------------------------------------------------------
// Good input

TEST(Motion, GoodDocumentParses) {
  const BodyModel model = tiny_model();
  const Motion m = parse_motion(good_motion_document(), kFile, model);
  EXPECT_EQ(m.name, "test tuck");
  EXPECT_EQ(m.model, "tiny-4");
  EXPECT_TRUE(m.takeoff.com_position.isApprox(Eigen::Vector3d(0, 1, 0)));
  EXPECT_TRUE(m.takeoff.com_velocity.isApprox(Eigen::Vector3d(0.15, 10.0, 0.15)));
  ASSERT_TRUE(m.takeoff.angular_momentum.has_value());
  EXPECT_TRUE(m.takeoff.angular_momentum->isApprox(Eigen::Vector3d(-40, 0, 0)));
  EXPECT_DOUBLE_EQ(m.tolerances.translation_m, 0.2);
  EXPECT_DOUBLE_EQ(m.tolerances.quaternion, 0.04);
  ASSERT_EQ(m.keyframes.size(), 3u);
  EXPECT_EQ(m.keyframes[0].time, 0.0);
  EXPECT_DOUBLE_EQ(m.keyframes[1].time, 0.47);
  EXPECT_DOUBLE_EQ(m.flight_time(), 1.0);
  for (const auto& k : m.keyframes) {
    ASSERT_EQ(k.rotations.size(), 4u);
    for (const auto& q : k.rotations)
      EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  }
  EXPECT_FALSE(m.keyframes[0].root_position.has_value());
  ASSERT_TRUE(m.keyframes[1].root_position.has_value());
  EXPECT_TRUE(m.keyframes[1].root_position->isApprox(Eigen::Vector3d(0, 2, 0.1)));

  // Rotations are indexed by model segment: lumbar is segment 1, knee_l segment 3.
  const Eigen::Quaterniond lumbar = m.keyframes[1].rotations[model.joint_index("lumbar")];
  EXPECT_TRUE(lumbar.coeffs().isApprox(Eigen::Quaterniond(0.6, 0.8, 0, 0).coeffs(), 1e-15));
  const Eigen::Quaterniond knee = m.keyframes[1].rotations[model.joint_index("knee_l")];
  EXPECT_TRUE(same_rotation(
      knee, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX())), 1e-12));
  // [0, 1, 0, 0] is a half turn about x.
  EXPECT_TRUE(same_rotation(m.keyframes[2].rotations[0],
                            Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX())),
                            1e-12));

  ASSERT_TRUE(m.spline.has_value());
  EXPECT_EQ(m.spline->knots.size(), 9u);
  ASSERT_EQ(m.spline->root_translation.size(), 5u);
  EXPECT_TRUE(m.spline->root_translation[2].isApprox(Eigen::Vector3d(0, 2, 0)));
  ASSERT_EQ(m.spline->joint_control.size(), 4u);
  for (const auto& curve : m.spline->joint_control) {
    ASSERT_EQ(curve.size(), 5u);
    for (const auto& q : curve)
      EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  }
}

TEST(Motion, EulerXyz90IsQuarterTurnAboutX) {
  const BodyModel model = tiny_model();
  const Motion m = parse_motion(good_motion_document(), kFile, model);
  const Eigen::Quaterniond root = m.keyframes[1].rotations[model.joint_index("root")];
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(same_rotation(root, expected, 1e-12))
      << root.coeffs().transpose() << " vs " << expected.coeffs().transpose();
  // Intrinsic ZYX (-45, 10, 5) = Rz(-45) Ry(10) Rx(5), built independently with AngleAxis.
  const double d = M_PI / 180.0;
  const Eigen::Quaterniond zyx = Eigen::AngleAxisd(-45 * d, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(10 * d, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(5 * d, Eigen::Vector3d::UnitX());
  EXPECT_TRUE(same_rotation(m.keyframes[1].rotations[model.joint_index("hip_l")], zyx, 1e-12));
}

TEST(Motion, ToleranceDefaultsAndNameDefault) {
  nlohmann::json doc = good_motion_document();
  doc.erase("tolerances");
  doc.erase("name");
  doc.erase("spline");
  doc["takeoff"].erase("angular_momentum");
  const Motion m = parse_motion(doc, "/some/where/m1.motion.json", tiny_model());
  EXPECT_DOUBLE_EQ(m.tolerances.translation_m, 0.25);
  EXPECT_DOUBLE_EQ(m.tolerances.quaternion, 0.05);
  EXPECT_EQ(m.name, "m1");
  EXPECT_FALSE(m.takeoff.angular_momentum.has_value());
  EXPECT_FALSE(m.spline.has_value());

  // Each tolerance is optional on its own.
  doc["tolerances"] = {{"quaternion", 0.01}};
  const Motion partial = parse_motion(doc, kFile, tiny_model());
  EXPECT_DOUBLE_EQ(partial.tolerances.translation_m, 0.25);
  EXPECT_DOUBLE_EQ(partial.tolerances.quaternion, 0.01);
}

TEST(Motion, QuaternionSlightlyOffUnitIsNormalised) {
  nlohmann::json doc = good_motion_document();
  const double scale = 1.0 + 5e-4;
  doc["keyframes"][1]["rotations"]["lumbar"] = {0.6 * scale, 0.8 * scale, 0.0, 0.0};
  doc["spline"]["joints"]["hip_l"][2] = {scale, 0.0, 0.0, 0.0};
  const BodyModel model = tiny_model();
  const Motion m = parse_motion(doc, kFile, model);
  const Eigen::Quaterniond q = m.keyframes[1].rotations[model.joint_index("lumbar")];
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  EXPECT_NEAR(q.w(), 0.6, 1e-15);
  EXPECT_NEAR(q.x(), 0.8, 1e-15);
  const Eigen::Quaterniond c = m.spline->joint_control[model.joint_index("hip_l")][2];
  EXPECT_NEAR(c.w(), 1.0, 1e-15);
}

TEST(Motion, RoundTripReproducesMotion) {
  const BodyModel model = tiny_model();
  const Motion a = parse_motion(good_motion_document(), kFile, model);
  const nlohmann::json written = motion_to_json(a, model);
  // Through text as well, as a file would be.
  const Motion b = parse_motion(nlohmann::json::parse(written.dump(2)), kFile, model);

  EXPECT_EQ(b.name, a.name);
  EXPECT_EQ(a.description, "free text for people, kept and written back");
  EXPECT_EQ(b.description, a.description);
  EXPECT_EQ(b.model, a.model);
  EXPECT_EQ(written["keyframes"][1]["rotations"]["root"].size(), 4u);  // written as [w,x,y,z]
  EXPECT_LE((b.takeoff.com_position - a.takeoff.com_position).norm(), 1e-15);
  EXPECT_LE((b.takeoff.com_velocity - a.takeoff.com_velocity).norm(), 1e-15);
  ASSERT_TRUE(b.takeoff.angular_momentum.has_value());
  EXPECT_LE((*b.takeoff.angular_momentum - *a.takeoff.angular_momentum).norm(), 1e-15);
  EXPECT_EQ(b.tolerances.translation_m, a.tolerances.translation_m);
  EXPECT_EQ(b.tolerances.quaternion, a.tolerances.quaternion);
  ASSERT_EQ(b.keyframes.size(), a.keyframes.size());
  for (std::size_t k = 0; k < a.keyframes.size(); ++k) {
    EXPECT_EQ(b.keyframes[k].time, a.keyframes[k].time);
    ASSERT_EQ(b.keyframes[k].rotations.size(), a.keyframes[k].rotations.size());
    for (std::size_t j = 0; j < a.keyframes[k].rotations.size(); ++j)
      EXPECT_LE((b.keyframes[k].rotations[j].coeffs() - a.keyframes[k].rotations[j].coeffs())
                    .cwiseAbs()
                    .maxCoeff(),
                1e-15)
          << "keyframe " << k << " joint " << j;
    ASSERT_EQ(b.keyframes[k].root_position.has_value(), a.keyframes[k].root_position.has_value());
    if (a.keyframes[k].root_position) {
      EXPECT_LE((*b.keyframes[k].root_position - *a.keyframes[k].root_position).norm(), 1e-15);
    }
  }
  ASSERT_TRUE(b.spline.has_value());
  EXPECT_EQ(b.spline->knots, a.spline->knots);
  ASSERT_EQ(b.spline->root_translation.size(), a.spline->root_translation.size());
  for (std::size_t i = 0; i < a.spline->root_translation.size(); ++i)
    EXPECT_LE((b.spline->root_translation[i] - a.spline->root_translation[i]).norm(), 1e-15);
  ASSERT_EQ(b.spline->joint_control.size(), a.spline->joint_control.size());
  for (std::size_t j = 0; j < a.spline->joint_control.size(); ++j) {
    ASSERT_EQ(b.spline->joint_control[j].size(), a.spline->joint_control[j].size());
    for (std::size_t i = 0; i < a.spline->joint_control[j].size(); ++i)
      EXPECT_LE((b.spline->joint_control[j][i].coeffs() - a.spline->joint_control[j][i].coeffs())
                    .cwiseAbs()
                    .maxCoeff(),
                1e-15);
  }
}

TEST(Motion, RoundTripWithoutOptionalParts) {
  nlohmann::json doc = good_motion_document();
  doc.erase("spline");
  doc["takeoff"].erase("angular_momentum");
  doc["keyframes"][1].erase("root_position");
  doc.erase("description");
  const BodyModel model = tiny_model();
  const nlohmann::json written = motion_to_json(parse_motion(doc, kFile, model), model);
  EXPECT_FALSE(written.contains("description"));
  EXPECT_FALSE(written.contains("spline"));
  EXPECT_FALSE(written["takeoff"].contains("angular_momentum"));
  EXPECT_FALSE(written["keyframes"][1].contains("root_position"));
  const Motion b = parse_motion(written, kFile, model);
  EXPECT_FALSE(b.spline.has_value());
  EXPECT_FALSE(b.keyframes[1].root_position.has_value());
}

TEST(Motion, ReadModelField) {
  EXPECT_EQ(read_motion_model_field(good_motion_document(), kFile), "tiny-4");
  nlohmann::json doc = good_motion_document();
  doc.erase("model");
  expect_input_error([&] { read_motion_model_field(doc, kFile); }, kFile, "/", "\"model\"");
  doc["model"] = 3;
  expect_input_error([&] { read_motion_model_field(doc, kFile); }, kFile, "/model", "string");
}

TEST(Motion, LoadMotionFileResolvesRelativeModel) {
  const std::string path = std::string(SALTUS_TEST_DATA_DIR) + "/motion/tiny.motion.json";
  const MotionFile file = load_motion_file(path);
  EXPECT_EQ(file.path, path);
  EXPECT_EQ(file.model.name, "tiny-4");
  EXPECT_EQ(file.model.size(), 4);
  EXPECT_EQ(file.motion.name, "tiny tuck");
  EXPECT_EQ(file.motion.model, "tiny-model.json");
  ASSERT_EQ(file.motion.keyframes.size(), 2u);
  const Eigen::Quaterniond knee =
      file.motion.keyframes[1].rotations[file.model.joint_index("knee_l")];
  EXPECT_TRUE(same_rotation(
      knee, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX())), 1e-12));
}

TEST(Motion, ModelReferenceForASavedMotionFindsTheSameModel) {
  // The app saves edited motions anywhere; the field it writes must load the model it showed,
  // within the reader's rule (a bundled name or a file in the motion's folder tree).
  std::random_device rd;
  const fs::path root = fs::path(::testing::TempDir()) / ("model-ref-" + std::to_string(rd()));
  fs::create_directories(root / "models");
  fs::create_directories(root / "sub");
  const std::string data = std::string(SALTUS_TEST_DATA_DIR) + "/motion/";
  fs::copy_file(data + "tiny-model.json", root / "models" / "mine.json");
  nlohmann::json motion = nlohmann::json::parse(std::ifstream(data + "tiny.motion.json"));
  const auto save = [&](const fs::path& at, const std::string& field) {
    motion["model"] = field;
    std::ofstream(at) << motion.dump(2);
  };

  const ModelReference inside = model_reference_for((root / "models" / "mine.json").string(),
                                                    (root / "a.motion.json").string());
  EXPECT_EQ(inside.field, "models/mine.json");
  EXPECT_TRUE(inside.loads_by_itself);
  save(root / "a.motion.json", inside.field);
  EXPECT_EQ(load_motion_file((root / "a.motion.json").string()).model.name, "tiny-4");

  const ModelReference outside = model_reference_for((root / "models" / "mine.json").string(),
                                                     (root / "sub" / "b.motion.json").string());
  EXPECT_EQ(outside.field, "../models/mine.json");
  EXPECT_FALSE(outside.loads_by_itself);
  save(root / "sub" / "b.motion.json", outside.field);
  expect_input_error([&] { load_motion_file((root / "sub" / "b.motion.json").string()); },
                     (root / "sub" / "b.motion.json").string(), "/model", "outside");
  EXPECT_EQ(load_motion_file((root / "sub" / "b.motion.json").string(),
                             (root / "models" / "mine.json").string())
                .model.name,
            "tiny-4");

  bool bundled_seen = false;
  for (const std::string& dir : resource_directories()) {
    const fs::path bundled = fs::path(dir) / "models" / "zatsiorsky-66kg.json";
    if (!fs::exists(bundled)) continue;
    const ModelReference by_name =
        model_reference_for(bundled.string(), (root / "sub" / "c.motion.json").string());
    EXPECT_EQ(by_name.field, "zatsiorsky-66kg");
    EXPECT_TRUE(by_name.loads_by_itself);
    bundled_seen = true;
  }
  EXPECT_TRUE(bundled_seen) << "no bundled model among the resource directories";
  fs::remove_all(root);
}

// ---------------------------------------------------------------------------------------------
// Bad input: one change to the good document each.

TEST(MotionErrors, WrongFormatTag) {
  nlohmann::json doc = good_motion_document();
  doc["format"] = "saltus-motion/2";
  expect_parse_error(doc, "/format", "saltus-motion/1");
}

TEST(MotionErrors, MissingTakeoff) {
  nlohmann::json doc = good_motion_document();
  doc.erase("takeoff");
  expect_parse_error(doc, "/", "missing field \"takeoff\"");
}

TEST(MotionErrors, ComVelocityWrongLength) {
  nlohmann::json doc = good_motion_document();
  doc["takeoff"]["com_velocity"] = {0.15, 10.0};
  expect_parse_error(doc, "/takeoff/com_velocity", "expected 3 numbers, found 2");
}

TEST(MotionErrors, StringInsteadOfNumber) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][1]["time"] = "0.5";
  expect_parse_error(doc, "/keyframes/1/time", "expected a number, found string");
}

TEST(MotionErrors, KeyframeTimesUnsorted) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][1]["time"] = 1.5;
  expect_parse_error(doc, "/keyframes/2/time",
                     "keyframe 2 time 1 is not after keyframe 1 time 1.5");
}

TEST(MotionErrors, KeyframeTimesEqual) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][2]["time"] = 0.47;
  expect_parse_error(doc, "/keyframes/2/time", "strictly increase");
}

TEST(MotionErrors, FirstTimeNotZero) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][0]["time"] = 0.1;
  expect_parse_error(doc, "/keyframes/0/time", "must be 0");
}

TEST(MotionErrors, FirstTimeWithinPrintingNoiseIsZero) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][0]["time"] = 1e-13;
  const Motion m = parse_motion(doc, kFile, tiny_model());
  EXPECT_EQ(m.keyframes[0].time, 0.0);
}

TEST(Motion, GapsOfTheShortestLengthReadDespiteRounding) {
  // A 1 kHz capture's frame times are k·0.001: 10·0.001 − 9·0.001 is 0.001 less a rounding.
  nlohmann::json doc = good_motion_document();
  doc.erase("spline");
  doc["keyframes"][1]["time"] = 9 * 0.001;
  doc["keyframes"][2]["time"] = 10 * 0.001;
  ASSERT_LT(10 * 0.001 - 9 * 0.001, 0.001);
  EXPECT_NO_THROW(parse_motion(doc, kFile, tiny_model()));
  doc["keyframes"][2]["time"] = 9 * 0.001 + 0.999e-3;
  expect_parse_error(doc, "/keyframes/2/time", "apart");

  // Interior knots 0.001/50 apart, the same way: 107·g − 106·g < g.
  const double g = 0.001 / 50;
  ASSERT_LT(107 * g - 106 * g, g);
  doc = good_motion_document();
  doc["keyframes"][1]["time"] = 0.001;
  doc["keyframes"][2]["time"] = 107 * g;
  doc["spline"]["knots"] = {0, 0, 0, 0, 106 * g, 107 * g, 107 * g, 107 * g, 107 * g};
  EXPECT_NO_THROW(parse_motion(doc, kFile, tiny_model()));
  doc["spline"]["knots"][4] = 107 * g - 0.999 * g;
  expect_parse_error(doc, "/spline/knots/5", "interior knots");
}

TEST(MotionErrors, FewerThanTwoKeyframes) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"].erase(1);
  doc["keyframes"].erase(1);
  expect_parse_error(doc, "/keyframes", "at least 2 keyframes");
}

TEST(MotionErrors, MissingJoint) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][2]["rotations"].erase("knee_l");
  expect_parse_error(doc, "/keyframes/2/rotations", "missing joint \"knee_l\"");
}

TEST(MotionErrors, UnknownJoint) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][1]["rotations"]["elbow_l"] = {1, 0, 0, 0};
  expect_parse_error(doc, "/keyframes/1/rotations/elbow_l", "unknown joint \"elbow_l\"");
}

TEST(MotionErrors, QuaternionNormTooFarFromOne) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][2]["rotations"]["hip_l"] = {1.2, 0, 0, 0};
  expect_parse_error(doc, "/keyframes/2/rotations/hip_l", "quaternion norm 1.2 is not 1");
}

TEST(MotionErrors, QuaternionNormJustOutsideTolerance) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][2]["rotations"]["hip_l"] = {1.0 + 2e-3, 0, 0, 0};
  expect_parse_error(doc, "/keyframes/2/rotations/hip_l", "tolerance 1e-3");
}

TEST(MotionErrors, QuaternionWithThreeNumbers) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][0]["rotations"]["lumbar"] = {1, 0, 0};
  expect_parse_error(doc, "/keyframes/0/rotations/lumbar", "expected 4 numbers, found 3");
}

TEST(MotionErrors, BadEulerOrder) {
  nlohmann::json doc = good_motion_document();
  doc["keyframes"][1]["rotations"]["root"]["order"] = "XXY";
  expect_parse_error(doc, "/keyframes/1/rotations/root/order", "invalid Euler order \"XXY\"");
}

TEST(MotionErrors, NegativeTolerance) {
  nlohmann::json doc = good_motion_document();
  doc["tolerances"]["translation_m"] = -0.1;
  expect_parse_error(doc, "/tolerances/translation_m", "must be > 0");
}

TEST(MotionErrors, UnknownTakeoffField) {
  nlohmann::json doc = good_motion_document();
  doc["takeoff"]["angular_momentun"] = {0, 0, 0};
  expect_parse_error(doc, "/takeoff/angular_momentun", "unknown field");
}

TEST(MotionErrors, SplineWrongControlCount) {
  nlohmann::json doc = good_motion_document();
  doc["spline"]["joints"]["lumbar"].erase(4);
  expect_parse_error(doc, "/spline/joints/lumbar", "expected 5 control points");
  doc = good_motion_document();
  doc["spline"]["root_translation"].push_back({0, 0, 0});
  expect_parse_error(doc, "/spline/root_translation", "expected 5 control points");
}

TEST(MotionErrors, SplineDecreasingKnots) {
  nlohmann::json doc = good_motion_document();
  doc["spline"]["knots"][4] = -0.5;
  expect_parse_error(doc, "/spline/knots/4", "must not decrease");
}

TEST(MotionErrors, InvalidJsonSyntax) {
  const MotionTempFile file("syntax", R"({ "format": "saltus-motion/1", "model": "tiny-4", })");
  expect_input_error([&] { load_motion_file(file.path()); }, file.path(), "", "invalid JSON");
}

TEST(MotionErrors, MissingModelFile) {
  nlohmann::json doc = good_motion_document();
  doc["model"] = "no-such-model-4f1c";
  const MotionTempFile file("missing-model", doc.dump());
  expect_input_error([&] { load_motion_file(file.path()); }, file.path(), "/model",
                     "model \"no-such-model-4f1c\" not found");
}

TEST(MotionLabel, IsTheSkillNumberOrTheFileNameWithoutItsSuffix) {
  EXPECT_EQ(motion_label("examples/motions/M3-tucked-double-back.motion.json"), "M3");
  EXPECT_EQ(motion_label("/a/b/M12-future.motion.json"), "M12");
  EXPECT_EQ(motion_label("dive-5m-front-one-and-a-half-twists.motion.json"),
            "dive-5m-front-one-and-a-half-twists");
  EXPECT_EQ(motion_label("Mx-not-a-skill.motion.json"), "Mx-not-a-skill");
  EXPECT_EQ(motion_label("plain.json"), "plain.json");
}

}  // namespace
}  // namespace saltus

namespace saltus {
namespace {

// save_motion_file: what it writes parses back to the same motion (through the file), it
// replaces a motion file it wrote, and it refuses any other file, leaving it as it was.
TEST(Motion, SaveMotionFileReplacesOnlyMotionFiles) {
  namespace fs = std::filesystem;
  const BodyModel model = tiny_model();
  const Motion motion = parse_motion(good_motion_document(), kFile, model);
  std::random_device rd;
  const fs::path folder = fs::path(::testing::TempDir()) / ("save-motion-" + std::to_string(rd()));
  const std::string path = (folder / "a.motion.json").string();
  save_motion_file(path, motion, model);  // creates the folder
  std::ifstream in(path);
  const Motion back = parse_motion(nlohmann::json::parse(in), path, model);
  EXPECT_EQ(back.keyframes.size(), motion.keyframes.size());
  Motion renamed = motion;
  renamed.name = "renamed";
  save_motion_file(path, renamed, model);
  std::ifstream again(path);
  EXPECT_EQ(nlohmann::json::parse(again)["name"], "renamed");

  const std::string foreign = (folder / "notes.json").string();
  std::ofstream(foreign) << "{\"format\": \"something-else\"}\n";
  try {
    save_motion_file(foreign, motion, model);
    ADD_FAILURE() << "a foreign file was replaced";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a motion Saltus wrote"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("notes.json"), std::string::npos) << e.what();
  }
  std::ifstream kept(foreign);
  EXPECT_EQ(nlohmann::json::parse(kept)["format"], "something-else");
  // A motion written by hand (the bundled M1's text, no mark) is the user's too.
  const std::string by_hand = (folder / "notes.json").string();
  std::ofstream(by_hand) << motion_to_json(motion, model).dump(2);
  EXPECT_THROW(save_motion_file(by_hand, renamed, model), InputError);
  // Nothing left behind but the two files.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(folder))
    ++entries;
  EXPECT_EQ(entries, 2);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace saltus
