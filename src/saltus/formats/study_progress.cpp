#include "saltus/formats/study_progress.h"

#include <cstdio>

#include "saltus/base/text_format.h"
#include "saltus/formats/study_case_file.h"

namespace saltus {
namespace {

/// What the case just recorded came to, in a few words.
std::string case_result(const CaseRecord& r) {
  if (!r.finished()) return r.failure;
  char text[96];
  switch (r.kind) {
    case CaseKind::kConvergence:
      std::snprintf(text, sizeof text, "%s, %d it., %.3g N", r.convergence.status.c_str(),
                    r.convergence.iterations, r.convergence.avg_force_after);
      return text;
    case CaseKind::kOptimization:
      std::snprintf(text, sizeof text, "%s, %d it., %.3g N", r.run.status.c_str(), r.run.iterations,
                    r.run.avg_force_after);
      return text;
    case CaseKind::kMassStudy:
      return "done";
    case CaseKind::kAthlete:
      std::snprintf(text, sizeof text, "%s, %d it., %.3g N", r.athlete.status.c_str(),
                    r.athlete.iterations, r.athlete.avg_root_force_after_N);
      return text;
  }
  return "";
}

/// "m:ss" or "h:mm:ss" back to seconds; "?" to −1; anything else to nothing.
std::optional<double> parse_clock(const std::string& text) {
  if (text == "?") return -1.0;
  long h = 0, m = 0, s = 0;
  int used = 0;
  if (std::sscanf(text.c_str(), "%ld:%ld:%ld%n", &h, &m, &s, &used) == 3 &&
      used == static_cast<int>(text.size()))
    return static_cast<double>(3600 * h + 60 * m + s);
  used = 0;
  if (std::sscanf(text.c_str(), "%ld:%ld%n", &m, &s, &used) == 2 &&
      used == static_cast<int>(text.size()))
    return static_cast<double>(60 * m + s);
  return std::nullopt;
}

}  // namespace

std::string clock_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

std::string study_progress_line(const StudyProgress& p) {
  const int width = static_cast<int>(std::to_string(p.total).size());
  // printable: a case named after a user's athlete must not split the line (the app reads it
  // line by line) nor send escapes to the terminal.
  const std::string last =
      p.last ? printable(p.last->name) + ": " + case_result(*p.last) : std::string();
  char head[160];
  std::snprintf(head, sizeof head, "  [%*d/%d] %d failed, %d not solved, %s elapsed, ETA %s  ",
                width, p.done, p.total, p.failed, p.unsolved, clock_text(p.elapsed_s).c_str(),
                p.eta_s < 0 ? "?" : clock_text(p.eta_s).c_str());
  return head + last;
}

std::optional<StudyProgressLine> parse_study_progress_line(const std::string& line) {
  StudyProgressLine out;
  char elapsed[32] = {0}, eta[32] = {0};
  int used = 0;
  if (std::sscanf(line.c_str(), " [%d/%d] %d failed, %d not solved, %31s elapsed, ETA %31s%n",
                  &out.done, &out.total, &out.failed, &out.unsolved, elapsed, eta, &used) != 6)
    return std::nullopt;
  const std::optional<double> elapsed_s = parse_clock(elapsed);
  const std::optional<double> eta_s = parse_clock(eta);
  if (!elapsed_s || *elapsed_s < 0 || !eta_s || out.total <= 0 || out.done < 0 ||
      out.done > out.total)
    return std::nullopt;
  out.elapsed_s = *elapsed_s;
  out.eta_s = *eta_s;
  std::string rest = line.substr(static_cast<std::size_t>(used));
  while (!rest.empty() && rest.front() == ' ')
    rest.erase(rest.begin());
  while (!rest.empty() && (rest.back() == '\n' || rest.back() == '\r'))
    rest.pop_back();
  // The case's name may hold ": " itself (none does today); its result never does.
  const std::size_t colon = rest.rfind(": ");
  out.last_case = colon == std::string::npos ? rest : rest.substr(0, colon);
  out.last_result = colon == std::string::npos ? "" : rest.substr(colon + 2);
  return out;
}

}  // namespace saltus
