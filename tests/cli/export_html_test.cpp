// `saltus export --format html` (use_cases/flight_page.h): the program writes one page and never
// over a file it did not write; the page of an optimised M7 opened in headless Chromium (software
// WebGL, SwiftShader) runs its own self-test (#selftest) and the test reads the findings back
// from the DOM: no error and no refused request, a picture that is not blank and changes from
// t = 0 to t = T and from before to after, the plot's cursor drawn at the slider's time, a click
// on the plot moving the time, and the title block's numbers equal to result.json's. The page of
// an imported capture draws the capture beside the athlete: its figure changes the picture when
// toggled, its curves are on the plot, its residual in the title block is result.json's.
// The same pages pass the same checks in Firefox ESR (ExportHtmlFirefox.*): a real window on a
// private X server (Mesa's software OpenGL), driven through WebDriver BiDi by
// tests/support/firefox_page.py, which also reports the JavaScript errors Firefox logged.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/chromium_page.h"
#include "support/cli_runner.h"

namespace saltus::test {
namespace {

namespace fs = std::filesystem;

std::string page_m1_path() {
  return m1_path();
}

TEST(ExportHtml, WritesOnePageAndNeverOverAnotherFile) {
  TempDir dir;
  const std::string page = dir / "flight.html";
  CliRun run = run_cli("export " + page_m1_path() + " --format html --out " + page);
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("as given"), std::string::npos) << run.output;
  EXPECT_EQ(read_text(page).rfind("<!DOCTYPE html>", 0), 0u);
  run = run_cli("export " + page_m1_path() + " --format html --quiet --out " + page);
  EXPECT_EQ(run.status, 0) << "its own page is replaced: " << run.output;
  EXPECT_EQ(run.output, "");

  const std::string notes = dir / "notes.html";
  write_text(notes, "<html>my notes</html>");
  run = run_cli("export " + page_m1_path() + " --format html --out " + notes);
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find(notes + ": exists and is not a flight page"), std::string::npos)
      << run.output;
  EXPECT_EQ(read_text(notes), "<html>my notes</html>");

  run = run_cli("export " + page_m1_path() + " --format html --fps 30 --out " + (dir / "b.html"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("--fps"), std::string::npos) << run.output;
  run = run_cli("export " + (dir / "absent.motion.json") + " --format html --out " +
                (dir / "c.html"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("absent.motion.json"), std::string::npos) << run.output;
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"flight.html", "notes.html"}))
      << "nothing else written, no temporary left";
}

/// The findings of the page's own self-test (#selftest), read from the DOM Chromium dumps.
nlohmann::json selftest_findings(const std::string& page, const std::string& profile) {
  return page_json("file://" + page + "#selftest", profile, "selftest-result");
}

/// Fails the test (not skips it) when Firefox or the script's websocket module is missing.
void require_firefox() {
  ASSERT_EQ(run_command("command -v firefox-esr").status, 0)
      << "firefox-esr is needed for this test: tools/bootstrap.sh test installs it";
  ASSERT_EQ(run_command("command -v Xvfb").status, 0)
      << "Xvfb is needed for this test: tools/bootstrap.sh test installs it (xvfb)";
  ASSERT_EQ(run_command("/usr/bin/python3 -c 'import websocket'").status, 0)
      << "python3-websocket is needed for this test: tools/bootstrap.sh test installs it";
}

/// What tests/support/firefox_page.py read from `page` in Firefox: {"selftest": the page's
/// findings (with `--selftest`), "browser_errors": the JavaScript errors Firefox logged}. Debian's
/// python3 by its path: the websocket module is Debian's, which another python3 may not see.
nlohmann::json firefox_page(const std::string& page, const std::string& options) {
  const std::string script =
      (fs::path(SALTUS_TEST_DATA_DIR).parent_path() / "support/firefox_page.py").string();
  const CliRun run =
      run_command("timeout -k 10 120 /usr/bin/python3 " + script + " '" + page + "' " + options);
  EXPECT_EQ(run.status, 0) << run.output;
  // The findings are the one line of JSON; the script's messages start with its name.
  std::istringstream lines(run.output);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line.front() != '{') continue;
    nlohmann::json out = nlohmann::json::parse(line, nullptr, false);
    if (out.is_object()) return out;
  }
  ADD_FAILURE() << "no findings from Firefox: " << run.output;
  return nlohmann::json::object();
}

