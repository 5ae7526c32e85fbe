// Tests for body model files (formats/model_file.h): the bundled default model's anthropometry
// (checked against independent expectations, not against numbers copied from the file), the
// exact round trip, and the validation of "saltus-model/1" documents, one test per kind of bad
// input. The BodyModel queries and mass scaling are tested in unit/body/body_model_test.cpp.

#include "saltus/formats/model_file.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/body/body_model.h"
#include "saltus/body/mass_properties.h"
#include "support/temp_path.h"

namespace saltus {
namespace {

const std::string kModelPath = std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json";
constexpr const char* kBadFile = "bad.json";

nlohmann::json good_document() {
  return read_json_file(kModelPath);
}

/// Parses `document` and requires an InputError whose message starts with
/// "bad.json: <pointer>: " and mentions `word`.
void expect_input_error(const nlohmann::json& document, const std::string& pointer,
                        const std::string& word) {
  try {
    parse_body_model(document, kBadFile);
    FAIL() << "expected InputError at " << pointer;
  } catch (const InputError& e) {
    const std::string what = e.what();
    const std::string prefix = std::string(kBadFile) + ": " + pointer + ": ";
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
    EXPECT_NE(what.find(word), std::string::npos) << what;
    EXPECT_EQ(e.file(), kBadFile);
    EXPECT_EQ(e.json_path(), pointer);
  }
}

/// Segment frame origins in the world at the identity pose with the root at the origin.
std::vector<Eigen::Vector3d> identity_pose_origins(const BodyModel& model) {
  std::vector<Eigen::Vector3d> origin(model.segments.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 1; i < model.segments.size(); ++i) {
    const Segment& s = model.segments[i];
    origin[i] = origin[static_cast<std::size_t>(s.parent)] + s.joint_position;
  }
  return origin;
}

int segment_named(const BodyModel& model, const std::string& name) {
  const int index = model.segment_index(name);
  EXPECT_GE(index, 0) << name;
  return index;
}

// ----------------------------------------------------------------------------------------------
// The bundled model.

TEST(BodyModelFile, RefusesMoreSegmentsThanABodyHasBeforeReadingThem) {
  // Every verb's cost grows with the segments (200 took 61 s and 1.6 GB to optimise).
  nlohmann::json document = {{"format", "saltus-model/1"}, {"name", "many"}};
  document["segments"] = nlohmann::json::array();
  for (int i = 0; i < 65; ++i)
    document["segments"].push_back(nlohmann::json::object());
  try {
    parse_body_model(document, "many.json");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.json_path(), "/segments");
    EXPECT_NE(std::string(e.what()).find("at most 64"), std::string::npos) << e.what();
  }
}

TEST(BodyModelDefault, LoadsWithTheDesignJointsInOrder) {
  const BodyModel model = load_body_model(kModelPath);
  EXPECT_EQ(model.name, "zatsiorsky-66kg");
  const std::vector<std::string> joints = {
      "root",  "lumbar", "thoracic", "shoulder_l", "elbow_l", "shoulder_r", "elbow_r",
      "hip_l", "knee_l", "ankle_l",  "hip_r",      "knee_r",  "ankle_r"};
  const std::vector<std::string> names = {
      "abdomen", "pelvis",  "thorax", "upper_arm_l", "forearm_l", "upper_arm_r", "forearm_r",
      "thigh_l", "shank_l", "foot_l", "thigh_r",     "shank_r",   "foot_r"};
  const std::vector<int> parents = {-1, 0, 0, 2, 3, 2, 5, 1, 7, 8, 1, 10, 11};
  ASSERT_EQ(model.size(), 13);
  for (int i = 0; i < model.size(); ++i) {
    EXPECT_EQ(model.segments[i].joint, joints[i]);
    EXPECT_EQ(model.segments[i].name, names[i]);
    EXPECT_EQ(model.segments[i].parent, parents[i]) << names[i];
    EXPECT_EQ(model.joint_index(joints[i]), i);
  }
  EXPECT_EQ(model.joint_index("neck"), -1);
  EXPECT_EQ(model.segment_index("head"), -1);
  EXPECT_NE(model.source.find("de Leva"), std::string::npos);
  EXPECT_NE(model.source.find("Zatsiorsky"), std::string::npos);
}

TEST(BodyModelDefault, MassesAndInertiasAreThePapersTable2) {
  const BodyModel model = load_body_model(kModelPath);
  EXPECT_NEAR(model.total_mass(), 65.5, 1e-12);
  struct Row {
    const char* segment;
    double mass, ix, iy, iz;
  };
  // Wei, Xia & Wang 2008, Table 2.
  const Row rows[] = {
      {"pelvis", 8.1, 0.053, 0.059, 0.066},       {"thigh_l", 10.0, 0.20, 0.041, 0.19},
      {"shank_r", 3.2, 0.037, 0.0065, 0.039},     {"foot_l", 1.0, 0.0040, 0.0010, 0.0044},
      {"abdomen", 12.0, 0.082, 0.12, 0.13},       {"thorax", 11.0, 0.071, 0.15, 0.17},
      {"upper_arm_r", 1.9, 0.011, 0.0040, 0.013}, {"forearm_l", 1.1, 0.0060, 0.0013, 0.0065}};
  for (const Row& row : rows) {
    const Segment& s = model.segments[static_cast<std::size_t>(segment_named(model, row.segment))];
    EXPECT_DOUBLE_EQ(s.mass, row.mass) << row.segment;
    EXPECT_DOUBLE_EQ(s.inertia(0, 0), row.ix) << row.segment;
    EXPECT_DOUBLE_EQ(s.inertia(1, 1), row.iy) << row.segment;
    EXPECT_DOUBLE_EQ(s.inertia(2, 2), row.iz) << row.segment;
    EXPECT_TRUE((s.inertia - Eigen::Matrix3d(s.inertia.diagonal().asDiagonal())).isZero(0.0));
  }
}

TEST(BodyModelDefault, LeftSegmentsMirrorRightOnes) {
  const BodyModel model = load_body_model(kModelPath);
  const Eigen::Vector3d mirror(-1.0, 1.0, 1.0);
  int pairs = 0;
  for (const Segment& left : model.segments) {
    if (left.name.size() < 2 || left.name.substr(left.name.size() - 2) != "_l") continue;
    const std::string right_name = left.name.substr(0, left.name.size() - 2) + "_r";
    const Segment& right =
        model.segments[static_cast<std::size_t>(segment_named(model, right_name))];
    ++pairs;
    EXPECT_EQ(left.joint.substr(0, left.joint.size() - 2),
              right.joint.substr(0, right.joint.size() - 2));
    EXPECT_EQ(left.joint_position, right.joint_position.cwiseProduct(mirror)) << left.name;
    EXPECT_EQ(left.com, right.com.cwiseProduct(mirror)) << left.name;
    EXPECT_EQ(left.mass, right.mass) << left.name;
    // Reflecting x flips the sign of the xy and xz entries and keeps the rest.
    const Eigen::Matrix3d reflect = mirror.asDiagonal();
    EXPECT_TRUE(left.inertia.isApprox(reflect * right.inertia * reflect)) << left.name;
    EXPECT_EQ(left.shape.length, right.shape.length) << left.name;
    EXPECT_EQ(left.shape.radius, right.shape.radius) << left.name;
    // The parent's left child must sit on the body's left (+x) or on the limb axis.
    EXPECT_GE(left.joint_position.x(), 0.0) << left.name;
  }
  EXPECT_EQ(pairs, 5);
  const auto origins = identity_pose_origins(model);
  EXPECT_GT(origins[static_cast<std::size_t>(model.joint_index("shoulder_l"))].x(), 0.1);
  EXPECT_GT(origins[static_cast<std::size_t>(model.joint_index("hip_l"))].x(), 0.05);
  EXPECT_LT(origins[static_cast<std::size_t>(model.joint_index("ankle_r"))].x(), -0.05);
}

TEST(BodyModelDefault, StandsAbout170cmTallAtTheIdentityPose) {
  const BodyModel model = load_body_model(kModelPath);
  const auto origin = identity_pose_origins(model);
  double top = -std::numeric_limits<double>::infinity();
  double bottom = std::numeric_limits<double>::infinity();
  std::string top_segment, bottom_segment;
  for (std::size_t i = 0; i < origin.size(); ++i) {
    const double end = origin[i].y() + model.segments[i].shape.length;
    if (std::max(origin[i].y(), end) > top) {
      top = std::max(origin[i].y(), end);
      top_segment = model.segments[i].name;
    }
    if (std::min(origin[i].y(), end) < bottom) {
      bottom = std::min(origin[i].y(), end);
      bottom_segment = model.segments[i].name;
    }
  }
  EXPECT_NEAR(top - bottom, 1.70, 0.03);
  EXPECT_EQ(top_segment, "thorax");  // the head is part of the thorax
  EXPECT_EQ(bottom_segment.substr(0, 5), "foot_");

  // Arms hang at the sides: the shoulders are below the head top, the elbows below the shoulders,
  // and the fingers end above the knees.
  const auto at = [&](const char* joint) {
    return origin[static_cast<std::size_t>(model.joint_index(joint))];
  };
  EXPECT_LT(at("shoulder_l").y(), top - 0.2);
  EXPECT_LT(at("elbow_l").y(), at("shoulder_l").y() - 0.2);
  const Segment& forearm = model.segments[static_cast<std::size_t>(model.joint_index("elbow_l"))];
  EXPECT_GT(at("elbow_l").y() + forearm.shape.length, at("knee_l").y());
  EXPECT_NEAR(at("shoulder_l").x(), 0.18, 0.03);

  // Whole-body CoM height of a standing adult is about 55-57 % of stature (Winter 2009, Table 4.1
  // proportions); an independent check of the CoM placements.
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < origin.size(); ++i)
    moment += model.segments[i].mass * (origin[i] + model.segments[i].com);
  const Eigen::Vector3d com = moment / model.total_mass();
  EXPECT_NEAR((com.y() - bottom) / (top - bottom), 0.56, 0.025);
  EXPECT_NEAR(com.x(), 0.0, 1e-12);
  EXPECT_NEAR(com.z(), 0.0, 1e-12);
}

