#pragma once
/// @file
/// Text files compiled into the library at build time (src/saltus/embed_text.cmake writes their
/// definitions as nullptr-ended lists of raw-string chunks): the flight page's template and
/// three.js (formats/flight_page_assets.h), the strength tables (body/strength_tables.h).

#include <string>

namespace saltus {

/// The chunks of one embedded file joined into its text.
std::string embedded_text(const char* const chunks[]);

}  // namespace saltus
