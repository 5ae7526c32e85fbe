#pragma once
/// @file
/// The flight page (`saltus export --format html`, docs/formats.md "Flight page"): one HTML file
/// that holds the page template, three.js and the flight's data as JSON, and opens offline in
/// any current browser. This file fills the template and writes the page; what the data holds
/// is composed by use_cases/flight_page.h.

#include <nlohmann/json.hpp>
#include <string>

#include "saltus/formats/output_kind.h"

namespace saltus {

/// The data's "format" tag, and the generator named in every page's head.
inline constexpr const char* kFlightPageFormat = "saltus-flight-page/1";
inline constexpr const char* kFlightPageGenerator = "saltus flight page";

/// The page: the template with three.js, OrbitControls and `data` (JSON, '<' escaped so that
/// no string can end the script) in place. Throws std::invalid_argument if `data` holds a
/// number that is not finite.
std::string flight_page_html(const nlohmann::json& data);

/// The JSON data embedded in a page written by flight_page_html, parsed back; InputError
/// naming `path` when the file is no such page.
nlohmann::json read_flight_page_data(const std::string& path);

/// A flight page as Saltus writes it (output_kind.h): marked by a last HTML comment, so that
/// only a page Saltus wrote, unchanged since, is ever replaced.
const FileKind& flight_page_kind();

/// Writes `html` to `path` through write_output_file (output_folder.h): at every instant absent,
/// the old or the new page; missing parent folders are created. Refuses (InputError naming
/// `path`, nothing written) a folder, a link, or an existing file that is not a page Saltus
/// wrote (flight_page_kind()); throws OutputError naming `path` when the system refuses (disk
/// full, no permission).
/// Returns the bytes written (the page and its mark).
std::size_t save_flight_page(const std::string& path, const std::string& html);

}  // namespace saltus