TEST(BodyModelDefault, CentresOfMassLieInsideTheirSegments) {
  const BodyModel model = load_body_model(kModelPath);
  for (const Segment& s : model.segments) {
    EXPECT_EQ(s.com.x(), 0.0) << s.name;
    EXPECT_EQ(s.com.z(), 0.0) << s.name;
    const double fraction = s.com.y() / s.shape.length;
    EXPECT_GT(fraction, 0.3) << s.name;
    EXPECT_LT(fraction, 0.7) << s.name;
    EXPECT_EQ(s.shape.type, "capsule") << s.name;
    EXPECT_GT(s.shape.radius, 0.03) << s.name;
  }
}

// ----------------------------------------------------------------------------------------------
// Serialisation.

void expect_same_model(const BodyModel& a, const BodyModel& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.source, b.source);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    const Segment& x = a.segments[i];
    const Segment& y = b.segments[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.parent, y.parent);
    EXPECT_EQ(x.joint, y.joint);
    EXPECT_EQ(x.joint_position, y.joint_position) << x.name;
    EXPECT_EQ(x.mass, y.mass) << x.name;
    EXPECT_EQ(x.com, y.com) << x.name;
    EXPECT_EQ(x.inertia, y.inertia) << x.name;
    EXPECT_EQ(x.shape.type, y.shape.type);
    EXPECT_EQ(x.shape.length, y.shape.length);
    EXPECT_EQ(x.shape.radius, y.shape.radius);
    ASSERT_EQ(x.shape.parts.size(), y.shape.parts.size()) << x.name;
    for (std::size_t k = 0; k < x.shape.parts.size(); ++k) {
      const ShapePart& p = x.shape.parts[k];
      const ShapePart& q = y.shape.parts[k];
      EXPECT_EQ(p.name, q.name);
      EXPECT_EQ(p.type, q.type);
      EXPECT_EQ(p.center, q.center);
      EXPECT_EQ(p.radii, q.radii);
      EXPECT_EQ(p.length, q.length);
      EXPECT_EQ(p.radius, q.radius);
    }
  }
}