/// The optimised M7 in `dir`/m7 and its page `dir`/m7.html.
void make_m7_page(const TempDir& dir) {
  const std::string m7 = std::string(SALTUS_EXAMPLES_DIR) +
                         "/motions/M7-double-front-one-and-a-half-twists.motion.json";
  CliRun run = run_cli("optimize " + m7 + " --quiet --out " + (dir / "m7"));
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string page = dir / "m7.html";
  run = run_cli("export " + (dir / "m7") + " --format html --out " + page);
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_LE(fs::file_size(page), 3000000u) << "the issue's bound for M7";
}

/// What the self-test of the M7 page (make_m7_page) must find, in any browser.
void expect_m7_findings(const nlohmann::json& found, const TempDir& dir) {
  SCOPED_TRACE(found.dump());
  ASSERT_TRUE(found.contains("capture")) << "the self-test stopped early";
  EXPECT_FALSE(found["capture"]["present"].get<bool>()) << "M7 came from no capture";

  EXPECT_EQ(found["problems"], nlohmann::json::array()) << "errors or refused requests";
  EXPECT_TRUE(found["webgl"].get<bool>());
  EXPECT_GT(found["non_background_fraction"].get<double>(), 0.05) << "the canvas is not blank";
  EXPECT_GT(found["start_end_difference_fraction"].get<double>(), 0.002)
      << "t = 0 and t = T look different";
  EXPECT_GT(found["before_after_difference_fraction"].get<double>(), 0.0);
  EXPECT_EQ(found["stages"], 2);

  const double pixel = found["cursor"]["pixel_seconds"].get<double>();
  EXPECT_GE(found["cursor"]["columns"].get<int>(), 1) << "the cursor is drawn";
  EXPECT_NEAR(found["cursor"]["slider_time"].get<double>(),
              found["cursor"]["requested_time"].get<double>(), 0.002)
      << "the slider keeps the time it was moved to";
  EXPECT_NEAR(found["cursor"]["cursor_time"].get<double>(),
              found["cursor"]["slider_time"].get<double>(), 1.5 * pixel);
  EXPECT_NEAR(found["click"]["slider_time"].get<double>(),
              found["click"]["target_time"].get<double>(), 1.5 * pixel);
  EXPECT_NEAR(found["click"]["slider_time"].get<double>(),
              found["click"]["state_time"].get<double>(), 1e-9);

  // The numbers shown (4 significant digits) against result.json.
  const nlohmann::json result = read_json(dir / "m7/result.json");
  const nlohmann::json& shown = found["shown"];
  int compared = 0;
  for (const char* stage : {"before", "after"})
    for (const char* key : {"avg_root_force", "max_force_N", "max_moment_Nm"}) {
      const std::string field = std::string(stage) + "." + key;
      ASSERT_TRUE(shown.contains(field)) << field;
      const double expected = result[stage][key].get<double>();
      EXPECT_NEAR(std::stod(shown[field].get<std::string>()), expected,
                  5e-4 * std::abs(expected) + 1e-12)
          << field;
      ++compared;
    }
  EXPECT_EQ(compared, 6);
  EXPECT_NEAR(std::stod(shown["duration_s"].get<std::string>()),
              result["flight_time_s"].get<double>(), 5e-4);
}

/// Where the pictures to look at go: build/<preset>/flight-page/.
fs::path pictures_dir() {
  const fs::path pictures = fs::path(SALTUS_BIN_DIR).parent_path() / "flight-page";
  fs::create_directories(pictures);
  return pictures;
}

enum class PageBrowser { kChromium, kFirefox };

