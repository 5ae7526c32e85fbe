#include "saltus/body/yeadon_model.h"

#include <algorithm>
#include <cmath>

#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "saltus/body/mass_properties.h"
#include "saltus/body/yeadon_solids.h"

namespace saltus {

namespace {

/// Segment densities, kg/L, of the ten groups Yeadon (1990) uses: head-neck, shoulders, thorax,
/// abdomen-pelvis, upper arm, forearm, hand, thigh, lower leg, foot; from Dempster (1955),
/// Chandler et al. (1975) and Clauser et al. (1969) as tabulated by Yeadon and the `yeadon`
/// package (densities.py).
enum Group {
  kHeadNeck,
  kShoulders,
  kThorax,
  kAbdomenPelvis,
  kUpperArm,
  kForearm,
  kHand,
  kThigh,
  kLowerLeg,
  kFoot,
  kGroups
};

double density_of(YeadonDensities set, Group group) {
  static const double dempster[kGroups] = {1.11, 1.04, 0.92, 1.01, 1.07,
                                           1.13, 1.16, 1.05, 1.09, 1.10};
  static const double chandler[kGroups] = {1.056, 0.853, 0.853, 0.853, 1.005,
                                           1.052, 1.080, 1.020, 1.078, 1.091};
  static const double clauser[kGroups] = {1.070, 1.019, 1.019, 1.019, 1.056,
                                          1.089, 1.109, 1.044, 1.085, 1.084};
  const double* table = set == YeadonDensities::kDempster   ? dempster
                        : set == YeadonDensities::kChandler ? chandler
                                                            : clauser;
  return 1000.0 * table[group];
}

/// Reads measurements, checks them, and makes the stadia and solids of one segment at a time.
class Builder {
 public:
  explicit Builder(const YeadonInput& in) : in_(in) {}

  double m(const std::string& key) const {
    const auto it = in_.measured.find(key);
    if (it == in_.measured.end()) throw InputError(in_.file, key, "missing measurement");
    return it->second;
  }

  /// A left/right note for messages about `key`, "" when its pair agrees.
  std::string pair_note(const std::string& key) const {
    const std::string other = paired(key);
    if (other.empty() || !in_.measured.count(other)) return "";
    const double a = m(key), b = m(other);
    if (std::max(a, b) <= 1.5 * std::min(a, b)) return "";
    return " (" + key + " " + message_number(a) + " m against " + other + " " + message_number(b) +
           " m on the other side: a typing error?)";
  }

  /// The stadium from `p_key` and `w_key`; p > πw becomes a circle of perimeter p (as the
  /// `yeadon` package does). p <= 2w fits no convex shape, so one of the two is wrong: when the
  /// width differs from the other side's like a typing error (the example female1's right wrist,
  /// 14.1 cm wide against 5.5 cm on the left), the width is the wrong one and the level becomes
  /// a circle of perimeter p, with a warning naming both widths; otherwise it is refused.
  Stadium perimeter_width(const std::string& p_key, const std::string& w_key,
                          bool anterior_posterior = false) {
    const double p = m(p_key), w = m(w_key);
    int status = 0;
    Stadium s = stadium_from_perimeter_width(p, w, &status);
    if (status < 0 && !pair_note(w_key).empty()) {
      warnings_.push_back(p_key + " " + message_number(p) + " m is too small for the width " +
                          w_key + " " + message_number(w) + " m" + pair_note(w_key) +
                          ": taken as a circle of perimeter " + message_number(p) + " m");
      s = circle_from_perimeter(p);
      status = 0;
    }
    if (status < 0)
      throw InputError(in_.file, p_key,
                       "perimeter " + message_number(p) + " m is too small for the width " + w_key +
                           " " + message_number(w) +
                           " m: no stadium has a perimeter of twice its width or less" +
                           pair_note(w_key) + pair_note(p_key));
    if (status > 0) {
      warnings_.push_back(p_key + " " + message_number(p) + " m is more than π × " + w_key + " " +
                          message_number(w) +
                          " m (rounder than a circle of that width): taken as a circle of "
                          "perimeter " +
                          message_number(p) + " m" + pair_note(w_key));
      s = circle_from_perimeter(p);
    }
    s.anterior_posterior = anterior_posterior;
    return s;
  }