TEST(BodyModelJson, RoundTripReproducesTheModelExactly) {
  BodyModel model = load_body_model(kModelPath);
  // Off-diagonal entries and awkward decimals exercise the 6-value form and the number printing.
  model.segments[2].inertia(0, 1) = model.segments[2].inertia(1, 0) = 0.0123456789012345;
  model.segments[2].inertia(1, 2) = model.segments[2].inertia(2, 1) = -0.01 / 3.0;
  model.segments[4].mass = 1.0 / 3.0;
  model.segments[4].com.z() = 0.1 + 0.2;
  const nlohmann::json json = body_model_to_json(model);
  EXPECT_EQ(json.at("format"), "saltus-model/1");
  EXPECT_EQ(json.at("segments").at(2).at("inertia").size(), 6u);
  EXPECT_TRUE(json.at("segments").at(0).at("parent").is_null());
  EXPECT_EQ(json.at("segments").at(1).at("parent"), "abdomen");
  expect_same_model(parse_body_model(json, "memory"), model);
  // Through text too, as a file written by `saltus` and read back would go.
  expect_same_model(parse_body_model(nlohmann::json::parse(json.dump(2)), "text"), model);
}

TEST(BodyModelJson, SixValueInertiaIsASymmetricMatrix) {
  nlohmann::json doc = good_document();
  doc["segments"][0]["inertia"] = {0.082, 0.12, 0.13, 0.01, -0.02, 0.03};
  const BodyModel model = parse_body_model(doc, kBadFile);
  Eigen::Matrix3d expected;
  expected << 0.082, 0.01, -0.02, 0.01, 0.12, 0.03, -0.02, 0.03, 0.13;
  EXPECT_EQ(model.segments[0].inertia, expected);
}

