// libFuzzer target: a motion file's text, read against the bundled model and exported as
// `saltus export --format opensim` exports it (at kFuzzExportFps). Bad input must end in
// InputError (exit 2); an accepted motion must give the four files, a .mot and a .sto whose
// headers count their rows and columns right and whose every number is finite, with each
// rotation of the .mot continuous from row to row (less than half a turn apart), and a .osim
// without a NaN or infinity. Anything else (another exception, a crash, a sanitizer report, more
// than the limits' time or memory) is a finding.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "saltus/formats/opensim_files.h"
#include "saltus/use_cases/motion_exports.h"

namespace {

/// Aborts unless `text` is a storage file of `rows` rows and `columns` columns (time included),
/// every number finite; returns its rows.
std::vector<std::vector<double>> checked_storage(const std::string& text, std::size_t rows,
                                                 std::size_t columns) {
  std::istringstream in(text);
  std::string line;
  bool counted_rows = false, counted_columns = false;
  while (std::getline(in, line) && line != "endheader") {
    counted_rows = counted_rows || line == "nRows=" + std::to_string(rows);
    counted_columns = counted_columns || line == "nColumns=" + std::to_string(columns);
  }
  if (!counted_rows || !counted_columns || !std::getline(in, line)) std::abort();
  std::vector<std::vector<double>> out;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    out.emplace_back();
    for (std::string f; std::getline(fields, f, '\t');) {
      char* end = nullptr;
      const double v = std::strtod(f.c_str(), &end);
      if (*end != '\0' || !std::isfinite(v)) std::abort();
      out.back().push_back(v);
    }
    if (out.back().size() != columns) std::abort();
  }
  if (out.size() != rows) std::abort();
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::optional<saltus::fuzz::FuzzedExport> exported =
      saltus::fuzz::fuzzed_export(data, size, "opensim");
  if (!exported) return 0;
  const std::vector<saltus::ExportFile>& files = exported->files;
  const std::size_t frames = exported->frames;
  if (files.size() != 4 || files[0].name != "model.osim" || files[1].name != "coordinates.mot" ||
      files[2].name != "inverse_dynamics.sto")
    std::abort();
  const std::vector<saltus::OpensimCoordinate> coordinates =
      saltus::opensim_coordinates(exported->source.model);
  const auto mot = checked_storage(files[1].contents, frames, coordinates.size() + 1);
  checked_storage(files[2].contents, frames, coordinates.size() + 1);
  for (std::size_t r = 1; r < mot.size(); ++r)
    for (std::size_t i = 0; i < coordinates.size(); ++i)
      if (coordinates[i].rotational && !(std::abs(mot[r][i + 1] - mot[r - 1][i + 1]) <= 180.0))
        std::abort();
  saltus::fuzz::abort_on_non_finite_word(files[0].contents);
  return 0;
}
