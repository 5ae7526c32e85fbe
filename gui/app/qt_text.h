#pragma once
/// @file
/// Library text (UTF-8 std::string) as Qt text, in one place for every widget.

#include <QString>
#include <string>

namespace saltus::gui {

inline QString qstr(const std::string& s) {
  return QString::fromStdString(s);
}

}  // namespace saltus::gui
