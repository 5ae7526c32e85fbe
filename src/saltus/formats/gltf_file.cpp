#include "saltus/formats/gltf_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/base/input_error.h"
#include "saltus/body/drawn_parts.h"
#include "saltus/formats/flight_page_assets.h"

namespace saltus {

namespace {

// glTF 2.0's numeric codes (Khronos, "glTF 2.0 Specification", 5.1 and 3.6).
constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;
constexpr int kLineStrip = 3;
constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

/// The largest JSON chunk read when asking whether a .glb is Saltus's: its own are a few hundred
/// kB.
constexpr std::uint32_t kMaxGlbJsonBytes = 64u * 1024u * 1024u;

/// Slices around a shape's axis and rings from its equator to a pole.
constexpr int kSlices = 24;
constexpr int kRingsPerHalf = 8;

/// A triangle mesh in segment coordinates.
struct TriangleMesh {
  std::vector<float> positions;  ///< x y z per vertex
  std::vector<float> normals;    ///< unit, x y z per vertex
  std::vector<std::uint16_t> indices;
};

/// A point of a shape's profile around the y axis: its distance from the axis, its height, and
/// the outward normal in the (distance, height) plane.
struct ProfilePoint {
  double rho, y, normal_rho, normal_y;
};

/// The solid of revolution of `profile` (from the bottom pole to the top pole, both on the
/// axis), scaled by `scale` along x, y, z, about `center`. Counter-clockwise seen from outside.
TriangleMesh lathe(const std::vector<ProfilePoint>& profile, const Eigen::Vector3d& center,
                   const Eigen::Vector3d& scale) {
  TriangleMesh mesh;
  const auto vertex = [&](const ProfilePoint& p, double theta) {
    const Eigen::Vector3d unit(p.rho * std::sin(theta), p.y, p.rho * std::cos(theta));
    const Eigen::Vector3d position = center + scale.cwiseProduct(unit);
    // Normals of a scaled surface scale by the inverse.
    const Eigen::Vector3d normal =
        Eigen::Vector3d(p.normal_rho * std::sin(theta), p.normal_y, p.normal_rho * std::cos(theta))
            .cwiseQuotient(scale)
            .normalized();
    for (int i = 0; i < 3; ++i) {
      mesh.positions.push_back(static_cast<float>(position[i]));
      mesh.normals.push_back(static_cast<float>(normal[i]));
    }
  };
  const int rings = static_cast<int>(profile.size()) - 2;  // without the poles
  vertex(profile.front(), 0.0);
  for (int r = 1; r <= rings; ++r)
    for (int s = 0; s < kSlices; ++s)
      vertex(profile[r], 2 * kPi * s / kSlices);
  vertex(profile.back(), 0.0);
  const auto at = [](int ring, int slice) {
    return static_cast<std::uint16_t>(1 + (ring - 1) * kSlices + slice % kSlices);
  };
  const auto top = static_cast<std::uint16_t>(1 + rings * kSlices);
  for (int s = 0; s < kSlices; ++s) {
    mesh.indices.insert(mesh.indices.end(), {0, at(1, s + 1), at(1, s)});
    for (int r = 1; r < rings; ++r)
      mesh.indices.insert(mesh.indices.end(), {at(r, s), at(r, s + 1), at(r + 1, s + 1), at(r, s),
                                               at(r + 1, s + 1), at(r + 1, s)});
    mesh.indices.insert(mesh.indices.end(), {at(rings, s), at(rings, s + 1), top});
  }
  return mesh;
}

/// A capsule along y: two half spheres of radius `radius` joined by a cylinder `length` long.
TriangleMesh capsule_mesh(const Eigen::Vector3d& center, double length, double radius) {
  std::vector<ProfilePoint> profile;
  const double half = 0.5 * std::abs(length);
  for (int k = -kRingsPerHalf; k <= kRingsPerHalf; ++k) {
    const double phi = 0.5 * kPi * k / kRingsPerHalf;
    const double c = std::cos(phi), s = std::sin(phi);
    // The equator twice, at both ends of the cylinder (once when there is no cylinder).
    if (k <= 0) profile.push_back({radius * c, -half + radius * s, c, s});
    if (k >= 0 && (k > 0 || half > 0)) profile.push_back({radius * c, half + radius * s, c, s});
  }
  profile.front().rho = profile.back().rho = 0.0;
  return lathe(profile, center, Eigen::Vector3d::Ones());
}

/// An ellipsoid with semi-axes `radii` along the segment's axes.
TriangleMesh ellipsoid_mesh(const Eigen::Vector3d& center, const Eigen::Vector3d& radii) {
  std::vector<ProfilePoint> profile;
  for (int k = -kRingsPerHalf; k <= kRingsPerHalf; ++k) {
    const double phi = 0.5 * kPi * k / kRingsPerHalf;
    profile.push_back({std::cos(phi), std::sin(phi), std::cos(phi), std::sin(phi)});
  }
  profile.front().rho = profile.back().rho = 0.0;
  return lathe(profile, center, radii);
}

/// glTF's colours are linear; the app's are sRGB (IEC 61966-2-1's transfer function).
double linear_from_srgb(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

/// The binary buffer and the JSON that describes it, grown view by view. Each view starts on a
/// 4-byte boundary and holds one accessor, so no view needs a stride.
class GlbBuffer {
 public:
  /// A view of `values` and its accessor (`type` "SCALAR", "VEC3", "VEC4"); with `bounds`, the
  /// accessor's min and max (exactly the stored floats').
  template <typename T>
  int add(const std::vector<T>& values, int component_type, const char* type, int target,
          bool bounds) {
    const int width = std::string(type) == "SCALAR" ? 1 : std::string(type) == "VEC3" ? 3 : 4;
    nlohmann::json view = {
        {"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", values.size() * sizeof(T)}};
    if (target) view["target"] = target;
    const std::size_t start = bin_.size();
    bin_.resize(start + values.size() * sizeof(T));
    std::memcpy(&bin_[start], values.data(), values.size() * sizeof(T));
    bin_.resize((bin_.size() + 3) / 4 * 4, '\0');
    views_.push_back(view);
    nlohmann::json accessor = {{"bufferView", views_.size() - 1},
                               {"componentType", component_type},
                               {"count", values.size() / width},
                               {"type", type}};
    if (bounds) {
      std::vector<double> low(width, std::numeric_limits<double>::infinity());
      std::vector<double> high(width, -std::numeric_limits<double>::infinity());
      for (std::size_t i = 0; i < values.size(); ++i) {
        low[i % width] = std::min(low[i % width], static_cast<double>(values[i]));
        high[i % width] = std::max(high[i % width], static_cast<double>(values[i]));
      }
      accessor["min"] = low;
      accessor["max"] = high;
    }
    accessors_.push_back(accessor);
    return static_cast<int>(accessors_.size()) - 1;
  }
  const std::string& bin() const { return bin_; }
  const nlohmann::json& views() const { return views_; }
  const nlohmann::json& accessors() const { return accessors_; }

 private:
  std::string bin_;
  nlohmann::json views_ = nlohmann::json::array();
  nlohmann::json accessors_ = nlohmann::json::array();
};

void append_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i)
    out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

std::uint32_t read_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return v;
}

std::vector<float> floats(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

/// glTF's rotation: x y z w.
std::vector<double> xyzw(const Eigen::Quaterniond& q) {
  const Eigen::Quaterniond n = q.normalized();
  return {n.x(), n.y(), n.z(), n.w()};
}

/// One mesh per segment, a primitive per drawn part, a material per colour.
void add_meshes(const BodyModel& model, GlbBuffer& buffer, nlohmann::json& meshes,
                nlohmann::json& materials) {
  std::map<std::string, int> material_of;
  const auto material = [&](const DrawingColour& c) {
    const std::string name = hex_colour(c);
    const auto found = material_of.find(name);
    if (found != material_of.end()) return found->second;
    materials.push_back(
        {{"name", name},
         {"pbrMetallicRoughness",
          {{"baseColorFactor",
            {linear_from_srgb(c.r), linear_from_srgb(c.g), linear_from_srgb(c.b), 1.0}},
           {"metallicFactor", 0.0},
           {"roughnessFactor", 0.8}}}});
    return material_of[name] = static_cast<int>(materials.size()) - 1;
  };
  for (const Segment& s : model.segments) {
    nlohmann::json primitives = nlohmann::json::array();
    for (const DrawnPart& part : drawn_parts(s)) {
      const ShapePart& p = part.shape;
      const TriangleMesh mesh = p.type == "capsule" ? capsule_mesh(p.center, p.length, p.radius)
                                                    : ellipsoid_mesh(p.center, p.radii);
      primitives.push_back(
          {{"attributes",
            {{"POSITION", buffer.add(mesh.positions, kFloat, "VEC3", kArrayBuffer, true)},
             {"NORMAL", buffer.add(mesh.normals, kFloat, "VEC3", kArrayBuffer, false)}}},
           {"indices",
            buffer.add(mesh.indices, kUnsignedShort, "SCALAR", kElementArrayBuffer, false)},
           {"material", material(part.colour)},
           {"mode", kTriangles}});
    }
    meshes.push_back({{"name", s.name + " mesh"}, {"primitives", primitives}});
  }
}

}  // namespace

std::string gltf_binary(const BodyModel& model, const std::string& title,
                        const std::vector<double>& times,
                        const std::vector<BodyState<double>>& states,
                        const std::vector<Eigen::Vector3d>& com) {
  const int n = model.size();
  if (n < 1 || times.size() < 2 || states.size() != times.size() || com.size() != times.size())
    throw std::invalid_argument("gltf_binary: one state and one CoM per time, two times at least");
  for (const BodyState<double>& s : states)
    if (static_cast<int>(s.joints.size()) != n)
      throw std::invalid_argument("gltf_binary: a state does not fit the model");

  GlbBuffer buffer;
  nlohmann::json meshes = nlohmann::json::array(), materials = nlohmann::json::array();
  add_meshes(model, buffer, meshes, materials);

  // Nodes: one per segment (index = segment index) at the first frame's pose, then the CoM path.
  nlohmann::json nodes = nlohmann::json::array();
  for (int k = 0; k < n; ++k) {
    const Segment& s = model.segments[k];
    nlohmann::json node = {
        {"name", s.name},
        {"mesh", k},
        {"rotation", xyzw(states.front().joints[k].q)},
        {"translation", k == 0 ? floats(states.front().root_position) : floats(s.joint_position)}};
    std::vector<int> children;
    for (int c = 0; c < n; ++c)
      if (model.segments[c].parent == k) children.push_back(c);
    if (!children.empty()) node["children"] = children;
    nodes.push_back(node);
  }
  std::vector<float> path;
  for (const Eigen::Vector3d& c : com)
    for (float v : floats(c))
      path.push_back(v);
  materials.push_back({{"name", "centre of mass path"},
                       {"pbrMetallicRoughness",
                        {{"baseColorFactor", {0.02, 0.02, 0.02, 1.0}}, {"metallicFactor", 0.0}}}});
  meshes.push_back(
      {{"name", "centre of mass path"},
       {"primitives",
        {{{"attributes", {{"POSITION", buffer.add(path, kFloat, "VEC3", kArrayBuffer, true)}}},
          {"material", materials.size() - 1},
          {"mode", kLineStrip}}}}});
  nodes.push_back({{"name", "centre_of_mass_path"}, {"mesh", meshes.size() - 1}});

  // The animation: every node's rotation, the root's translation, at the frames.
  std::vector<float> seconds(times.begin(), times.end());
  const int input = buffer.add(seconds, kFloat, "SCALAR", 0, true);
  nlohmann::json samplers = nlohmann::json::array(), channels = nlohmann::json::array();
  const auto animate = [&](int node, const char* path_name, int output) {
    samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
    channels.push_back(
        {{"sampler", samplers.size() - 1}, {"target", {{"node", node}, {"path", path_name}}}});
  };
  std::vector<float> translation;
  for (const BodyState<double>& s : states)
    for (float v : floats(s.root_position))
      translation.push_back(v);
  animate(0, "translation", buffer.add(translation, kFloat, "VEC3", 0, false));
  for (int k = 0; k < n; ++k) {
    // Each quaternion on the side of its predecessor, so that slerp takes the short way.
    std::vector<float> rotation;
    Eigen::Quaterniond previous = states.front().joints[k].q;
    for (const BodyState<double>& s : states) {
      Eigen::Quaterniond q = s.joints[k].q.normalized();
      if (q.dot(previous) < 0) q.coeffs() = -q.coeffs();
      previous = q;
      for (double v : xyzw(q))
        rotation.push_back(static_cast<float>(v));
    }
    animate(k, "rotation", buffer.add(rotation, kFloat, "VEC4", 0, false));
  }

  const nlohmann::json gltf = {
      {"asset",
       {{"version", "2.0"},
        {"generator", kGltfGenerator},
        {"extras", {{"saltus_version", kSaltusVersion}, {"model", model.name}}}}},
      {"scene", 0},
      {"scenes", {{{"name", title}, {"nodes", {0, n}}}}},
      {"nodes", nodes},
      {"meshes", meshes},
      {"materials", materials},
      {"animations", {{{"name", title}, {"samplers", samplers}, {"channels", channels}}}},
      {"accessors", buffer.accessors()},
      {"bufferViews", buffer.views()},
      {"buffers", {{{"byteLength", buffer.bin().size()}}}}};

  std::string json = gltf.dump();
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::string glb;
  append_u32(glb, kGlbMagic);
  append_u32(glb, 2);
  append_u32(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + buffer.bin().size()));
  append_u32(glb, static_cast<std::uint32_t>(json.size()));
  append_u32(glb, kJsonChunk);
  glb += json;
  append_u32(glb, static_cast<std::uint32_t>(buffer.bin().size()));
  append_u32(glb, kBinChunk);
  glb += buffer.bin();
  return glb;
}

