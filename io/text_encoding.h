#pragma once

#include <string>
#include <string_view>

namespace caliper3d::io {

// True when `text` starts with a UTF-16 byte-order mark (either byte order).
bool hasUtf16Mark(std::string_view text);

// UTF-16 with a byte-order mark, as some Windows tools write LAS, decoded to
// UTF-8; text without the mark is returned unchanged. An unpaired surrogate
// is a ParseError naming the line.
std::string fromUtf16IfMarked(std::string text, const std::string& name);

}  // namespace caliper3d::io
