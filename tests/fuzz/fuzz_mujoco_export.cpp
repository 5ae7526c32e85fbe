// libFuzzer target: a motion file's text, read against the bundled model and exported as
// `saltus export --format mujoco` exports it (at kFuzzExportFps). Bad input must end in
// InputError (exit 2); an accepted motion must give the three files, a trajectory.csv Saltus's
// CSV reader reads back with 1 + nq + 2·nv columns and one row per frame, a model.xml with one
// key per frame, and no NaN or infinity written anywhere. Anything else (another exception, a
// crash, a sanitizer report, more than the limits' time or memory) is a finding.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "fuzz_support.h"
#include "saltus/formats/csv_table.h"
#include "saltus/use_cases/motion_exports.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::optional<saltus::fuzz::FuzzedExport> exported =
      saltus::fuzz::fuzzed_export(data, size, "mujoco");
  if (!exported) return 0;
  const std::vector<saltus::ExportFile>& files = exported->files;
  const std::size_t frames = exported->frames;
  if (files.size() != 3 || files[0].name != "model.xml" || files[1].name != "trajectory.csv")
    std::abort();
  const int n = exported->source.model.size();
  std::istringstream csv(files[1].contents);
  saltus::CsvTable table;
  try {
    table = saltus::parse_csv_table(csv, "trajectory.csv");  // refuses a non-finite number
  } catch (const saltus::InputError&) {
    std::abort();  // Saltus wrote a CSV its own reader refuses
  }
  if (table.columns.size() != 1u + (7 + 4 * (n - 1)) + 2u * (6 + 3 * (n - 1)) ||
      table.rows.size() != frames)
    std::abort();
  std::size_t keys = 0;
  for (std::size_t at = files[0].contents.find("<key "); at != std::string::npos;
       at = files[0].contents.find("<key ", at + 1))
    ++keys;
  if (keys != frames) std::abort();
  for (const saltus::ExportFile& f : files)
    saltus::fuzz::abort_on_non_finite_word(f.contents);
  return 0;
}
