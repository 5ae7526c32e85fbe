#pragma once
/// @file
/// "Can this athlete land it?" as rich text, the same wherever the app shows it (the Model panel,
/// New athlete, the compare window): the library's verdict (use_cases/athlete_verdict.h) in its
/// light's colour, the flight in Yeadon's words and the verdict's reasons in the CLI's words.

#include <QString>

#include "saltus/use_cases/athlete_verdict.h"

namespace saltus::gui {

/// The headline in bold in its colour (unless `with_headline` is false: a dialog that shows it
/// larger apart), then the flight's words, the joints' words when the headline does not give
/// them, and one "⚠" line per reason in the headline's colour: all of them, or the first
/// `max_reasons` and "… and N more (point here to read them)" for a window short of room that
/// puts the whole text in its tooltip.
QString verdict_html(const AthleteVerdict& verdict, bool with_headline = true,
                     int max_reasons = -1);

}  // namespace saltus::gui
