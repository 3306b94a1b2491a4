#include "io/text_encoding.h"

#include "io/parse_error.h"

namespace caliper3d::io {

bool hasUtf16Mark(std::string_view text) {
    if (text.size() < 2) return false;
    const auto b0 = static_cast<unsigned char>(text[0]), b1 = static_cast<unsigned char>(text[1]);
    return (b0 == 0xFF && b1 == 0xFE) || (b0 == 0xFE && b1 == 0xFF);
}

// UTF-16 with a byte-order mark, as some Windows tools write LAS: decoded to
// UTF-8 (header text may hold a degree sign); unpaired surrogates are refused.
std::string fromUtf16IfMarked(std::string text, const std::string& name) {
    if (text.size() < 2) return text;
    const auto b0 = static_cast<unsigned char>(text[0]), b1 = static_cast<unsigned char>(text[1]);
    const bool le = b0 == 0xFF && b1 == 0xFE, be = b0 == 0xFE && b1 == 0xFF;
    if (!le && !be) return text;
    auto unit = [&](std::size_t i) {
        const unsigned lo = static_cast<unsigned char>(text[le ? i : i + 1]);
        const unsigned hi = static_cast<unsigned char>(text[le ? i + 1 : i]);
        return hi << 8 | lo;
    };
    std::string out;
    out.reserve(text.size() / 2);
    std::size_t line = 1;
    for (std::size_t i = 2; i + 1 < text.size(); i += 2) {
        unsigned c = unit(i);
        if (c >= 0xD800 && c <= 0xDBFF && i + 3 < text.size() && unit(i + 2) >= 0xDC00 &&
            unit(i + 2) <= 0xDFFF) {
            c = 0x10000 + ((c - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
            i += 2;
        } else if (c >= 0xD800 && c <= 0xDFFF) {
            throw ParseError(name, line, 0, "expected UTF-16 text, found an unpaired surrogate");
        }
        if (c == '\n') ++line;
        if (c < 0x80) {
            out.push_back(static_cast<char>(c));
        } else if (c < 0x800) {
            out.push_back(static_cast<char>(0xC0 | (c >> 6)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        } else if (c < 0x10000) {
            out.push_back(static_cast<char>(0xE0 | (c >> 12)));
            out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        } else {
            out.push_back(static_cast<char>(0xF0 | (c >> 18)));
            out.push_back(static_cast<char>(0x80 | ((c >> 12) & 0x3F)));
            out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        }
    }
    return out;
}

}  // namespace caliper3d::io
