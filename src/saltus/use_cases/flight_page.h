#pragma once
/// @file
/// `saltus export --format html` and the app's File > Export web page…: a flight as one
/// self-contained web page (formats/flight_page.h): the athlete in 3D with the model's drawing
/// shapes and colours, the apparatus, the CoM parabola, the residual arrows, |F| and |M| before
/// and after, and a title block. What the data holds: docs/formats.md, "Flight page".

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace saltus {

/// A stage holds at most this many frames; a longer trajectory is thinned evenly (its first and
/// last samples kept) so that the page stays small whatever --samples the run used.
inline constexpr int kFlightPageMaxFrames = 1001;

/// The page's data ("format": kFlightPageFormat) for `source`: a result folder of `optimize`
/// (result.json, model.json, optimized.motion.json and both trajectories: stages "before" and
/// "after", the figures of result.json), or a motion file, a capture (its picked keyframes) or
/// an `import` folder (its keyframes.motion.json), evaluated with the default options: one stage
/// "before".
///
/// The motion capture drawn beside the athlete ("capture": its own trajectory and residual) is
/// `capture` when given (an `import` folder or a BVH file), else the one the source came from:
/// the source itself when it is a capture or an `import` folder; the `import` folder a motion
/// file lies in; for an `optimize` folder, the file its result.json's `motion_file` names (as
/// given, read from the current folder), by the same two rules. No capture found: none drawn.
/// `date` goes into the title block as given. Bad input throws InputError naming the file.
nlohmann::json flight_page_data(const std::string& source, const std::string& date,
                                const std::string& capture = "");

/// What export_flight_page wrote.
struct FlightPageSummary {
  std::string motion;      ///< the motion's name
  std::string model;       ///< the body model's name
  bool optimised = false;  ///< the page has an "after" stage
  int frames = 0;          ///< frames of the first stage
  std::string capture;     ///< the capture drawn beside the athlete ("" for none)
  std::size_t bytes = 0;   ///< size of the page
};

/// Writes the page of `source` to `out_path` (save_flight_page: atomic, never over a file Saltus
/// did not write), dated today (UTC, YYYY-MM-DD); `capture` as for flight_page_data.
FlightPageSummary export_flight_page(const std::string& source, const std::string& out_path,
                                     const std::string& capture = "");

}  // namespace saltus
