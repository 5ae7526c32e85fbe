// The glTF export's file (formats/gltf_file.h), read back byte by byte against the glTF 2.0
// specification: the GLB container's lengths, every buffer view on a 4-byte boundary inside the
// buffer, every accessor inside its view with min and max equal to the stored floats; nodes
// named and nested as the model, the animation's samples the states' poses, the CoM path the
// CoMs; each drawn shape's vertices on its surface, normals unit and outward, triangles turning
// counter-clockwise seen from outside. Khronos's validator and three.js read it too
// (tests/cli/export_gltf_test.cpp).

#include "saltus/formats/gltf_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>

#include "saltus/base/input_error.h"
#include "saltus/motion/interpolate.h"
#include "support/input_errors.h"
#include "support/temp_path.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// A motion's frames, ready for gltf_binary.
struct GltfInput {
  BodyModel model = test::bundled_model();
  std::vector<double> times;
  std::vector<BodyState<double>> states;
  std::vector<Eigen::Vector3d> com;
};

GltfInput twist_frames(int frames) {
  GltfInput in;
  const Trajectory<double> trajectory = motion_trajectory(test::twist_motion(in.model), in.model);
  for (int k = 0; k < frames; ++k) {
    in.times.push_back(trajectory.duration() * k / (frames - 1));
    in.states.emplace_back(in.model.size());
    trajectory.sample(in.times.back(), in.states.back());
    in.com.push_back(Eigen::Vector3d(0.1 * k, 1.0 + k, -0.5 * k));
  }
  return in;
}

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

/// The GLB's parts, read here without the library's reader.
struct Glb {
  nlohmann::json json;
  std::string bin;
};

Glb split(const std::string& bytes) {
  Glb glb;
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(u32(bytes, 4), 2u);
  EXPECT_EQ(u32(bytes, 8), bytes.size());
  const std::uint32_t json_length = u32(bytes, 12);
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_EQ(bytes.substr(16, 4), "JSON");
  glb.json = nlohmann::json::parse(bytes.substr(20, json_length));
  const std::size_t bin_at = 20 + json_length;
  EXPECT_EQ(u32(bytes, bin_at) % 4, 0u);
  EXPECT_EQ(bytes.substr(bin_at + 4, 4), std::string("BIN\0", 4));
  glb.bin = bytes.substr(bin_at + 8, u32(bytes, bin_at));
  EXPECT_EQ(bin_at + 8 + glb.bin.size(), bytes.size());
  return glb;
}

/// Accessor `index` as doubles, after checking it lies inside its view and its view inside the
/// buffer, aligned.
std::vector<double> accessor_values(const Glb& glb, int index) {
  const nlohmann::json& a = glb.json["accessors"][index];
  const nlohmann::json& view = glb.json["bufferViews"][a["bufferView"].get<int>()];
  const std::size_t offset = view["byteOffset"], length = view["byteLength"];
  EXPECT_EQ(offset % 4, 0u);
  EXPECT_LE(offset + length, glb.bin.size());
  EXPECT_EQ(glb.json["buffers"][0]["byteLength"], glb.bin.size());
  const std::string type = a["type"];
  const std::size_t width = type == "SCALAR" ? 1 : type == "VEC3" ? 3 : 4;
  const int component = a["componentType"];
  const std::size_t size = component == 5126 ? 4 : 2;
  const std::size_t count = a["count"];
  EXPECT_EQ(count * width * size, length) << "one accessor fills its view";
  std::vector<double> values;
  for (std::size_t i = 0; i < count * width; ++i) {
    if (component == 5126) {
      float f;
      std::memcpy(&f, glb.bin.data() + offset + 4 * i, 4);
      values.push_back(f);
    } else {
      std::uint16_t s;
      std::memcpy(&s, glb.bin.data() + offset + 2 * i, 2);
      values.push_back(s);
    }
  }
  if (a.contains("min")) {
    for (std::size_t c = 0; c < width; ++c) {
      double low = 1e300, high = -1e300;
      for (std::size_t i = c; i < values.size(); i += width) {
        low = std::min(low, values[i]);
        high = std::max(high, values[i]);
      }
      EXPECT_EQ(a["min"][c].get<double>(), low) << "accessor " << index;
      EXPECT_EQ(a["max"][c].get<double>(), high) << "accessor " << index;
    }
  }
  return values;
}

