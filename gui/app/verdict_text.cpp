#include "app/verdict_text.h"

#include <algorithm>

#include "core/athlete_landing.h"

namespace saltus::gui {

QString verdict_html(const AthleteVerdict& verdict, bool with_headline, int max_reasons) {
  const QString colour = QString::fromStdString(verdict_html_colour(verdict.light));
  const auto html = [](const std::string& s) { return QString::fromStdString(s).toHtmlEscaped(); };
  QString text = with_headline ? QStringLiteral("<span style='color:%1'><b>%2</b></span><br>")
                                     .arg(colour, html(verdict.headline))
                               : QString();
  text += html(verdict.flight_words) + ".";
  if (verdict.headline.find(verdict.strength_words) == std::string::npos)
    text += QObject::tr("<br>Joints: %1.").arg(html(verdict.strength_words));
  const int reasons = static_cast<int>(verdict.reasons.size());
  const int shown = max_reasons < 0 ? reasons : std::min(reasons, max_reasons);
  for (int i = 0; i < shown; ++i)
    text += QStringLiteral("<br><span style='color:%1'>⚠ %2</span>")
                .arg(colour, html(verdict.reasons[static_cast<std::size_t>(i)]));
  if (shown < reasons)
    text +=
        QObject::tr("<br><span style='color:%1'>⚠ … and %2 more (point here to read them)</span>")
            .arg(colour)
            .arg(reasons - shown);
  return text;
}

}  // namespace saltus::gui
