#include "io/number_parsing.h"

#include <charconv>
#include <cstring>

namespace caliper3d::io {

bool parseNumber(std::string_view token, double& value) {
    if (token.empty()) return false;
    // from_chars rejects a leading '+', which some writers emit.
    if (token.front() == '+') token.remove_prefix(1);
    const char* first = token.data();
    const char* last = first + token.size();
    char buffer[64];
    const void* comma = std::memchr(first, ',', token.size());
    if (comma != nullptr) {
        if (token.size() >= sizeof buffer) return false;
        if (std::memchr(first, '.', token.size()) != nullptr) return false;
        std::memcpy(buffer, first, token.size());
        std::size_t commaAt = static_cast<const char*>(comma) - first;
        buffer[commaAt] = '.';
        if (std::memchr(buffer + commaAt + 1, ',', token.size() - commaAt - 1) != nullptr)
            return false;
        first = buffer;
        last = buffer + token.size();
    }
    auto [end, ec] = std::from_chars(first, last, value);
    return ec == std::errc() && end == last;
}

}  // namespace caliper3d::io