  Stadium circle(const std::string& p_key) { return circle_from_perimeter(m(p_key)); }

  /// `upper` - `lower` > 0, else InputError naming `upper_key`.
  double rise(double lower, double upper, const std::string& upper_key,
              const std::string& lower_what) const {
    if (!(upper > lower))
      throw InputError(in_.file, upper_key,
                       "must be more than " + lower_what + " (" + message_number(lower) +
                           " m), found " + message_number(upper) +
                           " m: the levels go outwards from the joint" + pair_note(upper_key));
    return upper - lower;
  }

  /// Adds to `segment` the solid from stadium `bottom`, at height `start` in the segment's frame,
  /// to `top`, `h` further along y in `direction` (+1 up, -1 down).
  void add(RigidMass& segment, bool& empty, std::vector<ShapePart>& parts, const std::string& label,
           Group group, const Stadium& bottom, const Stadium& top, double start, double h,
           double direction) {
    const double rho = density_of(in_.densities, group);
    RigidMass piece = stadium_solid(rho, bottom, top, h);
    volume_ += stadium_solid_volume(bottom, top, h);
    place(segment, empty, piece, start, direction);
    const auto half_x = [](const Stadium& s) { return s.anterior_posterior ? s.r : s.t + s.r; };
    const auto half_z = [](const Stadium& s) { return s.anterior_posterior ? s.t + s.r : s.r; };
    ShapePart part;
    part.name = label;
    part.type = "ellipsoid";
    part.center = Eigen::Vector3d(0, start + direction * 0.5 * h, 0);
    part.radii = Eigen::Vector3d(0.5 * (half_x(bottom) + half_x(top)), 0.5 * h,
                                 0.5 * (half_z(bottom) + half_z(top)));
    parts.push_back(part);
    ++solids_;
  }

  void add_head(RigidMass& segment, bool& empty, std::vector<ShapePart>& parts, double r,
                double base, double h) {
    const double rho = density_of(in_.densities, kHeadNeck);
    RigidMass piece = semi_ellipsoid(rho, r, h);
    volume_ += 2.0 / 3.0 * M_PI * r * r * h;
    place(segment, empty, piece, base, 1.0);
    ShapePart part;
    part.name = "head";
    part.type = "ellipsoid";
    part.center = Eigen::Vector3d(0, base, 0);
    part.radii = Eigen::Vector3d(r, h, r);
    parts.push_back(part);
    ++solids_;
  }

  std::vector<std::string>& warnings() { return warnings_; }
  int solids() const { return solids_; }
  double volume() const { return volume_; }

 private:
  static std::string paired(const std::string& key) {
    if (key.size() < 3 || key[0] != 'L') return "";
    std::string other = key;
    const char side = key[1];
    if (side == 'a')
      other[1] = 'b';
    else if (side == 'b')
      other[1] = 'a';
    else if (side == 'j')
      other[1] = 'k';
    else if (side == 'k')
      other[1] = 'j';
    else
      return "";
    return other;
  }

  static void place(RigidMass& segment, bool& empty, RigidMass piece, double start,
                    double direction) {
    // Pointing down, the solid's CoM goes below its base; its diagonal inertia is unchanged.
    piece.com.y() = start + direction * piece.com.y();
    // A solid too thin to weigh anything (a perimeter of 1e-300 m: its volume underflows) adds
    // nothing; a segment made only of such solids is refused by name (check_segment_masses).
    if (!(piece.mass > 0.0)) return;
    segment = empty ? piece : combine(segment, piece);
    empty = false;
  }