nlohmann::json read_glb_json(const std::string& bytes, const std::string& file) {
  const auto fail = [&](const std::string& problem) -> nlohmann::json {
    throw InputError(file, "", problem);
  };
  if (bytes.size() < 20 || read_u32(bytes, 0) != kGlbMagic)
    return fail("not a binary glTF file (no \"glTF\" header)");
  if (read_u32(bytes, 4) != 2) return fail("not glTF version 2");
  if (read_u32(bytes, 8) != bytes.size())
    return fail("the header's length is not the file's (" + std::to_string(bytes.size()) +
                " bytes)");
  const std::uint32_t json_length = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != kJsonChunk || json_length % 4 != 0 || json_length > bytes.size() - 20)
    return fail("the first chunk is not a JSON chunk of a length the file holds");
  const std::size_t bin_at = 20 + json_length;
  if (bin_at != bytes.size()) {
    if (bin_at + 8 > bytes.size() || read_u32(bytes, bin_at + 4) != kBinChunk ||
        read_u32(bytes, bin_at) != bytes.size() - bin_at - 8)
      return fail("the second chunk is not a BIN chunk that ends the file");
  }
  nlohmann::json json =
      nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + bin_at, nullptr, false);
  if (json.is_discarded() || !json.is_object()) return fail("its JSON chunk is not a JSON object");
  return json;
}

