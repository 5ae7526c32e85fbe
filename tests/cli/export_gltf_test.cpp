// `saltus export --format gltf` read by real consumers: the .glb of M7 passes Khronos's glTF
// validator (the npm package pinned in tests/support/npm) with no error, warning, info or hint;
// three.js r111's GLTFLoader (Debian's libjs-three) loads it in headless Chromium, plays its one
// animation and finds every segment where `saltus evaluate` puts it (its trajectory.csv, at the
// same frames: the first, a middle one and the last) to 1 mm and 0.01°, and the CoM's path a
// line through the CSV's CoM. The file is replaced only when Saltus wrote it.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "saltus/formats/csv_table.h"
#include "support/chromium_page.h"
#include "support/cli_runner.h"

namespace saltus::test {
namespace {

namespace fs = std::filesystem;

std::string m7_motion() {
  return std::string(SALTUS_EXAMPLES_DIR) +
         "/motions/M7-double-front-one-and-a-half-twists.motion.json";
}

fs::path npm_tools() {
  return fs::path(SALTUS_TEST_DATA_DIR).parent_path() / "support/npm";
}

/// Standard base64 (RFC 4648), for a file inlined into a page.
std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 |
                       static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    for (int k = 18; k >= 0; k -= 6)
      out.push_back(digits[(v >> k) & 63]);
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 |
                       (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0);
    out.push_back(digits[(v >> 18) & 63]);
    out.push_back(digits[(v >> 12) & 63]);
    out.push_back(two ? digits[(v >> 6) & 63] : '=');
    out.push_back('=');
  }
  return out;
}

/// A page that loads `glb` with three.js's GLTFLoader, plays its first animation (once, held at
/// the end) and writes into #result, at the animation's frames `frames` (−1: the last), each
/// named node's world position and rotation, and the CoM path's points.
std::string three_page(const std::string& glb, const std::vector<std::string>& nodes,
                       const std::vector<int>& frames) {
  const std::string three = "file:///usr/share/javascript/three/";
  return "<!DOCTYPE html><html><head><meta charset=\"utf-8\">"
         "<script src=\"" +
         three +
         "build/three.min.js\"></script>"
         "<script src=\"" +
         three +
         "examples/js/loaders/GLTFLoader.js\"></script>"
         "</head><body><pre id=\"result\"></pre><script>\n"
         "const nodes = " +
         nlohmann::json(nodes).dump() +
         ";\n"
         "const frames = " +
         nlohmann::json(frames).dump() +
         ";\n"
         "const bytes = Uint8Array.from(atob('" +
         base64(glb) +
         "'), c => c.charCodeAt(0));\n"
         R"(const result = document.getElementById('result');
new THREE.GLTFLoader().parse(bytes.buffer, '', function (gltf) {
  const clip = gltf.animations[0];
  const out = {animations: gltf.animations.length, name: clip.name, duration: clip.duration,
               frames: clip.tracks[0].times.length, poses: []};
  const mixer = new THREE.AnimationMixer(gltf.scene);
  const action = mixer.clipAction(clip);
  action.setLoop(THREE.LoopOnce);
  action.clampWhenFinished = true;
  action.play();
  for (const f of frames) {
    const frame = f < 0 ? out.frames - 1 : f;
    const time = clip.tracks[0].times[frame];
    mixer.setTime(time);
    gltf.scene.updateMatrixWorld(true);
    const pose = {frame: frame, time: time, nodes: {}};
    for (const name of nodes) {
      const o = gltf.scene.getObjectByName(name);
      if (!o) continue;
      const p = new THREE.Vector3(), q = new THREE.Quaternion();
      o.getWorldPosition(p);
      o.getWorldQuaternion(q);
      pose.nodes[name] = {p: [p.x, p.y, p.z], q: [q.w, q.x, q.y, q.z]};
    }
    out.poses.push(pose);
  }
  const line = gltf.scene.getObjectByName('centre_of_mass_path');
  out.com_is_line = !!(line && line.isLine);
  out.com = line ? Array.from(line.geometry.attributes.position.array) : [];
  result.textContent = JSON.stringify(out);
}, function (error) { result.textContent = JSON.stringify({error: String(error)}); });
</script></body></html>
)";
}

TEST(ExportGltf, WritesOneFileAndReplacesOnlyItsOwn) {
  TempDir dir;
  const std::string glb = dir / "m7.glb";
  CliRun run = run_cli("export " + m7_motion() + " --format gltf --out " + glb);
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("one animation of 123 frames"), std::string::npos) << run.output;
  EXPECT_EQ(read_text(glb).substr(0, 4), "glTF");
  run = run_cli("export " + m7_motion() + " --format gltf --quiet --out " + glb);
  EXPECT_EQ(run.status, 0) << "its own file is replaced: " << run.output;

  const std::string model = dir / "model.glb";
  write_text(model, "glTF, but someone else's");
  run = run_cli("export " + m7_motion() + " --format gltf --out " + model);
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find(model + ": exists and is not a glTF file Saltus wrote"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(read_text(model), "glTF, but someone else's");
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"m7.glb", "model.glb"}))
      << "no temporary left";
}

