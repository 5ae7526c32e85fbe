// The flight page file (formats/flight_page.h): the data goes in as JSON that no string can break
// out of and reads back equal; non-finite numbers are refused; the page is written atomically
// and never over a file Saltus did not write.

#include "saltus/formats/flight_page.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "saltus/base/input_error.h"
#include "support/temp_path.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

std::string page_file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

nlohmann::json small_page_data() {
  return {{"format", kFlightPageFormat},
          {"motion", "a </script><script>alert(1)</script> motion"},
          {"numbers", {0.1, -2.5e-7, 123456.789}}};
}

TEST(FlightPage, DataReadsBackEqualAndCannotEndItsScript) {
  const std::string html = flight_page_html(small_page_data());
  EXPECT_EQ(html.find("</script><script>alert"), std::string::npos);
  EXPECT_NE(html.find("<meta name=\"generator\" content=\"saltus flight page 0.1.0\">"),
            std::string::npos);
  EXPECT_NE(html.find("REVISION=\"111\""), std::string::npos) << "three.js inlined";
  EXPECT_EQ(html.find("/*SALTUS_"), std::string::npos) << "every placeholder filled";
  const fs::path path = test::temp_path("data.html");
  save_flight_page(path.string(), html);
  EXPECT_EQ(read_flight_page_data(path.string()), small_page_data());
  EXPECT_EQ(unmarked_reason(flight_page_kind(), page_file_text(path)), "");
}

TEST(FlightPage, NonFiniteNumbersAreRefused) {
  nlohmann::json data = small_page_data();
  data["numbers"][1] = std::numeric_limits<double>::quiet_NaN();
  try {
    flight_page_html(data);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/numbers/1"), std::string::npos) << e.what();
  }
  data["numbers"][1] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(flight_page_html(data), std::invalid_argument);
}

TEST(FlightPage, ReplacesItsOwnPageButNoOtherFile) {
  const std::string html = flight_page_html(small_page_data());
  const fs::path dir = test::temp_path("own");
  fs::create_directories(dir);
  const fs::path page = dir / "flight.html";
  save_flight_page(page.string(), html);
  save_flight_page(page.string(), html + "<!-- again -->");
  EXPECT_EQ(page_file_text(page), marked_text(flight_page_kind(), html + "<!-- again -->"));
  // A page the user edited since is theirs now.
  std::ofstream(page, std::ios::app) << "<!-- my note -->\n";
  EXPECT_THROW(save_flight_page(page.string(), html), InputError);
  fs::remove(page);
  save_flight_page(page.string(), html);

  const fs::path other = dir / "notes.html";
  std::ofstream(other) << "<html>my own notes</html>";
  try {
    save_flight_page(other.string(), html);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), other.string());
    EXPECT_NE(e.problem().find("not a flight page Saltus wrote"), std::string::npos);
  }
  EXPECT_EQ(page_file_text(other), "<html>my own notes</html>");

  fs::create_symlink(page, dir / "link.html");
  EXPECT_THROW(save_flight_page((dir / "link.html").string(), html), InputError);
  fs::create_directories(dir / "folder.html");
  EXPECT_THROW(save_flight_page((dir / "folder.html").string(), html), InputError);
  // A missing folder is created, as for every --out.
  save_flight_page((dir / "missing" / "x.html").string(), html);
  EXPECT_EQ(page_file_text(dir / "missing" / "x.html"), marked_text(flight_page_kind(), html));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 5)
      << "flight.html, notes.html, link.html, folder.html, missing/: no temporary left";
}

TEST(FlightPage, OnlyAPageSaltusWroteIsRecognised) {
  const fs::path path = test::temp_path("plain.html");
  std::ofstream(path) << "<html><head><meta name=\"generator\" content=\"other\"></head></html>";
  EXPECT_NE(unmarked_reason(flight_page_kind(), page_file_text(path)), "");
  // A page that names Saltus's generator but carries no mark (written by hand, or by a Saltus
  // that did not mark its pages) is not replaced either.
  std::ofstream(path) << flight_page_html(small_page_data());
  EXPECT_THROW(save_flight_page(path.string(), "<html></html>"), InputError);
  EXPECT_THROW(read_flight_page_data(test::temp_path("absent.html").string()), InputError);
}

}  // namespace
}  // namespace saltus
