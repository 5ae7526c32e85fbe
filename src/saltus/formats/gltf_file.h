#pragma once
/// @file
/// The glTF export (`saltus export --format gltf`, docs/formats.md "glTF"): one binary glTF 2.0
/// file (.glb) that Blender, three.js and web viewers open. A node per segment, nested as the
/// model's tree and named as the segments, each with a mesh of its drawing (the app's shapes and
/// colours); one animation "flight" that turns every node (parent_from_child) and moves the root
/// at the motion's frames, linearly interpolated (quaternions by slerp); the CoM's path as a
/// line. Metres and y up, as glTF asks and as Saltus's world already is; the athlete faces +z
/// at rest, glTF's front.

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/dynamics/body_state.h"
#include "saltus/formats/output_kind.h"

namespace saltus {

/// The generator every .glb Saltus writes names in asset.generator: Saltus replaces an existing
/// .glb only when it finds this there (gltf_written_by_saltus).
inline constexpr const char* kGltfGenerator = "Saltus glTF export";

/// The .glb bytes. Nodes at the first frame's pose; the animation's times are `times`.
/// @param title   the scene's and the animation's name (the motion's)
/// @param times   frame times, s, increasing
/// @param states  one per time: root position (world, m) and joint rotations (root:
///                world_from_root; others: parent_from_child); rates are not used
/// @param com     the whole-body CoM at each time, world, m
/// Throws std::invalid_argument when the sizes disagree or there are fewer than two frames.
std::string gltf_binary(const BodyModel& model, const std::string& title,
                        const std::vector<double>& times,
                        const std::vector<BodyState<double>>& states,
                        const std::vector<Eigen::Vector3d>& com);

/// The JSON chunk of GLB bytes, parsed, after checking the container (the header's magic,
/// version 2 and length, the chunks' types and lengths). InputError naming `file` otherwise.
nlohmann::json read_glb_json(const std::string& bytes, const std::string& file);

/// True when `bytes` are a .glb whose asset.generator is kGltfGenerator: the mark of
/// gltf_file_kind().
bool glb_names_saltus(const std::string& bytes);

/// A .glb as Saltus writes it (output_kind.h): marked by its writer in asset.generator, so that
/// only a .glb Saltus wrote is ever replaced.
const FileKind& gltf_file_kind();

/// True when `path` is a regular .glb whose asset.generator is kGltfGenerator.
bool gltf_written_by_saltus(const std::string& path);

}  // namespace saltus
