#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace caliper3d::io {

// Small text helpers every reader shares (ASCII case mapping: mnemonics, units
// and keywords of the formats read are ASCII; other bytes pass unchanged).
std::string upper(std::string_view s);
std::string lower(std::string_view s);
// Without leading and trailing white space (std::isspace: blanks, tabs, line ends).
std::string_view trim(std::string_view s);
// A blank inside a line of data: space, tab or the CR of a CRLF line end.
inline bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}
// The fields of a line separated by runs of blanks.
std::vector<std::string_view> splitBlank(std::string_view s);

// Calls visit(line, number) for each line of `text`, trimmed, numbered from firstNumber,
// while visit returns true.
template <typename Visit>
void forEachTrimmedLine(std::string_view text, std::size_t firstNumber, Visit&& visit) {
    std::size_t pos = 0, number = firstNumber;
    while (pos < text.size()) {
        const std::size_t nl = text.find('\n', pos);
        const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
        if (!visit(trim(text.substr(pos, end - pos)), number)) return;
        pos = end + 1;
        ++number;
    }
}

}  // namespace caliper3d::io
