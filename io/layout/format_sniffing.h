#pragma once

#include <string>
#include <string_view>

namespace caliper3d::io {

// True when the first content line (after blank and '#' lines) starts a LAS section ('~').
bool looksLikeLas(std::string_view text);

// Files that are text but not a caliper log would otherwise read as column
// text and fail late with a misleading message, or worse, a survey of 11
// numbers per line would read as an 11-arm log. Throws ParseError naming
// `file` for a binary file, JSON or a deviation survey; `start` is the
// beginning of the text.
void refuseWhatIsNotALog(std::string_view start, const std::string& file);

}  // namespace caliper3d::io