TEST(BodyModelJson, OptionalFieldsMayBeLeftOut) {
  nlohmann::json doc = good_document();
  doc.erase("source");
  doc["segments"][0].erase("joint_position");
  doc["segments"][3].erase("shape");
  const BodyModel model = parse_body_model(doc, kBadFile);
  EXPECT_EQ(model.source, "");
  EXPECT_EQ(model.segments[0].joint_position, Eigen::Vector3d::Zero());
  EXPECT_EQ(model.segments[3].shape.length, 0.0);
  EXPECT_EQ(model.segments[3].shape.type, "capsule");
}

TEST(BodyModelJson, StrengthRoundTripsAndDefaultsToAYoungMan) {
  // The bundled athlete flies elite skills: the elite gymnast's strength.
  EXPECT_EQ(load_body_model(kModelPath).strength.reference, "elite-gymnast");
  // Without "strength": a young man's population strength.
  nlohmann::json doc = good_document();
  doc.erase("strength");
  const BodyModel bundled = parse_body_model(doc, kBadFile);
  EXPECT_EQ(bundled.strength.reference, "population");
  EXPECT_FALSE(bundled.strength.female);
  EXPECT_DOUBLE_EQ(bundled.strength.age_years, 21.0);
  BodyModel model = bundled;
  model.strength.reference = "elite-gymnast";
  model.strength.female = true;
  model.strength.age_years = 33.5;
  model.strength.measured = {{"hip", "extension", 231.5}, {"knee_l", "flexion", 97.0}};
  const nlohmann::json json = body_model_to_json(model);
  EXPECT_EQ(json.at("strength").at("sex"), "female");
  const BodyModel back = parse_body_model(nlohmann::json::parse(json.dump(2)), "text");
  EXPECT_EQ(back.strength.reference, "elite-gymnast");
  EXPECT_TRUE(back.strength.female);
  EXPECT_DOUBLE_EQ(back.strength.age_years, 33.5);
  ASSERT_EQ(back.strength.measured.size(), 2u);
  EXPECT_EQ(back.strength.measured[1].joint, "knee_l");
  EXPECT_EQ(back.strength.measured[1].direction, "flexion");
  EXPECT_DOUBLE_EQ(back.strength.measured[1].peak_moment_Nm, 97.0);
}

