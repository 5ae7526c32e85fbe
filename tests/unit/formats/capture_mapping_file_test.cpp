// Mapping files: what they may say, and errors that name the file and the JSON path.

#include "saltus/formats/capture_mapping_file.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "saltus/base/input_error.h"

namespace saltus {
namespace {

nlohmann::json valid() {
  return nlohmann::json::parse(R"({
    "format": "saltus-capture-mapping/1", "unit": "inch", "up": "-z",
    "joints": { "pelvis": "Bip Pelvis", "abdomen": ["S1", "S2"], "thorax": null,
                "upper_arm_l": "L Up", "foot_r": null } })");
}

std::string error_of(const nlohmann::json& document) {
  try {
    parse_capture_mapping(document, "map.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CaptureMappingFile, ReadsUnitsAxesAndJoints) {
  const SkeletonMapping m = parse_capture_mapping(valid(), "map.json");
  EXPECT_DOUBLE_EQ(*m.metres_per_unit, 0.0254);
  EXPECT_EQ(*m.up, Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(m.joints.at("abdomen"), (std::vector<std::string>{"S1", "S2"}));
  EXPECT_TRUE(m.joints.at("thorax").empty());
  EXPECT_TRUE(m.joints.at("foot_r").empty());
  EXPECT_EQ(m.joints.count("thigh_l"), 0u);  // left to the names
}

TEST(CaptureMappingFile, ErrorsNameTheJsonPath) {
  nlohmann::json d = valid();
  d["joints"]["elbow_l"] = "x";
  EXPECT_EQ(error_of(d).rfind("map.json: /joints/elbow_l: unknown key \"elbow_l\"", 0), 0u)
      << error_of(d);
  d = valid();
  d["joints"]["thigh_l"] = {"a", "b"};
  EXPECT_EQ(error_of(d),
            "map.json: /joints/thigh_l: thigh_l takes one joint (only the abdomen and the thorax "
            "may average several)");
  d = valid();
  d["joints"]["shank_r"] = nullptr;
  EXPECT_EQ(error_of(d),
            "map.json: /joints/shank_r: shank_r needs a source joint (only abdomen, thorax, feet "
            "and hands may be null)");
  d = valid();
  d["unit"] = "furlong";
  EXPECT_EQ(error_of(d),
            "map.json: /unit: unknown unit \"furlong\" (expected m, cm, mm, inch or metres per "
            "unit)");
  d = valid();
  d["up"] = "w";
  EXPECT_EQ(error_of(d), "map.json: /up: unknown up axis \"w\" (expected x, y, z, -x, -y or -z)");
  d = valid();
  d["format"] = "saltus-motion/1";
  EXPECT_EQ(error_of(d),
            "map.json: /format: expected format \"saltus-capture-mapping/1\", found "
            "\"saltus-motion/1\"");
  d = valid();
  d["units"] = "cm";
  EXPECT_EQ(error_of(d).rfind("map.json: /units: unknown field \"units\"", 0), 0u);
}

TEST(CaptureMappingFile, UnitsArePhysicalAndUserTextIsEscaped) {
  // Issue 28: "unit": 1e308 wrote null root positions.
  nlohmann::json d = valid();
  d["unit"] = 1e308;
  EXPECT_EQ(error_of(d),
            "map.json: /unit: 1e+308 metres per unit is outside the plausible range [0.0001, 10] "
            "metres per unit");
  d["unit"] = 0;
  EXPECT_NE(error_of(d).find("map.json: /unit: 0 metres per unit is outside"), std::string::npos);
  d["unit"] = 0.0254;
  EXPECT_DOUBLE_EQ(*parse_capture_mapping(d, "map.json").metres_per_unit, 0.0254);
  d = valid();
  d["up"] = "z\n\x1B[2J";
  EXPECT_EQ(error_of(d),
            "map.json: /up: unknown up axis \"z\\x0A\\x1B[2J\" (expected x, y, z, -x, -y or -z)");
}

TEST(CaptureMappingFile, JointsMustBeInTheCapture) {
  const SkeletonMapping m = parse_capture_mapping(valid(), "map.json");
  MocapClip clip;
  for (const char* name : {"Bip Pelvis", "S1", "L Up"}) {
    MocapJoint joint;
    joint.name = name;
    clip.joints.push_back(joint);
  }
  try {
    check_capture_mapping(m, clip, "map.json", "take.bvh");
    FAIL() << "a missing joint was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "map.json: /joints/abdomen/1: joint \"S2\" is not in take.bvh");
  }
}

}  // namespace
}  // namespace saltus
