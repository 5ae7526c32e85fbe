#pragma once
// Pages opened in headless Chromium with software WebGL (SwiftShader through ANGLE): the flight
// page's test and the glTF export's three.js test read what a page wrote into its DOM.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "support/cli_runner.h"

namespace saltus::test {

/// Fails the test (not skips it) when Chromium is missing.
inline void require_chromium() {
  ASSERT_EQ(run_command("command -v chromium").status, 0)
      << "chromium is needed for this test: tools/bootstrap.sh test installs it";
}

/// Chromium headless with software WebGL (SwiftShader through ANGLE), its profile in `profile`.
inline std::string chromium_command(const std::string& profile) {
  return "timeout 60 chromium --headless --no-sandbox --disable-gpu --use-angle=swiftshader "
         "--enable-unsafe-swiftshader --hide-scrollbars --mute-audio --no-first-run "
         "--disable-extensions --disable-background-networking --user-data-dir=" +
         profile;
}

/// The text of a DOM dump with HTML's five entities written back as characters.
inline std::string unescape_html(std::string text) {
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"&lt;", "<"},
                                 {"&gt;", ">"},
                                 {"&quot;", "\""},
                                 {"&amp;", "&"}}) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  }
  return text;
}

/// Opens `url` (file://...) in Chromium, lets it run for up to 10 s of virtual time, and parses
/// the JSON the page wrote as the text of its <pre id="`element`">. An empty object, and a test
/// failure, when the page wrote none.
inline nlohmann::json page_json(const std::string& url, const std::string& profile,
                                const std::string& element) {
  CliRun run = run_command(chromium_command(profile) + " --virtual-time-budget=10000 --dump-dom '" +
                           url + "'");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(run.output.find("Uncaught"), std::string::npos) << run.output;
  const std::string open = "<pre id=\"" + element + "\">";
  const std::size_t start = run.output.find(open);
  if (start == std::string::npos) {
    ADD_FAILURE() << "no #" << element << " in the page: " << run.output;
    return nlohmann::json::object();
  }
  const std::size_t end = run.output.find("</pre>", start);
  return nlohmann::json::parse(
      unescape_html(run.output.substr(start + open.size(), end - start - open.size())));
}

}  // namespace saltus::test