/// A viewport a page is pictured in.
struct PageViewport {
  std::string name;  ///< "laptop", in the picture's file name
  int width = 0;
  int height = 0;
  /// "1280,720" (Chromium's --window-size) or "1280x720" (firefox_page.py's).
  std::string size(char between) const {
    return std::to_string(width) + between + std::to_string(height);
  }
};
const PageViewport kLaptopView{"laptop", 1280, 720};
const PageViewport kPhoneView{"phone", 390, 844};

/// Pictures to look at of `page` at time `t` in `browser`, one a viewport, left in pictures_dir()
/// as <prefix><viewport>.png (Firefox's as firefox-<prefix><viewport>.png), each checked to be
/// there and not blank. Chromium takes each in a run of its own (its profile in `dir`); Firefox
/// takes them all in one window, which first runs the page's self-test in each viewport: its
/// findings (firefox_page) are returned. Chromium's self-test is read by selftest_findings.
nlohmann::json take_pictures(PageBrowser browser, const TempDir& dir, const std::string& page,
                             double t, const std::string& prefix,
                             const std::vector<PageViewport>& viewports) {
  const bool firefox = browser == PageBrowser::kFirefox;
  std::vector<fs::path> pngs;
  for (const PageViewport& v : viewports) {
    pngs.push_back(pictures_dir() / ((firefox ? "firefox-" : "") + prefix + v.name + ".png"));
    fs::remove(pngs.back());
  }
  nlohmann::json out = nlohmann::json::object();
  std::string output;
  if (firefox) {
    std::string options;
    for (const PageViewport& v : viewports)
      options += "--selftest " + v.size('x') + " ";
    options += "--at " + std::to_string(t);
    for (std::size_t i = 0; i < viewports.size(); ++i)
      options += " --shot " + viewports[i].size('x') + ":" + pngs[i].string();
    out = firefox_page(page, options);
  } else {
    for (std::size_t i = 0; i < viewports.size(); ++i) {
      const CliRun run =
          run_command(chromium_command(dir / "profile") +
                      " --virtual-time-budget=5000 --window-size=" + viewports[i].size(',') +
                      " --screenshot=" + pngs[i].string() + " 'file://" + page +
                      "#t=" + std::to_string(t) + "'");
      EXPECT_EQ(run.status, 0) << run.output;
      output += run.output;
    }
  }
  for (const fs::path& png : pngs) {
    if (!fs::exists(png)) {
      ADD_FAILURE() << png << " was not written" << (output.empty() ? "" : ": " + output);
      continue;
    }
    EXPECT_GT(fs::file_size(png), 20000u) << png << ": a blank page compresses to less";
  }
  return out;
}

TEST(ExportHtmlBrowser, TheOptimisedM7PageRunsOfflineAndShowsTheResult) {
  ASSERT_NO_FATAL_FAILURE(require_chromium());
  TempDir dir;
  ASSERT_NO_FATAL_FAILURE(make_m7_page(dir));
  const std::string page = dir / "m7.html";
  expect_m7_findings(selftest_findings(page, dir / "profile"), dir);

  // Pictures to look at, laptop and phone sized, at 40 % of the flight.
  const double t = 0.4 * read_json(dir / "m7/result.json")["flight_time_s"].get<double>();
  take_pictures(PageBrowser::kChromium, dir, page, t, "", {kLaptopView, kPhoneView});
}

/// The imported backflip capture in `dir`/bf and its page `dir`/bf.html.
void make_capture_page(const TempDir& dir) {
  const std::string bvh = std::string(SALTUS_EXAMPLES_DIR) + "/captures/deepmimic-backflip.bvh";
  CliRun run = run_cli("import " + bvh + " --quiet --out " + (dir / "bf"));
  ASSERT_EQ(run.status, 0) << run.output;
  run = run_cli("export " + (dir / "bf") + " --format html --out " + (dir / "bf.html"));
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("the motion capture beside it: " + (dir / "bf")), std::string::npos)
      << run.output;
}

