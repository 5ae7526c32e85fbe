#include "saltus/body/athlete_model.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "saltus/base/text_format.h"
#include "saltus/body/mass_properties.h"

namespace saltus {

namespace {

using P = DeLevaPart;

/// Density that turns a segment's mass and length into a drawing radius, kg/m³ (about water's:
/// the body's is 1000-1100).
constexpr double kDrawingDensity = 1000.0;

/// de Leva's table scaled to one athlete.
class ScaledTable {
 public:
  explicit ScaledTable(const AthleteSize& size) : size_(size) {
    double percent = 0.0;
    for (const DeLevaRow& row : de_leva_rows(size.sex)) {
      if (row.part == P::kTrunk || row.part == P::kTrunkMids) continue;
      const bool paired = row.part != P::kHead && row.part != P::kUpperTrunk &&
                          row.part != P::kMiddleTrunk && row.part != P::kLowerTrunk;
      percent += (paired ? 2.0 : 1.0) * row.mass_percent;
    }
    mass_sum_ = percent / 100.0;
  }

  const DeLevaRow& row(P part) const { return de_leva_row(size_.sex, part); }
  /// m
  double length(P part) const {
    return row(part).length_mm / 1000.0 * size_.height_m / de_leva_stature(size_.sex);
  }
  /// kg, the fractions made to sum to 1.
  double mass(P part) const { return row(part).mass_percent / 100.0 / mass_sum_ * size_.mass_kg; }
  /// Distance of the CoM from the row's first landmark, m.
  double com(P part) const { return row(part).com_percent / 100.0 * length(part); }
  /// Principal radii of gyration along Saltus's segment axes (x medio-lateral, y along the
  /// segment, z antero-posterior), m, over the segment's own length (`length_m`).
  Eigen::Vector3d radii(P part, double length_m) const {
    const DeLevaRow& r = row(part);
    return Eigen::Vector3d(r.r_transverse, r.r_longitudinal, r.r_sagittal) / 100.0 * length_m;
  }
  Eigen::Vector3d radii(P part) const { return radii(part, length(part)); }
  /// A piece of this part whose CoM is at height `com_y` on the segment's axis.
  RigidMass piece(P part, double com_y) const {
    return rigid_mass_from_radii(mass(part), Eigen::Vector3d(0.0, com_y, 0.0), radii(part));
  }
  double mass_sum() const { return mass_sum_; }