// ----------------------------------------------------------------------------------------------
// Validation: one test per kind of bad input.

TEST(BodyModelValidation, StrengthNamesWhatItCannotUse) {
  nlohmann::json doc = good_document();
  doc["strength"] = {{"reference", "olympian"}};
  expect_input_error(doc, "/strength/reference", "olympian");
  doc["strength"] = {{"sex", "other"}};
  expect_input_error(doc, "/strength/sex", "\"male\" or \"female\"");
  doc["strength"] = {{"age_years", 300}};
  expect_input_error(doc, "/strength/age_years", "years");
  doc["strength"] = {
      {"measured", {{{"joint", "hip"}, {"direction", "pronation"}, {"peak_moment_Nm", 100}}}}};
  expect_input_error(doc, "/strength/measured/0", "pronation");
  doc["strength"] = {
      {"measured", {{{"joint", "tail"}, {"direction", "flexion"}, {"peak_moment_Nm", 100}}}}};
  expect_input_error(doc, "/strength/measured/0", "tail");
  doc["strength"] = {
      {"measured", {{{"joint", "hip"}, {"direction", "flexion"}, {"peak_moment_Nm", -5}}}}};
  expect_input_error(doc, "/strength/measured/0/peak_moment_Nm", "N·m");
  doc["strength"] = {{"age", 20}};
  expect_input_error(doc, "/strength/age", "age_years");
}

TEST(BodyModelValidation, GoodDocumentParses) {
  EXPECT_NO_THROW(parse_body_model(good_document(), kBadFile));
}

TEST(BodyModelValidation, WrongFormatTag) {
  nlohmann::json doc = good_document();
  doc["format"] = "saltus-model/2";
  expect_input_error(doc, "/format", "saltus-model/2");
}

TEST(BodyModelValidation, MissingSegments) {
  nlohmann::json doc = good_document();
  doc.erase("segments");
  expect_input_error(doc, "/", "missing field \"segments\"");
}

TEST(BodyModelValidation, EmptySegments) {
  nlohmann::json doc = good_document();
  doc["segments"] = nlohmann::json::array();
  expect_input_error(doc, "/segments", "non-empty");
}

TEST(BodyModelValidation, UnknownParent) {
  nlohmann::json doc = good_document();
  doc["segments"][4]["parent"] = "upper_arm_x";
  expect_input_error(doc, "/segments/4/parent", "unknown parent \"upper_arm_x\"");
}

TEST(BodyModelValidation, ParentListedLaterIsACycleOrBadOrder) {
  nlohmann::json doc = good_document();
  // thorax's parent becomes forearm_r, whose chain leads back to the thorax.
  doc["segments"][2]["parent"] = "forearm_r";
  expect_input_error(doc, "/segments/2/parent", "listed after");
}

TEST(BodyModelValidation, SelfParent) {
  nlohmann::json doc = good_document();
  doc["segments"][8]["parent"] = "shank_l";
  expect_input_error(doc, "/segments/8/parent", "its own parent");
}

TEST(BodyModelValidation, DuplicateSegmentName) {
  nlohmann::json doc = good_document();
  doc["segments"][5]["name"] = "upper_arm_l";
  expect_input_error(doc, "/segments/5/name", "duplicate segment name \"upper_arm_l\"");
}

