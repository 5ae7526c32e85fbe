#pragma once
/// @file
/// The files the flight page is made of, compiled into the library at build time
/// (src/saltus/embed_text.cmake writes their definitions): the page template
/// (resources/web/flight_page.html) and Debian's three.js r111 with its OrbitControls
/// (libjs-three, MIT). Each is a nullptr-ended list of chunks; embedded_text() joins them.

#include <string>

namespace saltus {

extern const char* const kSaltusVersion;  ///< the project's version, "0.1.0"
extern const char* const kFlightPageTemplate[];
extern const char* const kThreeJs[];
extern const char* const kOrbitControlsJs[];

/// The chunks of one embedded file joined into its text.
std::string embedded_text(const char* const chunks[]);

}  // namespace saltus
