#include "io/layout/format_sniffing.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "io/parse_error.h"
#include "io/survey_reader.h"
#include "io/text.h"

namespace caliper3d::io {

namespace {

std::size_t lineOf(std::string_view text, std::size_t offset) {
    return 1 + static_cast<std::size_t>(std::count(
                   text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

}  // namespace

bool looksLikeLas(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (isBlank(text[i]) || text[i] == '\n')) ++i;
        if (i < text.size() && text[i] == '#') {
            const std::size_t nl = text.find('\n', i);
            if (nl == std::string_view::npos) return false;
            i = nl + 1;
            continue;
        }
        return i < text.size() && text[i] == '~';
    }
    return false;
}

void refuseWhatIsNotALog(std::string_view start, const std::string& file) {
    const std::string_view head = start.substr(0, 64u << 10);
    if (const void* nul = std::memchr(head.data(), '\0', head.size())) {
        const std::size_t at =
            static_cast<std::size_t>(static_cast<const char*>(nul) - head.data());
        const std::size_t newline = at == 0 ? std::string_view::npos : head.rfind('\n', at - 1);
        const std::size_t column = newline == std::string_view::npos ? at + 1 : at - newline;
        throw ParseError(file, lineOf(head, at), column,
                         "expected text, found a NUL byte (a binary file, or UTF-16 without a "
                         "byte-order mark)");
    }
    const std::size_t first = head.find_first_not_of(" \t\r\n");
    if (first != std::string_view::npos && (head[first] == '{' || head[first] == '['))
        throw ParseError(file, lineOf(head, first), 0,
                         "expected a caliper log (LAS or column text), found JSON");
    if (!looksLikeLas(head) && looksLikeSurvey(head))
        throw ParseError(
            file, 0, 0,
            "expected a caliper log, found a deviation survey (a line names measured depth, "
            "inclination and azimuth columns, and no caliper curves): give it with --survey, "
            "or see it with caliper3d info");
}

}  // namespace caliper3d::io
