#pragma once
/// @file
/// Numbers and user text for people: a printf pattern for tables, reports and the app's labels,
/// the stream default for numbers in error messages, and user strings made safe to quote in a
/// one-line message. (Data files write the shortest exact form, trajectory_csv.)

#include <cstddef>
#include <string>

namespace saltus {

/// One number in a printf pattern ("%.2f N", "±%g s"): tables, reports, the app's labels.
std::string format_number(const char* pattern, double value);

/// Six significant digits (the stream default): what a person compares against a file in an
/// error message.
std::string message_number(double value);

/// `value` for a message that puts it beside the range [low, high]: message_number, or every
/// digit it needs (exact_number) where six would print it as a bound it is not ("300.0000001 kg
/// is outside [10, 300]", not "300 kg is outside [10, 300]").
std::string message_number_beside(double value, double low, double high);

/// The shortest text that reads back to the same double (std::to_chars), "0" for −0: the exact
/// numbers of data files (the exports write every number so).
std::string exact_number(double value);

/// True when `text` is well-formed UTF-8 (no overlong forms, surrogates or code points past
/// U+10FFFF).
bool is_valid_utf8(const std::string& text);

/// `text` with every byte that is not part of well-formed UTF-8, and every control character,
/// written as \xNN: safe to print and to store in a JSON string.
std::string printable(const std::string& text);

/// `text` fit for an XML attribute or element (the MuJoCo and OpenSim exports): printable(), then
/// & < > " ' as entities.
std::string xml_text(const std::string& text);

/// `noun` after "a" or "an" by its first letter ("an import", "a body model"); "" stays "".
std::string with_article(const std::string& noun);

/// The most bytes of a user string message_text keeps: a joint name or a token is a few dozen.
inline constexpr std::size_t kMaxMessageTextBytes = 80;

/// A string from a user's file or command line, fit to quote in a one-line message: control
/// characters (a newline would split the message, an ESC would reach the terminal) and bytes
/// that are not UTF-8 written as \xNN (printable()), then cut to at most `max_bytes` at a
/// character boundary with "..." and the full length appended ("abc... (5000 bytes)").
std::string message_text(const std::string& text, std::size_t max_bytes = kMaxMessageTextBytes);

}  // namespace saltus