TEST(BodyModelValidation, DuplicateJointName) {
  nlohmann::json doc = good_document();
  doc["segments"][11]["joint"] = "knee_l";
  expect_input_error(doc, "/segments/11/joint", "duplicate joint name \"knee_l\"");
}

TEST(BodyModelValidation, RootNotFirst) {
  nlohmann::json doc = good_document();
  std::swap(doc["segments"][0], doc["segments"][1]);  // pelvis (parent abdomen) comes first
  expect_input_error(doc, "/segments/0/parent", "root");
}

TEST(BodyModelValidation, SecondRoot) {
  nlohmann::json doc = good_document();
  doc["segments"][2]["parent"] = nullptr;
  expect_input_error(doc, "/segments/2/parent", "only the first segment");
}

TEST(BodyModelValidation, RootJointNotNamedRoot) {
  nlohmann::json doc = good_document();
  doc["segments"][0]["joint"] = "pelvis_free";
  expect_input_error(doc, "/segments/0/joint", "must be named \"root\"");
}

TEST(BodyModelValidation, NonPositiveMass) {
  nlohmann::json doc = good_document();
  doc["segments"][2]["mass"] = -2;
  expect_input_error(doc, "/segments/2/mass", "mass must be positive, found -2");
  doc["segments"][2]["mass"] = 0.0;
  expect_input_error(doc, "/segments/2/mass", "positive");
}

TEST(BodyModelValidation, NonFiniteMass) {
  // JSON text cannot carry NaN, but a document built in code can.
  nlohmann::json doc = good_document();
  doc["segments"][3]["mass"] = std::numeric_limits<double>::quiet_NaN();
  expect_input_error(doc, "/segments/3/mass", "finite");
  doc["segments"][3]["mass"] = std::numeric_limits<double>::infinity();
  expect_input_error(doc, "/segments/3/mass", "finite");
}

TEST(BodyModelValidation, NonPositivePrincipalInertia) {
  nlohmann::json doc = good_document();
  doc["segments"][7]["inertia"][1] = 0.0;
  expect_input_error(doc, "/segments/7/inertia/1", "must be positive");
}

TEST(BodyModelValidation, SixValueInertiaNotPositiveDefinite) {
  nlohmann::json doc = good_document();
  // Positive diagonal, but Ixy = 0.2 > sqrt(Ixx * Iyy): an indefinite matrix.
  doc["segments"][1]["inertia"] = {0.053, 0.059, 0.066, 0.2, 0.0, 0.0};
  expect_input_error(doc, "/segments/1/inertia", "inertia is not positive definite");
}

TEST(BodyModelValidation, InertiaOfWrongLength) {
  nlohmann::json doc = good_document();
  doc["segments"][1]["inertia"] = {0.053, 0.059, 0.066, 0.0};
  expect_input_error(doc, "/segments/1/inertia", "found 4 values");
}

TEST(BodyModelValidation, WrongVectorLength) {
  nlohmann::json doc = good_document();
  doc["segments"][6]["com"] = {0.0, -0.17};
  expect_input_error(doc, "/segments/6/com", "expected 3 numbers, found 2");
}

TEST(BodyModelValidation, StringWhereANumberIsExpected) {
  nlohmann::json doc = good_document();
  doc["segments"][9]["joint_position"][1] = "-0.43";
  expect_input_error(doc, "/segments/9/joint_position/1", "expected a number, found string");
}

TEST(BodyModelValidation, BadShape) {
  nlohmann::json doc = good_document();
  doc["segments"][3]["shape"]["type"] = "cylinder";
  expect_input_error(doc, "/segments/3/shape/type", "cylinder");
  doc = good_document();
  doc["segments"][3]["shape"]["radius"] = -0.01;
  expect_input_error(doc, "/segments/3/shape/radius", "negative");
}

