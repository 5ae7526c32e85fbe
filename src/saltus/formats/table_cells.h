#pragma once
/// @file
/// A user's text (an athlete's or a motion's name, a failure's message) as one cell of the
/// tables Saltus writes, so that no comma, quote, newline or `|` in it can shift a row.

#include <string>

namespace saltus {

/// `text` as one field of a CSV row (RFC 4180): as it is, or in double quotes with every quote
/// doubled when it holds a comma, a double quote, CR or LF. Read back by any CSV reader as
/// `text`, byte for byte.
std::string csv_field(const std::string& text);

/// `text` as one cell of a Markdown table (GitHub Flavored Markdown): printable() (a newline
/// would end the row, an ESC reach a terminal that shows the file), then every `\` and `|`
/// escaped with a backslash, so the cell shows printable(text).
std::string markdown_cell(const std::string& text);

}  // namespace saltus