 private:
  AthleteSize size_;
  double mass_sum_ = 1.0;
};

Segment make_segment(const std::string& name, int parent, const std::string& joint,
                     const Eigen::Vector3d& joint_position, const RigidMass& mass) {
  Segment s;
  s.name = name;
  s.parent = parent;
  s.joint = joint;
  s.joint_position = joint_position;
  s.mass = mass.mass;
  s.com = mass.com;
  s.inertia = mass.inertia;
  return s;
}

/// A capsule along y of `length` (signed) whose volume at kDrawingDensity holds `mass`.
SegmentShape capsule_for(double mass, double length) {
  SegmentShape shape;
  shape.type = "capsule";
  shape.length = length;
  shape.radius = std::sqrt(mass / (kDrawingDensity * M_PI * std::abs(length)));
  return shape;
}

ShapePart ellipsoid(const std::string& name, const Eigen::Vector3d& center,
                    const Eigen::Vector3d& radii) {
  ShapePart part;
  part.name = name;
  part.type = "ellipsoid";
  part.center = center;
  part.radii = radii;
  return part;
}

ShapePart capsule_part(const std::string& name, const Eigen::Vector3d& center, double length,
                       double radius) {
  ShapePart part;
  part.name = name;
  part.type = "capsule";
  part.center = center;
  part.length = length;
  part.radius = radius;
  return part;
}

std::string default_name(const AthleteSize& size) {
  char text[96];
  std::snprintf(text, sizeof text, "de-leva-%s-%.2fm-%.1fkg", sex_name(size.sex).c_str(),
                size.height_m, size.mass_kg);
  return text;
}

std::string source_text(const AthleteSize& size, double mass_sum, double neck) {
  return "de Leva 1996, 'Adjustments to Zatsiorsky-Seluyanov's segment inertia parameters', J. "
         "Biomech. 29(9), Table 4 (" +
         sex_name(size.sex) + "), for a " + message_number(size.height_m) + " m, " +
         message_number(size.mass_kg) + " kg athlete: lengths his mean lengths x stature / " +
         message_number(de_leva_stature(size.sex)) +
         " m; masses his fractions of body mass divided by their sum " + message_number(mass_sum) +
         "; CoMs and principal radii of gyration his fractions of each length (sagittal radius "
         "about z, transverse about x, longitudinal about y). abdomen = middle trunk XYPH-OMPH "
         "(lumbar joint at the navel); pelvis = lower trunk OMPH-MIDH; thorax = upper trunk "
         "SUPR-XYPH + head VERT-MIDG (its mass includes the neck), the head's vertex at the top "
         "of the stature, the neck between them " +
         message_number(neck) +
         " m and massless; forearm = forearm EJC-WJC + hand WJC-MET3; thigh HJC-KJC; shank "
         "KJC-AJC; the foot hangs from the ankle along -y as in the bundled model, its length "
         "the ankle height 0.039 x stature (Drillis & Contini), its CoM at de Leva's fraction "
         "of that length, its radii his fractions of his foot length HEEL-TTIP. Shoulders at "
         "his mid-shoulder height MIDS-MIDH, shoulder and hip joint centres 0.1059 and 0.05 x "
         "stature either side (the bundled model's proportions). Composition by the "
         "parallel-axis theorem. Drawing: capsules holding each segment's mass at 1000 kg/m3, "
         "parts sized like the bundled model's.";
}

}  // namespace

BodyModel de_leva_model(const AthleteSize& size) {
  if (!(size.height_m > 0.0) || !(size.mass_kg > 0.0) || !std::isfinite(size.height_m) ||
      !std::isfinite(size.mass_kg))
    throw std::invalid_argument("de_leva_model: height and mass must be positive");
  const ScaledTable t(size);
  const double H = size.height_m;
  const double k = H / kReferenceStature;
  // Drawing widths: the bundled model's, with the cross-section following mass per length.
  const double kw = std::sqrt(size.mass_kg / kReferenceMass / k);

  const double l_mid = t.length(P::kMiddleTrunk);
  const double l_low = t.length(P::kLowerTrunk);
  const double l_up = t.length(P::kUpperTrunk);
  const double l_head = t.length(P::kHead);
  const double l_upper_arm = t.length(P::kUpperArm);
  const double l_forearm = t.length(P::kForearm);
  const double l_hand = t.length(P::kHand);
  const double l_thigh = t.length(P::kThigh);
  const double l_shank = t.length(P::kShank);
  const double ankle = kAnkleHeight * H;
  // Xiphion to vertex: what the stature leaves above the navel's segments.
  const double thorax_length = H - (ankle + l_shank + l_thigh + l_low + l_mid);
  const double neck = thorax_length - l_up - l_head;
  if (!(neck >= 0.0)) throw std::logic_error("de_leva_model: the table leaves no room for a neck");

  BodyModel m;
  m.name = size.name.empty() ? default_name(size) : size.name;
  m.source = source_text(size, t.mass_sum(), neck);

  // abdomen (root): origin at the navel (OMPH), xiphion at +l_mid; de Leva's CoM is from XYPH.
  Segment abdomen = make_segment("abdomen", -1, "root", Eigen::Vector3d::Zero(),
                                 t.piece(P::kMiddleTrunk, l_mid - t.com(P::kMiddleTrunk)));
  abdomen.shape = capsule_for(abdomen.mass, l_mid);
  abdomen.shape.parts = {ellipsoid("abdomen", Eigen::Vector3d(0, 0.5 * l_mid, 0),
                                   Eigen::Vector3d(0.145 * kw, 1.09 * l_mid, 0.105 * kw))};
  m.segments.push_back(abdomen);

  Segment pelvis = make_segment("pelvis", 0, "lumbar", Eigen::Vector3d::Zero(),
                                t.piece(P::kLowerTrunk, -t.com(P::kLowerTrunk)));
  pelvis.shape = capsule_for(pelvis.mass, -l_low);
  pelvis.shape.parts = {ellipsoid("pelvis", Eigen::Vector3d(0, -0.42 * l_low, -0.005 * kw),
                                  Eigen::Vector3d(0.155 * kw, 0.98 * l_low, 0.11 * kw))};
  m.segments.push_back(pelvis);

  // thorax: origin at the xiphion; the upper trunk's CoM is measured down from SUPR (at l_up),
  // the head's down from the vertex (at thorax_length).
  const RigidMass upper_trunk = t.piece(P::kUpperTrunk, l_up - t.com(P::kUpperTrunk));
  const RigidMass head = t.piece(P::kHead, thorax_length - t.com(P::kHead));
  Segment thorax = make_segment("thorax", 0, "thoracic", Eigen::Vector3d(0, l_mid, 0),
                                combine(upper_trunk, head));
  thorax.shape = capsule_for(upper_trunk.mass, thorax_length);
  const double head_centre = thorax_length - 0.52 * l_head;
  const double head_bottom = head_centre - 0.52 * l_head;
  thorax.shape.parts = {
      ellipsoid("chest", Eigen::Vector3d(0, 0.6 * l_up, 0),
                Eigen::Vector3d(0.165 * kw, 1.14 * l_up, 0.115 * kw)),
      capsule_part("neck", Eigen::Vector3d(0, 0.5 * (l_up + head_bottom), 0),
                   std::max(0.01, head_bottom - l_up), 0.05 * k),
      ellipsoid("head", Eigen::Vector3d(0, head_centre, 0.015 * k),
                Eigen::Vector3d(0.078 * k, 0.52 * l_head, 0.095 * k)),
      ellipsoid("nose", Eigen::Vector3d(0, thorax_length - 0.55 * l_head, 0.108 * k),
                Eigen::Vector3d(0.016 * k, 0.024 * k, 0.018 * k))};
  m.segments.push_back(thorax);

  // Shoulders at de Leva's mid-shoulder height above the hips (MIDS-MIDH), in the thorax frame.
  const double shoulder_y = t.length(P::kTrunkMids) - l_low - l_mid;
  for (const double side : {1.0, -1.0}) {  // +x is the body's left
    const std::string s = side > 0 ? "_l" : "_r";
    const int thorax_index = 2;
    Segment upper_arm = make_segment("upper_arm" + s, thorax_index, "shoulder" + s,
                                     Eigen::Vector3d(side * kShoulderHalfWidth * H, shoulder_y, 0),
                                     t.piece(P::kUpperArm, -t.com(P::kUpperArm)));
    upper_arm.shape = capsule_for(upper_arm.mass, -l_upper_arm);
    m.segments.push_back(upper_arm);

    const RigidMass forearm_alone = t.piece(P::kForearm, -t.com(P::kForearm));
    const RigidMass hand = t.piece(P::kHand, -(l_forearm + t.com(P::kHand)));
    Segment forearm =
        make_segment("forearm" + s, m.size() - 1, "elbow" + s, Eigen::Vector3d(0, -l_upper_arm, 0),
                     combine(forearm_alone, hand));
    forearm.shape = capsule_for(forearm_alone.mass, -(l_forearm + l_hand));
    forearm.shape.parts = {capsule_part("forearm", Eigen::Vector3d(0, -0.495 * l_forearm, 0),
                                        -0.76 * l_forearm, 0.036 * kw),
                           ellipsoid("hand", Eigen::Vector3d(0, -(l_forearm + 0.8 * l_hand), 0),
                                     Eigen::Vector3d(0.022 * kw, 0.085 * k, 0.045 * k))};
    m.segments.push_back(forearm);
  }

  const double l_foot = t.length(P::kFoot);
  for (const double side : {1.0, -1.0}) {
    const std::string s = side > 0 ? "_l" : "_r";
    Segment thigh = make_segment("thigh" + s, 1, "hip" + s,
                                 Eigen::Vector3d(side * kHipHalfWidth * H, -l_low, 0),
                                 t.piece(P::kThigh, -t.com(P::kThigh)));
    thigh.shape = capsule_for(thigh.mass, -l_thigh);
    m.segments.push_back(thigh);

    Segment shank =
        make_segment("shank" + s, m.size() - 1, "knee" + s, Eigen::Vector3d(0, -l_thigh, 0),
                     t.piece(P::kShank, -t.com(P::kShank)));
    shank.shape = capsule_for(shank.mass, -l_shank);
    m.segments.push_back(shank);

    // The foot hangs from the ankle (the bundled model's convention): its CoM at de Leva's
    // fraction of the ankle height, its radii his fractions of his own foot length.
    const RigidMass foot_mass = rigid_mass_from_radii(
        t.mass(P::kFoot), Eigen::Vector3d(0, -t.row(P::kFoot).com_percent / 100.0 * ankle, 0),
        t.radii(P::kFoot, l_foot));
    Segment foot = make_segment("foot" + s, m.size() - 1, "ankle" + s,
                                Eigen::Vector3d(0, -l_shank, 0), foot_mass);
    foot.shape = capsule_for(foot.mass, -ankle);
    foot.shape.parts = {ellipsoid("foot", Eigen::Vector3d(0, -0.337 * l_foot, 0.015 * k),
                                  Eigen::Vector3d(0.042 * kw, 0.456 * l_foot, 0.05 * k))};
    m.segments.push_back(foot);
  }
  return m;
}

BodyModel scale_body_model(const BodyModel& model, double length_factor, double mass_factor,
                           const std::string& name) {
  if (!(length_factor > 0.0) || !(mass_factor > 0.0) || !std::isfinite(length_factor) ||
      !std::isfinite(mass_factor))
    throw std::invalid_argument("scale_body_model: factors must be positive and finite");
  BodyModel scaled = model;
  scaled.name = name;
  scaled.source = model.source + " Scaled: lengths x " + message_number(length_factor) +
                  ", masses x " + message_number(mass_factor) + ".";
  const double k = length_factor;
  for (Segment& s : scaled.segments) {
    s.joint_position *= k;
    s.mass *= mass_factor;
    s.com *= k;
    s.inertia *= mass_factor * k * k;
    s.shape.length *= k;
    s.shape.radius *= k;
    for (ShapePart& part : s.shape.parts) {
      part.center *= k;
      part.radii *= k;
      part.length *= k;
      part.radius *= k;
    }
  }
  return scaled;
}

}  // namespace saltus
