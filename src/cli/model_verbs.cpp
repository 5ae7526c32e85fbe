#include "model_verbs.h"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "saltus/base/text_format.h"
#include "saltus/body/joint_strength.h"
#include "saltus/body/segment_names.h"
#include "saltus/formats/model_file.h"
#include "saltus/use_cases/athlete_models.h"

namespace saltus_cli {

namespace {

std::string absolute_model_path(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

void print_summary(const saltus::ModelSummary& s) {
  const saltus::StandingBody& b = s.standing;
  const Eigen::Matrix3d& I = b.body.inertia;
  std::printf("  %.2f kg, standing height %.3f m\n", s.total_mass, b.height());
  std::printf(
      "  whole-body CoM, standing: %.3f m above the soles (%.1f %% of the height), (%.3f, %.3f, "
      "%.3f) m in the root's frame\n",
      b.com_height(), 100.0 * b.com_height() / b.height(), b.body.com.x(), b.body.com.y(),
      b.body.com.z());
  std::printf(
      "  whole-body inertia about the CoM, standing: %.3f kg·m² about x (somersault), %.3f about "
      "y (twist), %.3f about z (cartwheel); principal %.3f, %.3f, %.3f\n",
      I(0, 0), I(1, 1), I(2, 2), b.principal_moments.x(), b.principal_moments.y(),
      b.principal_moments.z());
  std::printf("  %-22s %8s %6s %8s  %-26s %s\n", "segment", "mass kg", "%", "length m",
              "CoM (x, y, z) m", "principal moments kg·m²");
  for (const saltus::SegmentSummary& r : s.segments)
    std::printf("  %-22s %8.3f %6.2f %8.3f  (%6.3f, %6.3f, %6.3f)  %.4g, %.4g, %.4g\n",
                r.label.c_str(), r.mass, r.mass_percent, r.length, r.com.x(), r.com.y(), r.com.z(),
                r.principal_moments.x(), r.principal_moments.y(), r.principal_moments.z());
}

/// The athlete's strength: whose, then each covered joint direction's isometric peak.
void print_strength(const saltus::BodyModel& model) {
  std::printf("  strength: %s\n", saltus::strength_reference_words(model.strength).c_str());
  std::printf("  %-34s %10s  %s\n", "joint direction", "peak N·m", "source (curve)");
  for (const saltus::StrengthRow& row : saltus::strength_rows(model))
    std::printf("  %-34s %10.1f  %s%s\n",
                (saltus::joint_label(row.joint) + " " + row.direction).c_str(), row.curve.peak_Nm,
                row.curve.source.c_str(), row.curve.measured ? ", measured" : "");
}

void print_written(const char* verb, const saltus::BodyModel& model, const std::string& path) {
  std::printf("saltus model %s: %s\n", verb, saltus::printable(model.name).c_str());
  print_summary(saltus::summarize_model(model));
  std::printf("  wrote %s\n", saltus::printable(absolute_model_path(path)).c_str());
}

int run_new(const ModelArgs& args) {
  saltus::AthleteSize size;
  size.height_m = args.height;
  size.mass_kg = args.mass;
  size.sex = saltus::parse_sex(args.sex, "--sex");
  size.name = args.name;
  saltus::BodyModel model = saltus::new_athlete_model(size);
  model.strength = saltus::strength_from_flags(args.strength, args.sex, args.age);
  saltus::write_athlete_model(args.out_path, model);
  if (!args.quiet) print_written("new", model, args.out_path);
  return 0;
}

int run_info(const ModelArgs& args) {
  const saltus::BodyModel model = saltus::load_model_argument(args.model);
  const saltus::ModelSummary summary = saltus::summarize_model(model);
  if (args.json) {
    std::printf("%s\n", saltus::model_summary_to_json(summary).dump(2).c_str());
    return 0;
  }
  std::printf("saltus model info: %s (%s)\n", saltus::printable(model.name).c_str(),
              saltus::printable(args.model).c_str());
  print_summary(summary);
  print_strength(model);
  return 0;
}

int run_scale(const ModelArgs& args) {
  const saltus::BodyModel source = saltus::load_model_argument(args.model);
  const saltus::BodyModel model =
      saltus::scaled_athlete_model(source, args.height, args.mass, args.name);
  saltus::write_athlete_model(args.out_path, model);
  if (!args.quiet) print_written("scale", model, args.out_path);
  return 0;
}

int run_yeadon(const ModelArgs& args) {
  saltus::YeadonModel made =
      saltus::yeadon_athlete_model(args.model, args.densities, args.yeadon_mass, args.name);
  made.model.strength = saltus::strength_from_flags(args.strength, args.sex, args.age);
  saltus::write_athlete_model(args.out_path, made.model);
  if (!args.quiet) {
    print_written("yeadon", made.model, args.out_path);
    std::printf("  %d solids, %.4f m³, %s densities", made.solids, made.volume,
                args.densities.c_str());
    if (made.density_scale != 1.0)
      std::printf(" scaled by %.4f to the given mass", made.density_scale);
    std::printf("\n");
  }
  std::fflush(stdout);
  for (const std::string& warning : made.warnings)
    std::fprintf(stderr, "saltus model yeadon: warning: %s: %s\n",
                 saltus::printable(args.model).c_str(), warning.c_str());
  return 0;
}

void add_size(CLI::App* cmd, ModelArgs& a) {
  cmd->add_option("--height", a.height, "standing height (stature), m")->required();
  cmd->add_option("--mass", a.mass, "body mass, kg")->required();
}

void add_strength(CLI::App* cmd, ModelArgs& a) {
  cmd->add_option("--age", a.age, "age, years (Anderson 2007's age groups for the legs' strength)")
      ->capture_default_str();
  cmd->add_option("--strength", a.strength,
                  "whose strength: population (Anderson 2007's by sex and age, the upper body "
                  "scaled alike) or elite-gymnast")
      ->capture_default_str();
}

void add_out(CLI::App* cmd, ModelArgs& a) {
  cmd->add_option("--out", a.out_path,
                  "model file to write (*.model.json); replaces only a Saltus model file")
      ->required();
  cmd->add_option("--name", a.name, "the model's name (default: from the sex, height and mass)");
  cmd->add_flag("--quiet,-q", a.quiet, "print nothing on success");
}

}  // namespace

void add_model_verbs(CLI::App& app, ModelVerbs& verbs) {
  CLI::App* model = app.add_subcommand(
      "model",
      "Body models of particular athletes: `model new` (from height, mass and sex), `model "
      "yeadon` (from 95 measurements), `model info`, `model scale`");
  model->require_subcommand(1);

  ModelArgs& n = verbs.new_args;
  CLI::App* create = model->add_subcommand(
      "new",
      "A body model from a person's height, mass and sex: segment lengths, masses, centres of "
      "mass and radii of gyration from de Leva 1996 (Table 4), on the bundled model's 13 "
      "segments; writes a model file every verb takes with --model");
  add_size(create, n);
  create->add_option("--sex", n.sex, "female or male (de Leva's table for that sex)")
      ->required()
      ->check(CLI::IsMember({"female", "male"}));
  add_strength(create, n);
  add_out(create, n);
  verbs.new_command = create;

  ModelArgs& i = verbs.info_args;
  CLI::App* info = model->add_subcommand(
      "info",
      "A model's segments (mass kg and %, length, CoM, principal inertias), total mass, standing "
      "height, whole-body CoM and inertia standing");
  info->add_option("MODEL", i.model, "model file, or a bundled model's name")->required();
  info->add_flag("--json", i.json, "print the summary as JSON (saltus-model-info/1)");
  verbs.info_command = info;

  ModelArgs& s = verbs.scale_args;
  CLI::App* scale = model->add_subcommand(
      "scale",
      "A model scaled to another person: lengths in proportion to the standing height, masses "
      "to the body mass, inertias as mass × length²");
  scale->add_option("MODEL", s.model, "model file, or a bundled model's name")->required();
  add_size(scale, s);
  add_out(scale, s);
  verbs.scale_command = scale;

  ModelArgs& y = verbs.yeadon_args;
  CLI::App* yeadon = model->add_subcommand(
      "yeadon",
      "Yeadon's 1990 geometric model of a person from 95 measurements (the `yeadon` package's "
      "text format): 40 stadium solids and a semi-ellipsoid with segment densities, composed "
      "onto the 13 segments");
  yeadon->add_option("MEASUREMENTS", y.model, "measurement file (Key=value or Key: value lines)")
      ->required();
  yeadon->add_option("--densities", y.densities, "segment densities: dempster, chandler, clauser")
      ->check(CLI::IsMember({"dempster", "chandler", "clauser"}));
  yeadon->add_option("--mass", y.yeadon_mass,
                     "body mass, kg: scales every density to it (default: the file's totalmass, "
                     "else the densities' own mass)");
  y.sex = "male";
  yeadon->add_option("--sex", y.sex, "female or male, for the strength tables")
      ->capture_default_str();
  add_strength(yeadon, y);
  add_out(yeadon, y);
  verbs.yeadon_command = yeadon;
}

std::optional<int> run_model_verbs(const ModelVerbs& verbs) {
  if (verbs.new_command && verbs.new_command->parsed()) return run_new(verbs.new_args);
  if (verbs.info_command && verbs.info_command->parsed()) return run_info(verbs.info_args);
  if (verbs.scale_command && verbs.scale_command->parsed()) return run_scale(verbs.scale_args);
  if (verbs.yeadon_command && verbs.yeadon_command->parsed()) return run_yeadon(verbs.yeadon_args);
  return std::nullopt;
}

}  // namespace saltus_cli