  const YeadonInput& in_;
  std::vector<std::string> warnings_;
  int solids_ = 0;
  double volume_ = 0.0;
};

/// Refuses a model whose segment weighs nothing: its measurements in `file` give its solids no
/// volume (the file reader's bounds keep such values out; a YeadonInput made in code may not).
void check_segment_masses(const BodyModel& model, const std::string& file) {
  for (const Segment& s : model.segments)
    if (!(s.mass > 0.0))
      throw InputError(file, "",
                       "the measurements of the " + s.name + " segment give its solids no " +
                           "volume, so it has no mass (" + message_number(s.mass) +
                           " kg): are its perimeters and widths in the file's unit?");
}

struct Piece {
  RigidMass mass;
  bool empty = true;
  std::vector<ShapePart> parts;
};

Segment to_segment(const std::string& name, int parent, const std::string& joint,
                   const Eigen::Vector3d& joint_position, Piece& piece, double extent) {
  Segment s;
  s.name = name;
  s.parent = parent;
  s.joint = joint;
  s.joint_position = joint_position;
  s.mass = piece.mass.mass;
  s.com = piece.mass.com;
  s.inertia = piece.mass.inertia;
  s.shape.type = "capsule";
  s.shape.length = extent;
  s.shape.radius = std::sqrt(s.mass / (1000.0 * M_PI * std::abs(extent)));
  s.shape.parts = std::move(piece.parts);
  return s;
}

}  // namespace

std::string yeadon_densities_name(YeadonDensities densities) {
  switch (densities) {
    case YeadonDensities::kDempster:
      return "dempster";
    case YeadonDensities::kChandler:
      return "chandler";
    case YeadonDensities::kClauser:
      return "clauser";
  }
  return "";
}

const std::vector<std::string>& yeadon_measurement_names() {
  static const std::vector<std::string> names = {
      "Ls1L", "Ls2L", "Ls3L", "Ls4L", "Ls5L", "Ls6L", "Ls7L", "Ls8L", "Ls0p", "Ls1p", "Ls2p",
      "Ls3p", "Ls5p", "Ls6p", "Ls7p", "Ls0w", "Ls1w", "Ls2w", "Ls3w", "Ls4w", "Ls4d", "La2L",
      "La3L", "La4L", "La5L", "La6L", "La7L", "La0p", "La1p", "La2p", "La3p", "La4p", "La5p",
      "La6p", "La7p", "La4w", "La5w", "La6w", "La7w", "Lb2L", "Lb3L", "Lb4L", "Lb5L", "Lb6L",
      "Lb7L", "Lb0p", "Lb1p", "Lb2p", "Lb3p", "Lb4p", "Lb5p", "Lb6p", "Lb7p", "Lb4w", "Lb5w",
      "Lb6w", "Lb7w", "Lj1L", "Lj3L", "Lj4L", "Lj5L", "Lj6L", "Lj8L", "Lj9L", "Lj1p", "Lj2p",
      "Lj3p", "Lj4p", "Lj5p", "Lj6p", "Lj7p", "Lj8p", "Lj9p", "Lj8w", "Lj9w", "Lj6d", "Lk1L",
      "Lk3L", "Lk4L", "Lk5L", "Lk6L", "Lk8L", "Lk9L", "Lk1p", "Lk2p", "Lk3p", "Lk4p", "Lk5p",
      "Lk6p", "Lk7p", "Lk8p", "Lk9p", "Lk8w", "Lk9w", "Lk6d"};
  return names;
}

YeadonModel yeadon_model(const YeadonInput& input) {
  Builder b(input);
  // Left/right pairs that differ by more than half the smaller: named, used as given.
  for (const std::string& key : yeadon_measurement_names()) {
    if (key[1] != 'a' && key[1] != 'j') continue;
    const std::string note = b.pair_note(key);
    if (!note.empty()) b.warnings().push_back(note.substr(2, note.size() - 3));
  }

  // Torso levels above the hip joint centres (Ls0), m.
  const double L1 = b.m("Ls1L");
  const double L2 = L1 + b.rise(L1, b.m("Ls2L"), "Ls2L", "Ls1L");
  const double L3 = L2 + b.rise(L2, b.m("Ls3L"), "Ls3L", "Ls2L");
  const double L4 = L3 + b.rise(L3, b.m("Ls4L"), "Ls4L", "Ls3L");
  const double L5 = L4 + b.rise(L4, b.m("Ls5L"), "Ls5L", "Ls4L");
  const double h6 = b.m("Ls6L");
  const double h7 = b.rise(h6, b.m("Ls7L"), "Ls7L", "Ls6L");
  const double h8 = b.rise(b.m("Ls7L"), b.m("Ls8L"), "Ls8L", "Ls7L");

  const Stadium s0 = b.perimeter_width("Ls0p", "Ls0w");
  const Stadium s1 = b.perimeter_width("Ls1p", "Ls1w");
  const Stadium s2 = b.perimeter_width("Ls2p", "Ls2w");
  const Stadium s3 = b.perimeter_width("Ls3p", "Ls3w");
  // Shoulders: a depth and a width (the shoulder joints make a perimeter unmeasurable); the
  // acromion's stadium from them, radius 0.57 of the shoulders' (Yeadon's ISEG code).
  const double w4 = b.m("Ls4w"), d4 = b.m("Ls4d");
  if (!(w4 > d4))
    throw InputError(input.file, "Ls4w",
                     "shoulder width " + message_number(w4) + " m must exceed the depth Ls4d " +
                         message_number(d4) + " m");
  Stadium s4;
  s4.r = d4 / 2.0;
  s4.t = w4 / 2.0 - s4.r;
  Stadium s5;
  s5.r = 0.57 * s4.r;
  s5.t = w4 / 2.0 - s5.r;
  const Stadium neck = b.circle("Ls5p");
  const Stadium nose = b.circle("Ls6p");
  const Stadium ear = b.circle("Ls7p");

  Piece pelvis, abdomen, thorax;
  // Origin of pelvis and abdomen: the navel (Ls1); of the thorax: the lowest front rib (Ls2).
  b.add(pelvis.mass, pelvis.empty, pelvis.parts, "hip-navel", kAbdomenPelvis, s0, s1, -L1, L1, 1.0);
  b.add(abdomen.mass, abdomen.empty, abdomen.parts, "navel-rib", kAbdomenPelvis, s1, s2, 0.0,
        L2 - L1, 1.0);
  b.add(thorax.mass, thorax.empty, thorax.parts, "rib-nipple", kThorax, s2, s3, 0.0, L3 - L2, 1.0);
  b.add(thorax.mass, thorax.empty, thorax.parts, "nipple-shoulder", kThorax, s3, s4, L3 - L2,
        L4 - L3, 1.0);
  b.add(thorax.mass, thorax.empty, thorax.parts, "shoulder-acromion", kShoulders, s4, s5, L4 - L2,
        L5 - L4, 1.0);
  b.add(thorax.mass, thorax.empty, thorax.parts, "neck", kHeadNeck, neck, nose, L5 - L2, h6, 1.0);
  b.add(thorax.mass, thorax.empty, thorax.parts, "face", kHeadNeck, nose, ear, L5 + h6 - L2, h7,
        1.0);
  b.add_head(thorax.mass, thorax.empty, thorax.parts, ear.r, L5 + h6 + h7 - L2, h8);

  BodyModel model;
  model.name = input.name;
  model.segments.push_back(
      to_segment("abdomen", -1, "root", Eigen::Vector3d::Zero(), abdomen, L2 - L1));
  model.segments.push_back(to_segment("pelvis", 0, "lumbar", Eigen::Vector3d::Zero(), pelvis, -L1));
  model.segments.push_back(to_segment("thorax", 0, "thoracic", Eigen::Vector3d(0, L2 - L1, 0),
                                      thorax, L5 + h6 + h7 + h8 - L2));

  for (const char side : {'a', 'b'}) {  // a left (+x), b right
    const std::string k = std::string("L") + side;
    const std::string s = side == 'a' ? "_l" : "_r";
    const double x = side == 'a' ? 0.5 * w4 : -0.5 * w4;
    const double elbow = b.m(k + "2L");
    const double forearm_max = b.rise(elbow, b.m(k + "3L"), k + "3L", k + "2L");
    const double wrist = b.rise(b.m(k + "3L"), b.m(k + "4L"), k + "4L", k + "3L");
    const double thumb = b.m(k + "5L");
    const double knuckles = b.rise(thumb, b.m(k + "6L"), k + "6L", k + "5L");
    const double nails = b.rise(b.m(k + "6L"), b.m(k + "7L"), k + "7L", k + "6L");
    const Stadium a0 = b.circle(k + "0p"), a1 = b.circle(k + "1p"), a2 = b.circle(k + "2p"),
                  a3 = b.circle(k + "3p");
    const Stadium a4 = b.perimeter_width(k + "4p", k + "4w");
    const Stadium a5 = b.perimeter_width(k + "5p", k + "5w");
    const Stadium a6 = b.perimeter_width(k + "6p", k + "6w");
    const Stadium a7 = b.perimeter_width(k + "7p", k + "7w");
    Piece upper, fore;
    b.add(upper.mass, upper.empty, upper.parts, "shoulder-mid-arm", kUpperArm, a0, a1, 0.0,
          0.5 * elbow, -1.0);
    b.add(upper.mass, upper.empty, upper.parts, "mid-arm-elbow", kUpperArm, a1, a2, -0.5 * elbow,
          0.5 * elbow, -1.0);
    double y = 0.0;
    b.add(fore.mass, fore.empty, fore.parts, "elbow-forearm", kForearm, a2, a3, -y, forearm_max,
          -1.0);
    y += forearm_max;
    b.add(fore.mass, fore.empty, fore.parts, "forearm-wrist", kForearm, a3, a4, -y, wrist, -1.0);
    y += wrist;
    b.add(fore.mass, fore.empty, fore.parts, "wrist-thumb", kHand, a4, a5, -y, thumb, -1.0);
    y += thumb;
    b.add(fore.mass, fore.empty, fore.parts, "thumb-knuckles", kHand, a5, a6, -y, knuckles, -1.0);
    y += knuckles;
    b.add(fore.mass, fore.empty, fore.parts, "fingers", kHand, a6, a7, -y, nails, -1.0);
    y += nails;
    model.segments.push_back(to_segment("upper_arm" + s, 2, "shoulder" + s,
                                        Eigen::Vector3d(x, L4 - L2, 0), upper, -elbow));
    model.segments.push_back(to_segment("forearm" + s, model.size() - 1, "elbow" + s,
                                        Eigen::Vector3d(0, -elbow, 0), fore, -y));
  }

  // Hip joint centres either side of the mid-line at (t + r)/2 of the hip level's stadium, and
  // the thigh's top a circle of radius √(r·w)/2 (Yeadon's ISEG code, as the `yeadon` package).
  const double hip_x = 0.5 * (s0.t + s0.r);
  Stadium j0;
  j0.r = 0.5 * std::sqrt(s0.r * s0.width());
  for (const char side : {'j', 'k'}) {  // j left, k right
    const std::string k = std::string("L") + side;
    const std::string s = side == 'j' ? "_l" : "_r";
    const double x = side == 'j' ? hip_x : -hip_x;
    const double crotch = b.m(k + "1L");
    const double knee = b.rise(crotch, b.m(k + "3L"), k + "3L", k + "1L") + crotch;
    const double calf = b.rise(knee, b.m(k + "4L"), k + "4L", k + "3L");
    const double ankle = b.rise(b.m(k + "4L"), b.m(k + "5L"), k + "5L", k + "4L");
    const double heel = b.m(k + "6L");
    const double ball = b.rise(heel, b.m(k + "8L"), k + "8L", k + "6L") + heel;
    const double toes = b.rise(ball, b.m(k + "9L"), k + "9L", k + "8L");
    const Stadium l1 = b.circle(k + "1p"), l2 = b.circle(k + "2p"), l3 = b.circle(k + "3p"),
                  l4 = b.circle(k + "4p"), l5 = b.circle(k + "5p");
    const Stadium l6 = b.perimeter_width(k + "6p", k + "6d", true);
    const Stadium l7 = b.circle(k + "7p");
    const Stadium l8 = b.perimeter_width(k + "8p", k + "8w");
    const Stadium l9 = b.perimeter_width(k + "9p", k + "9w");
    Piece thigh, shank, foot;
    const double mid = 0.5 * (crotch + knee);
    b.add(thigh.mass, thigh.empty, thigh.parts, "hip-crotch", kThigh, j0, l1, 0.0, crotch, -1.0);
    b.add(thigh.mass, thigh.empty, thigh.parts, "crotch-mid-thigh", kThigh, l1, l2, -crotch,
          mid - crotch, -1.0);
    b.add(thigh.mass, thigh.empty, thigh.parts, "mid-thigh-knee", kThigh, l2, l3, -mid, knee - mid,
          -1.0);
    b.add(shank.mass, shank.empty, shank.parts, "knee-calf", kLowerLeg, l3, l4, 0.0, calf, -1.0);
    b.add(shank.mass, shank.empty, shank.parts, "calf-ankle", kLowerLeg, l4, l5, -calf, ankle,
          -1.0);
    const double arch = 0.5 * (heel + ball);
    b.add(foot.mass, foot.empty, foot.parts, "ankle-heel", kFoot, l5, l6, 0.0, heel, -1.0);
    b.add(foot.mass, foot.empty, foot.parts, "heel-arch", kFoot, l6, l7, -heel, arch - heel, -1.0);
    b.add(foot.mass, foot.empty, foot.parts, "arch-ball", kFoot, l7, l8, -arch, ball - arch, -1.0);
    b.add(foot.mass, foot.empty, foot.parts, "toes", kFoot, l8, l9, -ball, toes, -1.0);
    model.segments.push_back(
        to_segment("thigh" + s, 1, "hip" + s, Eigen::Vector3d(x, -L1, 0), thigh, -knee));
    model.segments.push_back(to_segment("shank" + s, model.size() - 1, "knee" + s,
                                        Eigen::Vector3d(0, -knee, 0), shank, -(calf + ankle)));
    // The foot hangs from the ankle as in Yeadon's model (pointed); its extent for the standing
    // height is the heel, about the ankle's height above the sole.
    model.segments.push_back(to_segment("foot" + s, model.size() - 1, "ankle" + s,
                                        Eigen::Vector3d(0, -(calf + ankle), 0), foot, -heel));
  }

  check_segment_masses(model, input.file);
  YeadonModel out;
  out.solids = b.solids();
  out.volume = b.volume();
  const double mass = model.total_mass();
  if (input.total_mass > 0.0) {
    out.density_scale = input.total_mass / mass;
    for (Segment& seg : model.segments) {
      seg.mass *= out.density_scale;
      seg.inertia *= out.density_scale;
    }
  }
  model.source =
      "Yeadon 1990, 'The simulation of aerial movement II: a mathematical inertia model of the "
      "human body', J. Biomech. 23(1):67-74: 40 stadium solids and a semi-ellipsoid head from "
      "the 95 measurements of " +
      input.file + ", " + yeadon_densities_name(input.densities) + " segment densities" +
      (input.total_mass > 0.0 ? " scaled by " + message_number(out.density_scale) +
                                    " to a body mass of " + message_number(input.total_mass) + " kg"
                              : std::string()) +
      ". abdomen = umbilicus to lowest front rib (Ls1-Ls2); pelvis = hip joint centres to "
      "umbilicus (Ls0-Ls1); thorax = Ls2 to the top of the head with the shoulders, neck and "
      "head; upper arm = shoulder to elbow; forearm = elbow to fingernails with the hand; thigh "
      "= hip to knee; shank = knee to ankle; foot = ankle to toenails, pointed (along the "
      "shank, as in Yeadon's model). Composed exactly (parallel-axis theorem). Drawing: an "
      "ellipsoid per solid.";
  out.model = std::move(model);
  out.warnings = std::move(b.warnings());
  return out;
}

}  // namespace saltus
