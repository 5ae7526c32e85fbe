#pragma once
/// @file
/// `saltus paper`: the reproduction report's own files. DIR/report.md puts everything side by
/// side with the paper: Table 1, the optimised M1-M7 (DIR/M1 ... DIR/M7, `saltus optimize`
/// folders), the dive (DIR/dive…), the mass study (DIR/mass) and the convergence study
/// (DIR/convergence). Figures are referenced from DIR/figures, which the desktop app's
/// --export-figures fills. Running the report: use_cases/paper_report_run.h.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/output_folder.h"
#include "saltus/studies/paper_report.h"

namespace saltus {

/// What a report's folder holds (output_kind.h): its own files, the app's figures/, the records'
/// cases/, and the runs' result folders (M1/, mass/, convergence/, ...).
const FolderKind& paper_report_folder_kind();

/// DIR/{report.md, result.json, convergence/} of a whole report, from the study's definition
/// and its runs; `failed_cases` counts the cases whose process did not finish. Returns
/// result.json.
nlohmann::json write_paper_report_files(const OutputFolder& folder,
                                        const nlohmann::json& definition, const PaperReport& report,
                                        int failed_cases);

}  // namespace saltus
