// Tests for reading Yeadon's measurement files (formats/yeadon_measurements_file.h): both real
// files of examples/athletes (two syntaxes), and every kind of bad line named by line and key.

#include "saltus/formats/yeadon_measurements_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "saltus/base/input_error.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

std::string ymf_text(const std::string& name) {
  std::ifstream in(std::string(SALTUS_EXAMPLES_DIR) + "/athletes/" + name);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The InputError's JSON path (here: "line N: key" or the key) when parsing `text`, or "".
std::string ymf_error_at(const std::string& text, std::string* problem = nullptr) {
  try {
    parse_yeadon_measurements(text, "m.txt");
  } catch (const InputError& e) {
    if (problem) *problem = e.problem();
    return e.json_path();
  }
  return "";
}

TEST(YeadonMeasurementsFile, ReadsBothRealFilesInMetres) {
  const YeadonMeasurementsFile male =
      load_yeadon_measurements(std::string(SALTUS_EXAMPLES_DIR) + "/athletes/yeadon-male1.txt");
  EXPECT_EQ(male.measured.size(), 95u);
  EXPECT_DOUBLE_EQ(male.conversion_factor, 0.01);
  EXPECT_NEAR(male.measured.at("Ls1L"), 0.049, 1e-15);  // Ls1L=4.9 (cm)
  EXPECT_EQ(male.total_mass, 0.0);
  const YeadonMeasurementsFile female = parse_yeadon_measurements(
      ymf_text("yeadon-female1.txt"), "yeadon-female1.txt");  // "Key: value", totalmass: -1
  EXPECT_EQ(female.measured.size(), 95u);
  EXPECT_NEAR(female.measured.at("Lb4w"), 0.141, 1e-15);
  EXPECT_EQ(female.total_mass, 0.0);
}

TEST(YeadonMeasurementsFile, BadLinesAreNamedByLineAndKey) {
  const std::string good = ymf_text("yeadon-male1.txt");
  std::string problem;
  // A misspelled key: the nearest known one is suggested.
  std::string text = good;
  text.replace(text.find("Ls2L="), 5, "Ls2l=");
  EXPECT_NE(ymf_error_at(text, &problem).find("Ls2l"), std::string::npos);
  EXPECT_NE(problem.find("Ls2L"), std::string::npos) << problem;
  // A missing key (the line removed).
  text = good;
  const auto at = text.find("Lk6d=");
  text.erase(at, text.find('\n', at) - at);
  EXPECT_EQ(ymf_error_at(text), "Lk6d");
  // Negative or zero, not a number, twice, no conversion factor, an absurd total mass.
  text = good + "\n";
  EXPECT_EQ(ymf_error_at(std::string(good).replace(good.find("Ls3L=33.4"), 9, "Ls3L=-3.4"))
                    .find("Ls3L") != std::string::npos,
            true);
  EXPECT_NE(ymf_error_at(good + "Ls0p=abc\n", &problem).find("Ls0p"), std::string::npos);
  EXPECT_NE(problem.find("number"), std::string::npos);
  EXPECT_NE(ymf_error_at(good + "Ls0p=80\n", &problem).find("Ls0p"), std::string::npos);
  EXPECT_NE(problem.find("twice"), std::string::npos);
  std::string no_factor = good;
  no_factor.replace(no_factor.find("measurementconversionfactor"), 1, "#");
  EXPECT_EQ(ymf_error_at(no_factor), "measurementconversionfactor");
  EXPECT_NE(ymf_error_at(good + "totalmass = 900\n").find("totalmass"), std::string::npos);
  EXPECT_NE(ymf_error_at(good + "just words\n").find("line"), std::string::npos);
  // Values in mm read as cm: a 4.9 m hip-to-navel length.
  std::string metres = good;
  metres.replace(metres.find("= .01"), 5, "= 1.");
  EXPECT_NE(ymf_error_at(metres, &problem), "");
  EXPECT_NE(problem.find("measurementconversionfactor"), std::string::npos) << problem;
}

TEST(YeadonMeasurementsFile, RepeatedTotalMassTinyLengthsAndNulBytesAreRefused) {
  const std::string good = ymf_text("yeadon-male1.txt");
  std::string problem;
  // totalmass twice, like every other repeated key (once the last one won).
  EXPECT_EQ(
      ymf_error_at(good + "totalmass = 70\ntotalmass = 80\n", &problem),
      "line " + std::to_string(std::count(good.begin(), good.end(), '\n') + 2) + ": totalmass");
  EXPECT_NE(problem.find("twice"), std::string::npos) << problem;
  // Every key at 1e-300 (any key: 47 of 95 once passed): refused naming the key and the range.
  for (const std::string& key : {"Ls1L", "Lb5L", "Lj6L", "Lk6d", "La0p"}) {
    std::string text = good;
    const auto at = text.find("\n" + key + "=") + 1;
    text.replace(at, text.find('\n', at) - at, key + "=1e-300");
    EXPECT_EQ(ymf_error_at(text, &problem), key);
    EXPECT_NE(problem.find("outside [0.001, 2] m"), std::string::npos) << problem;
  }
  // The edges: 0.1 cm and 200 cm are read, just past them refused.
  std::string edge = good;
  const auto at = edge.find("Ls1L=4.9");
  EXPECT_EQ(ymf_error_at(std::string(edge).replace(at, 8, "Ls1L=0.1")), "");
  EXPECT_EQ(ymf_error_at(std::string(edge).replace(at, 8, "Ls1L=200")), "");
  EXPECT_EQ(ymf_error_at(std::string(edge).replace(at, 8, "Ls1L=0.0999")), "Ls1L");
  EXPECT_EQ(ymf_error_at(std::string(edge).replace(at, 8, "Ls1L=200.01"), &problem), "Ls1L");
  EXPECT_NE(problem.find("2.0001 m is outside"), std::string::npos) << problem;
  // A NUL byte once cut the value short silently ("4.9\0junk" read as 4.9).
  std::string nul = good;
  nul.replace(nul.find("Ls1L=4.9"), 8, std::string("Ls1L=4.9\0junk", 13));
  EXPECT_NE(ymf_error_at(nul, &problem).find("Ls1L"), std::string::npos);
  EXPECT_NE(problem.find("\\x00"), std::string::npos) << problem;
}

TEST(YeadonMeasurementsFile, TheFileGuardsOfEveryReader) {
  // Through base/input_file.h: a name that is not UTF-8, a folder, a file too large.
  test::TempDir dir;
  const std::string bad_name = dir / "male\xff.txt";
  test::write_text(bad_name, ymf_text("yeadon-male1.txt"));
  try {
    load_yeadon_measurements(bad_name);
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("UTF-8"), std::string::npos) << e.what();
  }
  try {
    load_yeadon_measurements(dir.path().string());
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("folder"), std::string::npos) << e.what();
  }
  test::write_text(dir / "big.txt", std::string((1u << 20) + 1, '#'));
  EXPECT_THROW(load_yeadon_measurements(dir / "big.txt"), InputError);
}

}  // namespace
}  // namespace saltus