TEST(BodyModelValidation, BadShapePart) {
  nlohmann::json doc = good_document();
  const std::size_t thorax = 2;
  ASSERT_EQ(doc["segments"][thorax]["name"], "thorax");
  doc["segments"][thorax]["shape"]["parts"][2]["type"] = "cone";
  expect_input_error(doc, "/segments/2/shape/parts/2/type", "cone");
  doc = good_document();
  doc["segments"][thorax]["shape"]["parts"][2]["radii"][1] = 0.0;
  expect_input_error(doc, "/segments/2/shape/parts/2/radii", "positive");
  doc = good_document();
  doc["segments"][thorax]["shape"]["parts"][1]["radius"] = -0.05;
  expect_input_error(doc, "/segments/2/shape/parts/1/radius", "positive");
  doc = good_document();
  doc["segments"][thorax]["shape"]["parts"][0].erase("center");
  expect_input_error(doc, "/segments/2/shape/parts/0", "center");
  doc = good_document();
  doc["segments"][thorax]["shape"]["parts"] = "head";
  expect_input_error(doc, "/segments/2/shape/parts", "array");
}

TEST(BodyModelJson, FilesWithoutShapePartsStillReadAndWriteAsBefore) {
  nlohmann::json doc = good_document();
  for (auto& segment : doc["segments"])
    segment["shape"].erase("parts");
  const BodyModel model = parse_body_model(doc, kBadFile);
  for (const Segment& s : model.segments)
    EXPECT_TRUE(s.shape.parts.empty()) << s.name;
  // Written back, no "parts" key appears.
  const nlohmann::json written = body_model_to_json(model);
  for (const auto& segment : written["segments"])
    EXPECT_FALSE(segment["shape"].contains("parts"));
}

TEST(BodyModelDefault, DrawsAHeadOnTopHandsAtTheArmsAndFeetBelowTheAnkles) {
  // Drawing only, but it must sit where a person's head, hands and feet are: the head at the
  // top of the thorax's extent, the hands beyond the forearm's end, the feet below the ankles.
  const BodyModel model = load_body_model(kModelPath);
  auto part = [&](const char* segment, const char* name) -> const ShapePart& {
    const Segment& s = model.segments[static_cast<std::size_t>(segment_named(model, segment))];
    for (const ShapePart& p : s.shape.parts)
      if (p.name == name) return p;
    ADD_FAILURE() << segment << " has no part " << name;
    return s.shape.parts.front();
  };
  const Segment& thorax = model.segments[static_cast<std::size_t>(segment_named(model, "thorax"))];
  const ShapePart& head = part("thorax", "head");
  EXPECT_NEAR(head.center.y() + head.radii.y(), thorax.shape.length, 0.01);
  EXPECT_GT(part("thorax", "nose").center.z(), head.center.z());  // the face looks along +z
  for (const char* side : {"_l", "_r"}) {
    const std::string forearm = std::string("forearm") + side;
    const Segment& f = model.segments[static_cast<std::size_t>(segment_named(model, forearm))];
    const ShapePart& hand = part(forearm.c_str(), "hand");
    EXPECT_LT(hand.center.y(), f.shape.length + 0.05);  // beyond the wrist
    const ShapePart& foot = part((std::string("foot") + side).c_str(), "foot");
    EXPECT_LT(foot.center.y() - foot.radii.y(), -0.15);
  }
}

TEST(BodyModelValidation, MissingMass) {
  nlohmann::json doc = good_document();
  doc["segments"][12].erase("mass");
  expect_input_error(doc, "/segments/12", "missing field \"mass\"");
}

/// A file in the system's temporary folder, removed when the test ends.
class ModelTempFile {
 public:
  explicit ModelTempFile(const std::string& stem)
      : path_((std::filesystem::temp_directory_path() /
               (stem + "-" + std::to_string(std::random_device{}()) + ".json"))
                  .string()) {}
  ~ModelTempFile() { std::remove(path_.c_str()); }
  ModelTempFile(const ModelTempFile&) = delete;
  ModelTempFile& operator=(const ModelTempFile&) = delete;
  const std::string& path() const { return path_; }
  void write(const std::string& text) const { std::ofstream(path_) << text; }

