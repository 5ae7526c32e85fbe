// The files compiled into the library for the flight page (formats/flight_page_assets.h): the
// template with its placeholders, Debian's three.js r111 and its OrbitControls, whole.

#include "saltus/formats/flight_page_assets.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace saltus {
namespace {

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(FlightPageAssets, TheTemplateIsTheResourceFile) {
  const std::string page = embedded_text(kFlightPageTemplate);
  EXPECT_EQ(page, file_text(std::string(SALTUS_RESOURCES_DIR) + "/web/flight_page.html"))
      << "joined chunks give the file back byte for byte";
  for (const char* placeholder :
       {"/*SALTUS_THREE_JS*/", "/*SALTUS_ORBIT_CONTROLS_JS*/", "/*SALTUS_DATA*/", "SALTUS_VERSION"})
    EXPECT_NE(page.find(placeholder), std::string::npos) << placeholder;
  EXPECT_NE(page.find("Content-Security-Policy"), std::string::npos);
}

TEST(FlightPageAssets, ThreeJsIsRevision111AndCannotEndItsScript) {
  const std::string three = embedded_text(kThreeJs);
  EXPECT_GT(three.size(), 500000u);
  EXPECT_NE(three.find("REVISION=\"111\""), std::string::npos);
  EXPECT_EQ(three.find("</script"), std::string::npos);
  const std::string orbit = embedded_text(kOrbitControlsJs);
  EXPECT_NE(orbit.find("OrbitControls"), std::string::npos);
  EXPECT_EQ(orbit.find("</script"), std::string::npos);
  EXPECT_STREQ(kSaltusVersion, "0.1.0");
}

}  // namespace
}  // namespace saltus
