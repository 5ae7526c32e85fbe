#pragma once
// A seeded family of athletes (issue 25): de Leva's people from 1.2 to 2.0 m and 25 to 120 kg
// (a plausible body mass index, both sexes) and Yeadon's measured man with every measurement
// scaled by its own random factor in [0.9, 1.1], each written as a model file under the
// process's temporary folder and read back by the model reader. Shared by the family's tests
// (tests/integration/athlete_family_test.cpp) and its benchmark (tests/bench/family_bench.cpp),
// so both fly the same athletes. Free of GoogleTest: what a test checks about the family's
// making (the sizes asked for, the measurements scaled, the files refused) is returned with it.

#include <algorithm>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "saltus/base/input_error.h"
#include "saltus/body/body_model.h"
#include "saltus/formats/model_file.h"
#include "saltus/use_cases/athlete_models.h"
#include "support/temp_path.h"

namespace saltus::test {

struct FamilyMember {
  std::string path;  ///< its model file
  BodyModel model;
  std::optional<AthleteSize> size;  ///< de Leva's people: the height, mass and sex asked for
};

/// A perturbed Yeadon file the model reader refused, and its message.
struct RefusedMeasurements {
  std::string measurements;  ///< the file's path
  std::string what;
};

struct AthleteFamily {
  std::vector<FamilyMember> members;  ///< 8 of de Leva's people, then 4 measured men
  std::vector<int> scaled;            ///< per perturbed Yeadon file drawn, measurements scaled
  std::vector<RefusedMeasurements> refused;
};

/// Writes `examples/athletes/yeadon-male1.txt` to `path` with every measurement (not the
/// conversion factor nor the total mass) multiplied by a factor drawn from [0.9, 1.1]: each
/// perimeter, width and depth its own, the lengths one for the file. A limb's lengths run from
/// one joint to its successive levels (shoulder 47.2 cm, acromion 50.2 cm from the hip): errors
/// of their own would put the levels out of order, a body no one has, which the reader refuses.
/// Returns how many measurements it scaled (Yeadon's 95).
inline int perturbed_yeadon_file(std::mt19937& random, const std::string& path) {
  std::uniform_real_distribution<double> factor(0.9, 1.1);
  const double length_factor = factor(random);
  std::ifstream in(std::string(SALTUS_EXAMPLES_DIR) + "/athletes/yeadon-male1.txt");
  std::ostringstream out;
  std::string line;
  int scaled = 0;
  while (std::getline(in, line)) {
    const std::size_t separator = line.find_first_of("=:");
    const std::string key = line.substr(0, line.find_first_of(" =:"));
    if (line.empty() || line[0] == '#' || separator == std::string::npos ||
        key == "measurementconversionfactor" || key == "totalmass") {
      out << line << '\n';
      continue;
    }
    const double value = std::stod(line.substr(separator + 1));
    std::ostringstream number;
    number.precision(17);
    number << value * (key.back() == 'L' ? length_factor : factor(random));
    out << key << '=' << number.str() << '\n';
    ++scaled;
  }
  std::ofstream(path) << out.str();
  return scaled;
}

/// The family, seeded (the same 12 athletes in every process), made on first use: the corners
/// of de Leva's range (1.2 m and 25 kg, 2.0 m and 120 kg: body mass index 17 and 30), six
/// heights spread over it with a body mass index drawn for each, sexes alternating; then the
/// first four perturbed Yeadon files the reader accepts. A hand's perimeter is only 13 % above
/// twice its width: independent 10 % errors can make a level no stadium has, which the reader
/// refuses (InputError naming the file and the key); such files are listed in `refused`.
inline const AthleteFamily& athlete_family() {
  static const AthleteFamily family = [] {
    std::mt19937 random(25);
    std::uniform_real_distribution<double> unit(0.0, 1.0), bmi(16.0, 30.0);
    AthleteFamily out;
    for (int i = 0; i < 8; ++i) {
      AthleteSize size;
      size.height_m = i == 0 ? 1.2 : i == 1 ? 2.0 : 1.2 + 0.8 * (i - 2 + unit(random)) / 6.0;
      size.mass_kg = i == 0 ? 25.0
                     : i == 1
                         ? 120.0
                         : std::clamp(bmi(random) * size.height_m * size.height_m, 25.0, 120.0);
      size.sex = i % 2 ? Sex::kMale : Sex::kFemale;
      size.name = "family-" + std::to_string(i);
      const std::string path = temp_path(size.name + ".model.json").string();
      write_athlete_model(path, new_athlete_model(size));
      out.members.push_back({path, load_body_model(path), size});
    }
    for (int draw = 0; out.members.size() < 12 && draw < 20; ++draw) {
      const std::string name = "measured-" + std::to_string(draw);
      const std::string measurements = temp_path(name + ".txt").string();
      out.scaled.push_back(perturbed_yeadon_file(random, measurements));
      const std::string path = temp_path(name + ".model.json").string();
      try {
        write_athlete_model(path, yeadon_athlete_model(measurements, "dempster", 0.0, name).model);
      } catch (const InputError& e) {
        out.refused.push_back({measurements, e.what()});
        continue;
      }
      out.members.push_back({path, load_body_model(path), std::nullopt});
    }
    return out;
  }();
  return family;
}

}  // namespace saltus::test