 private:
  std::string path_;
};

TEST(BodyModelFile, InvalidJsonSyntaxNamesTheFile) {
  const ModelTempFile file("saltus-body-model-syntax");
  std::string text = good_document().dump(2);
  text.insert(text.find("\"segments\""), ",");  // a stray comma
  file.write(text);
  try {
    load_body_model(file.path());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(file.path() + ": ", 0), 0u) << what;
    EXPECT_NE(what.find("invalid JSON"), std::string::npos) << what;
    EXPECT_NE(what.find("line"), std::string::npos) << what;
  }
}

TEST(BodyModelFile, ValidationErrorsFromAFileNameThePath) {
  const ModelTempFile file("saltus-body-model-mass");
  nlohmann::json doc = good_document();
  doc["segments"][3]["mass"] = -2;
  file.write(doc.dump());
  try {
    load_body_model(file.path());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              file.path() + ": /segments/3/mass: mass must be positive, found -2");
  }
}

TEST(BodyModelFile, MissingFile) {
  const std::string path = std::string(SALTUS_TEST_DATA_DIR) + "/no-such-model.json";
  try {
    load_body_model(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
    EXPECT_NE(what.find("cannot open"), std::string::npos) << what;
  }
}

// ----------------------------------------------------------------------------------------------
// Writing a model file, and the summary `saltus model info --json` prints.

TEST(BodyModelFile, SavesAtomicallyAndReplacesOnlyItsOwnModelFiles) {
  const std::filesystem::path dir = test::temp_path("model-file-save");
  std::filesystem::create_directories(dir);
  const BodyModel model = load_body_model(kModelPath);
  const std::string path = (dir / "sub" / "athlete.model.json").string();
  save_body_model_file(path, model);  // creates the missing folder
  const BodyModel read = load_body_model(path);
  EXPECT_EQ(read.name, model.name);
  EXPECT_EQ(read.segments.size(), model.segments.size());
  // A Saltus model file is replaced; nothing else is left beside it.
  BodyModel renamed = model;
  renamed.name = "second";
  save_body_model_file(path, renamed);
  EXPECT_EQ(load_body_model(path).name, "second");
  std::size_t entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "sub")) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 1u);

  // Someone else's file, a JSON of another format, a folder: refused, left as they were.
  const std::string notes = (dir / "notes.txt").string();
  std::ofstream(notes) << "my notes";
  const std::string other = (dir / "other.json").string();
  std::ofstream(other) << R"({"format": "saltus-motion/1"})";
  for (const std::string& target : {notes, other, (dir / "sub").string()}) {
    try {
      save_body_model_file(target, model);
      FAIL() << target;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), target);
      EXPECT_NE(std::string(e.what()).find("Saltus"), std::string::npos) << e.what();
    }
  }
  std::ifstream in(notes);
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "my notes");
}

TEST(BodyModelFile, SummaryJsonCarriesTheStandingWholeBody) {
  const BodyModel model = load_body_model(kModelPath);
  const ModelSummary summary = summarize_model(model);
  const nlohmann::json j = model_summary_to_json(summary);
  EXPECT_EQ(j["format"], "saltus-model-info/1");
  EXPECT_EQ(j["name"], "zatsiorsky-66kg");
  EXPECT_NEAR(j["total_mass_kg"].get<double>(), 65.5, 1e-12);
  EXPECT_NEAR(j["standing_height_m"].get<double>(), 1.700, 5e-4);
  EXPECT_EQ(j["segments"].size(), 13u);
  EXPECT_EQ(j["segments"][2]["label"], "upper trunk and head");
  EXPECT_EQ(j["inertia_kgm2"].size(), 6u);
  EXPECT_NEAR(j["com_height_percent"].get<double>(),
              100.0 * j["com_height_m"].get<double>() / j["standing_height_m"].get<double>(),
              1e-12);
}

}  // namespace
}  // namespace saltus
