#pragma once

#include <string>
#include <string_view>

namespace caliper3d::io {

// Small text helpers every reader shares (ASCII case mapping: mnemonics, units
// and keywords of the formats read are ASCII; other bytes pass unchanged).
std::string upper(std::string_view s);
std::string lower(std::string_view s);
// Without leading and trailing white space (std::isspace: blanks, tabs, line ends).
std::string_view trim(std::string_view s);

}  // namespace caliper3d::io