bool glb_names_saltus(const std::string& bytes) {
  if (bytes.size() < 20 || read_u32(bytes, 0) != kGlbMagic || read_u32(bytes, 4) != 2) return false;
  const std::uint32_t json_length = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != kJsonChunk || json_length > kMaxGlbJsonBytes ||
      json_length > bytes.size() - 20)
    return false;
  const nlohmann::json json = nlohmann::json::parse(bytes.substr(20, json_length), nullptr, false);
  if (!json.is_object() || !json.contains("asset") || !json["asset"].is_object()) return false;
  const nlohmann::json& asset = json["asset"];
  return asset.contains("generator") && asset["generator"] == kGltfGenerator;
}

const FileKind& gltf_file_kind() {
  static const FileKind kind = FileKind::by_writer("glTF file", glb_names_saltus);
  return kind;
}

bool gltf_written_by_saltus(const std::string& path) {
  // Only the header and the JSON chunk are read: a large file of someone else's is not loaded.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(path, ec))) return false;
  std::ifstream in(path, std::ios::binary);
  std::string head(20, '\0');
  if (!in.read(&head[0], 20)) return false;
  const std::uint32_t json_length = read_u32(head, 12);
  if (json_length > kMaxGlbJsonBytes) return false;
  std::string json_text(json_length, '\0');
  if (!in.read(&json_text[0], json_length)) return false;
  return glb_names_saltus(head + json_text);
}

}  // namespace saltus