TEST(GltfFile, TheContainerViewsAndAccessorsFollowTheSpecification) {
  const GltfInput in = twist_frames(7);
  const Glb glb = split(gltf_binary(in.model, "twist", in.times, in.states, in.com));
  EXPECT_EQ(glb.json["asset"]["version"], "2.0");
  EXPECT_EQ(glb.json["asset"]["generator"], kGltfGenerator);
  for (std::size_t i = 0; i < glb.json["accessors"].size(); ++i)
    accessor_values(glb, static_cast<int>(i));
  // POSITION accessors and animation inputs must carry min and max.
  for (const nlohmann::json& mesh : glb.json["meshes"])
    for (const nlohmann::json& p : mesh["primitives"])
      EXPECT_TRUE(glb.json["accessors"][p["attributes"]["POSITION"].get<int>()].contains("min"));
  for (const nlohmann::json& s : glb.json["animations"][0]["samplers"])
    EXPECT_TRUE(glb.json["accessors"][s["input"].get<int>()].contains("max"));
}

TEST(GltfFile, NodesMirrorTheModelAndTheAnimationHoldsThePoses) {
  const GltfInput in = twist_frames(5);
  const Glb glb = split(gltf_binary(in.model, "twist", in.times, in.states, in.com));
  const nlohmann::json& nodes = glb.json["nodes"];
  const int n = in.model.size();
  ASSERT_EQ(nodes.size(), static_cast<std::size_t>(n + 1));
  EXPECT_EQ(glb.json["scenes"][0]["nodes"], nlohmann::json({0, n}));
  for (int k = 0; k < n; ++k) {
    const Segment& s = in.model.segments[k];
    EXPECT_EQ(nodes[k]["name"], s.name);
    for (int c = 0; c < n; ++c) {
      const bool listed = nodes[k].contains("children") &&
                          std::find(nodes[k]["children"].begin(), nodes[k]["children"].end(), c) !=
                              nodes[k]["children"].end();
      EXPECT_EQ(listed, in.model.segments[c].parent == k) << s.name << " / " << c;
    }
    if (k == 0) continue;  // the root's translation is the motion's
    for (int i = 0; i < 3; ++i)
      EXPECT_FLOAT_EQ(nodes[k]["translation"][i].get<float>(), s.joint_position[i]);
  }
  const nlohmann::json& animation = glb.json["animations"][0];
  EXPECT_EQ(animation["name"], "twist");
  ASSERT_EQ(animation["channels"].size(), static_cast<std::size_t>(n + 1));
  for (const nlohmann::json& channel : animation["channels"]) {
    const nlohmann::json& sampler = animation["samplers"][channel["sampler"].get<int>()];
    EXPECT_EQ(sampler["interpolation"], "LINEAR");
    const std::vector<double> t = accessor_values(glb, sampler["input"]);
    const std::vector<double> out = accessor_values(glb, sampler["output"]);
    const int node = channel["target"]["node"];
    ASSERT_EQ(t.size(), in.times.size());
    for (std::size_t f = 0; f < t.size(); ++f) {
      EXPECT_FLOAT_EQ(t[f], in.times[f]);
      if (channel["target"]["path"] == "translation") {
        EXPECT_EQ(node, 0);
        for (int i = 0; i < 3; ++i)
          EXPECT_FLOAT_EQ(out[3 * f + i], in.states[f].root_position[i]);
      } else {
        const Eigen::Quaterniond q(out[4 * f + 3], out[4 * f], out[4 * f + 1], out[4 * f + 2]);
        EXPECT_LT(q.angularDistance(in.states[f].joints[node].q), 1e-6) << node << " " << f;
        if (f > 0) {
          const Eigen::Quaterniond p(out[4 * f - 1], out[4 * f - 4], out[4 * f - 3],
                                     out[4 * f - 2]);
          EXPECT_GE(p.dot(q), 0.0) << "consecutive on one side: slerp turns the short way";
        }
      }
    }
  }
  // The CoM's path: the last node, a line strip through the CoMs.
  EXPECT_EQ(nodes[n]["name"], "centre_of_mass_path");
  const nlohmann::json& line = glb.json["meshes"][nodes[n]["mesh"].get<int>()]["primitives"][0];
  EXPECT_EQ(line["mode"], 3);
  const std::vector<double> path = accessor_values(glb, line["attributes"]["POSITION"]);
  ASSERT_EQ(path.size(), 3 * in.com.size());
  for (std::size_t f = 0; f < in.com.size(); ++f)
    for (int i = 0; i < 3; ++i)
      EXPECT_FLOAT_EQ(path[3 * f + i], in.com[f][i]);
}