TEST(ExportGltf, KhronossValidatorFindsNothingToSay) {
  ASSERT_TRUE(fs::is_directory(npm_tools() / "node_modules/gltf-validator"))
      << "the glTF validator is needed: run `npm ci` in " << npm_tools()
      << " (tools/bootstrap.sh test does)";
  TempDir dir;
  const std::string glb = dir / "m7.glb";
  ASSERT_EQ(run_cli("export " + m7_motion() + " --format gltf --out " + glb).status, 0);
  const CliRun run =
      run_command("timeout 60 node " + (npm_tools() / "validate_gltf.js").string() + " " + glb);
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json report = nlohmann::json::parse(run.output);
  const nlohmann::json& issues = report["issues"];
  EXPECT_EQ(issues["numErrors"], 0) << issues.dump(1);
  EXPECT_EQ(issues["numWarnings"], 0) << issues.dump(1);
  EXPECT_EQ(issues["numInfos"], 0) << issues.dump(1);
  EXPECT_EQ(issues["numHints"], 0) << issues.dump(1);
  EXPECT_EQ(report["info"]["animationCount"], 1);
  EXPECT_EQ(report["info"]["generator"], "Saltus glTF export");
}

TEST(ExportGltfBrowser, ThreeJsPlaysTheAnimationWithSaltussPoses) {
  ASSERT_NO_FATAL_FAILURE(require_chromium());
  TempDir dir;
  const std::string glb = dir / "m7.glb";
  ASSERT_EQ(run_cli("export " + m7_motion() + " --format gltf --out " + glb).status, 0);

  // Saltus's own poses at the same frames: `evaluate` on as many samples.
  CliRun run = run_cli("evaluate " + m7_motion() + " --samples 123 --quiet --out " + (dir / "ev"));
  ASSERT_EQ(run.status, 0) << run.output;
  const CsvTable csv = read_csv_table(dir / "ev/trajectory.csv");
  std::vector<std::string> segments;
  for (const std::string& c : csv.columns)
    if (c.size() > 2 && c.compare(c.size() - 2, 2, ".x") == 0)
      segments.push_back(c.substr(0, c.size() - 2));
  ASSERT_EQ(segments.size(), 13u);

  const std::string page = dir / "three.html";
  write_text(page, three_page(read_text(glb), segments, {0, 61, -1}));
  const nlohmann::json found = page_json("file://" + page, dir / "profile", "result");
  SCOPED_TRACE(found.dump().substr(0, 2000));
  ASSERT_FALSE(found.contains("error"));
  ASSERT_EQ(found["animations"], 1);
  ASSERT_EQ(found["frames"], static_cast<int>(csv.rows.size()));
  EXPECT_NEAR(found["duration"].get<double>(), csv.rows.back()[0], 1e-6);
  ASSERT_EQ(found["poses"].size(), 3u);
  double worst_mm = 0, worst_deg = 0;
  for (const nlohmann::json& pose : found["poses"]) {
    const std::vector<double>& row = csv.rows[pose["frame"].get<std::size_t>()];
    EXPECT_NEAR(pose["time"].get<double>(), row[0], 1e-6);
    ASSERT_EQ(pose["nodes"].size(), segments.size()) << "every segment is a node";
    for (const std::string& s : segments) {
      const int at = csv.column(s + ".x");
      const Eigen::Vector3d expected(row[at], row[at + 1], row[at + 2]);
      const Eigen::Quaterniond expected_q(row[at + 3], row[at + 4], row[at + 5], row[at + 6]);
      const nlohmann::json& node = pose["nodes"][s];
      const Eigen::Vector3d p(node["p"][0], node["p"][1], node["p"][2]);
      const Eigen::Quaterniond q(node["q"][0], node["q"][1], node["q"][2], node["q"][3]);
      const double mm = 1000 * (p - expected).norm();
      const double deg = q.normalized().angularDistance(expected_q) * 180 / M_PI;
      EXPECT_LT(mm, 1.0) << s << " at t = " << row[0];
      EXPECT_LT(deg, 0.01) << s << " at t = " << row[0];
      worst_mm = std::max(worst_mm, mm);
      worst_deg = std::max(worst_deg, deg);
    }
    // The CoM's path: a line through the CSV's CoM at every frame.
    const std::size_t k = pose["frame"].get<std::size_t>();
    const int com = csv.column("com_x");
    ASSERT_TRUE(found["com_is_line"].get<bool>());
    ASSERT_EQ(found["com"].size(), 3 * csv.rows.size());
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(found["com"][3 * k + i].get<double>(), row[com + i], 1e-6);
  }
  std::printf("three.js against saltus evaluate: segments within %.2g mm and %.2g deg\n", worst_mm,
              worst_deg);
}

}  // namespace
}  // namespace saltus::test
