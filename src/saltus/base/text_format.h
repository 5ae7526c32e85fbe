#pragma once
/// @file
/// Numbers as text for people: a printf pattern for tables, reports and the app's labels, and the
/// stream default for error messages. (Data files write the shortest exact form, trajectory_csv.)

#include <string>

namespace saltus {

/// One number in a printf pattern ("%.2f N", "±%g s"): tables, reports, the app's labels.
std::string format_number(const char* pattern, double value);

/// Six significant digits (the stream default): what a person compares against a file in an
/// error message.
std::string message_number(double value);

}  // namespace saltus