TEST(GltfFile, ShapesAreClosedSurfacesFacingOutward) {
  GltfInput in = twist_frames(2);
  BodyModel& model = in.model;
  model.segments.resize(1);
  model.segments[0].shape.parts.clear();
  ShapePart capsule;
  capsule.name = "capsule";
  capsule.type = "capsule";
  capsule.center = Eigen::Vector3d(0.1, 0.2, 0.3);
  capsule.length = -0.4;
  capsule.radius = 0.05;
  ShapePart ellipsoid;
  ellipsoid.name = "ellipsoid";
  ellipsoid.center = Eigen::Vector3d(-0.1, 0.0, 0.05);
  ellipsoid.radii = Eigen::Vector3d(0.1, 0.2, 0.05);
  model.segments[0].shape.parts = {capsule, ellipsoid};
  for (BodyState<double>& s : in.states)
    s.joints.resize(1);
  const Glb glb = split(gltf_binary(model, "shapes", in.times, in.states, in.com));
  const nlohmann::json& primitives = glb.json["meshes"][0]["primitives"];
  ASSERT_EQ(primitives.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const std::vector<double> p = accessor_values(glb, primitives[k]["attributes"]["POSITION"]);
    const std::vector<double> n = accessor_values(glb, primitives[k]["attributes"]["NORMAL"]);
    const std::vector<double> index = accessor_values(glb, primitives[k]["indices"]);
    const auto vertex = [&](std::size_t i) {
      return Eigen::Vector3d(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    };
    const auto normal = [&](std::size_t i) {
      return Eigen::Vector3d(n[3 * i], n[3 * i + 1], n[3 * i + 2]);
    };
    for (std::size_t i = 0; i < p.size() / 3; ++i) {
      const Eigen::Vector3d v = vertex(i);
      if (k == 0) {
        // On the capsule: at `radius` from its axis segment.
        const Eigen::Vector3d d = v - capsule.center;
        const double along = std::clamp(d.y(), -0.2, 0.2);
        EXPECT_NEAR((d - Eigen::Vector3d(0, along, 0)).norm(), 0.05, 1e-6);
      } else {
        EXPECT_NEAR((v - ellipsoid.center).cwiseQuotient(ellipsoid.radii).norm(), 1.0, 1e-6);
      }
      EXPECT_NEAR(normal(i).norm(), 1.0, 1e-6);
    }
    // Every triangle turns counter-clockwise seen from outside (its normal along the vertices');
    // every edge is shared by two triangles: a closed surface.
    std::map<std::pair<int, int>, int> edges;
    for (std::size_t t = 0; t < index.size(); t += 3) {
      const int a = index[t], b = index[t + 1], c = index[t + 2];
      const Eigen::Vector3d face = (vertex(b) - vertex(a)).cross(vertex(c) - vertex(a));
      EXPECT_GT(face.dot(normal(a) + normal(b) + normal(c)), 0.0) << "triangle " << t / 3;
      for (const auto& [u, w] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
        ++edges[{std::min(u, w), std::max(u, w)}];
    }
    for (const auto& [edge, count] : edges)
      EXPECT_EQ(count, 2);
  }
}

TEST(GltfFile, TheReaderChecksTheContainerAndKnowsSaltussOwnFiles) {
  const GltfInput in = twist_frames(3);
  const std::string bytes = gltf_binary(in.model, "twist", in.times, in.states, in.com);
  EXPECT_EQ(read_glb_json(bytes, "a.glb")["asset"]["generator"], kGltfGenerator);
  EXPECT_NE(test::input_error([&] {
              read_glb_json(bytes.substr(0, bytes.size() - 4), "a.glb");
            }).find("a.glb: the header's length"),
            std::string::npos);
  EXPECT_NE(test::input_error([&] { read_glb_json("PK\x03\x04", "b.glb"); }).find("b.glb: not a"),
            std::string::npos);

  const std::string mine = test::temp_path("mine.glb").string();
  std::ofstream(mine, std::ios::binary) << bytes;
  EXPECT_TRUE(gltf_written_by_saltus(mine));
  std::string other = bytes;
  other.replace(other.find(kGltfGenerator), 6, "Blendr");
  const std::string theirs = test::temp_path("theirs.glb").string();
  std::ofstream(theirs, std::ios::binary) << other;
  EXPECT_FALSE(gltf_written_by_saltus(theirs)) << "another generator";
  EXPECT_FALSE(gltf_written_by_saltus(test::temp_path("absent.glb").string()));

  EXPECT_THROW(gltf_binary(in.model, "x", {0.0}, {in.states[0]}, {in.com[0]}),
               std::invalid_argument);
}

}  // namespace
}  // namespace saltus