/// What the self-test of the capture's page (make_capture_page) must find, in any browser.
void expect_capture_findings(const nlohmann::json& found, const TempDir& dir) {
  SCOPED_TRACE(found.dump());
  ASSERT_TRUE(found.contains("capture")) << "the self-test stopped early";
  EXPECT_EQ(found["problems"], nlohmann::json::array()) << "errors or refused requests";
  EXPECT_GT(found["non_background_fraction"].get<double>(), 0.05) << "the canvas is not blank";
  const nlohmann::json& capture = found["capture"];
  ASSERT_TRUE(capture["present"].get<bool>());
  EXPECT_EQ(capture["figure_segments"], read_json(dir / "bf/model.json")["segments"].size())
      << "every segment of the grey figure is drawn";
  EXPECT_TRUE(capture["label_shown"].get<bool>()) << "the figure is labelled \"capture\"";
  EXPECT_GT(capture["toggle_difference_fraction"].get<double>(), 0.005)
      << "the picture changes when the capture is toggled";
  EXPECT_GT(capture["curve_pixels"].get<int>(), 50) << "its |F| and |M| are on the plot";
  const double residual =
      read_json(dir / "bf/result.json")["capture"]["residual"]["avg_root_force"].get<double>();
  EXPECT_NEAR(std::stod(found["shown"]["capture.avg_root_force"].get<std::string>()), residual,
              5e-4 * residual);
}

/// 40 % of the capture's flight, where its picture is taken.
double capture_picture_time(const TempDir& dir) {
  return 0.4 *
         read_json(dir / "bf/keyframes.motion.json")["keyframes"].back()["time"].get<double>();
}

TEST(ExportHtmlBrowser, AnImportedCaptureIsDrawnBesideTheAthlete) {
  ASSERT_NO_FATAL_FAILURE(require_chromium());
  TempDir dir;
  ASSERT_NO_FATAL_FAILURE(make_capture_page(dir));
  const std::string page = dir / "bf.html";
  CliRun run = run_cli("export " + (dir / "bf") + " --format bvh --capture " + (dir / "bf") +
                       " --out " + (dir / "bf.bvh"));
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--capture"), std::string::npos) << run.output;

  expect_capture_findings(selftest_findings(page, dir / "profile"), dir);

  // A picture to look at, laptop sized, at 40 % of the flight.
  take_pictures(PageBrowser::kChromium, dir, page, capture_picture_time(dir), "capture-",
                {kLaptopView});
}

// ---------- Firefox ----------

TEST(ExportHtmlFirefox, TheOptimisedM7PageRunsOfflineAndShowsTheResult) {
  ASSERT_NO_FATAL_FAILURE(require_firefox());
  TempDir dir;
  ASSERT_NO_FATAL_FAILURE(make_m7_page(dir));
  // The self-test in a laptop's and a phone's viewport, then pictures to look at in the same two,
  // at 40 % of the flight.
  const double t = 0.4 * read_json(dir / "m7/result.json")["flight_time_s"].get<double>();
  const nlohmann::json out =
      take_pictures(PageBrowser::kFirefox, dir, dir / "m7.html", t, "", {kLaptopView, kPhoneView});
  for (const char* size : {"1280x720", "390x844"}) {
    SCOPED_TRACE(size);
    ASSERT_TRUE(out.contains("selftest") && out["selftest"].contains(size)) << out.dump();
    expect_m7_findings(out["selftest"][size], dir);
  }
  EXPECT_EQ(out["browser_errors"], nlohmann::json::array()) << "JavaScript errors Firefox logged";
}

TEST(ExportHtmlFirefox, AnImportedCaptureIsDrawnBesideTheAthlete) {
  ASSERT_NO_FATAL_FAILURE(require_firefox());
  TempDir dir;
  ASSERT_NO_FATAL_FAILURE(make_capture_page(dir));
  const nlohmann::json out = take_pictures(PageBrowser::kFirefox, dir, dir / "bf.html",
                                           capture_picture_time(dir), "capture-", {kLaptopView});
  ASSERT_TRUE(out.contains("selftest") && out["selftest"].contains("1280x720")) << out.dump();
  expect_capture_findings(out["selftest"]["1280x720"], dir);
  EXPECT_EQ(out["browser_errors"], nlohmann::json::array()) << "JavaScript errors Firefox logged";
}

}  // namespace
}  // namespace saltus::test
