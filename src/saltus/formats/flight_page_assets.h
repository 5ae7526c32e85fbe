#pragma once
/// @file
/// The files the flight page is made of, compiled into the library at build time
/// (src/saltus/embed_text.cmake writes their definitions): the page template
/// (resources/web/flight_page.html) and Debian's three.js r111 with its OrbitControls
/// (libjs-three, MIT). Each is a nullptr-ended list of chunks; embedded_text() joins them.

#include <string>

#include "saltus/base/embedded_text.h"

namespace saltus {

extern const char* const kSaltusVersion;  ///< the project's version, "0.1.0"
extern const char* const kFlightPageTemplate[];
extern const char* const kThreeJs[];
extern const char* const kOrbitControlsJs[];

}  // namespace saltus
