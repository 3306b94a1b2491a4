#include "io/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

namespace caliper3d::io {

namespace {

// `value` rounded to `decimals` as a whole count of 10^-decimals, where that is what
// std::to_chars prints: the product value * 10^decimals is off the exact one by a few parts in
// 10^16 of itself, so wherever its fraction lies clearly away from a half, its rounding is the
// exact value's. False near a half, for large values, NaN and infinity.
bool scaledInteger(double value, int decimals, long long& n) {
    static constexpr double kPower[] = {1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6};
    if (decimals < 0 || decimals > 6) return false;
    const double scaled = value * kPower[decimals];
    if (!(std::abs(scaled) < 1e15)) return false;
    const double whole = std::floor(scaled), fraction = scaled - whole;
    if (std::abs(fraction - 0.5) <= 1e-12 * (1.0 + std::abs(scaled))) return false;
    n = static_cast<long long>(whole) + (fraction > 0.5 ? 1 : 0);
    return true;
}

}  // namespace

char* writeFixed(char* out, double value, int decimals) {
    long long n = 0;
    if (scaledInteger(value, decimals, n)) {
        // Digits from the last, the point put in after `decimals` of them, then the sign.
        char text[40];
        char* p = text + sizeof text;
        unsigned long long u =
            n < 0 ? 0ULL - static_cast<unsigned long long>(n) : static_cast<unsigned long long>(n);
        int k = 0;  // digits written
        do {
            if (k == decimals && k > 0) *--p = '.';
            *--p = static_cast<char>('0' + u % 10);
            u /= 10;
            ++k;
        } while (k <= decimals || u > 0);
        if (n < 0) *--p = '-';
        const auto length = static_cast<std::size_t>(text + sizeof text - p);
        std::memcpy(out, p, length);
        return out + length;
    }
    decimals = std::clamp(decimals, 0, kFixedMaxDecimals);
    char* end =
        std::to_chars(out, out + kFixedMaxChars, value, std::chars_format::fixed, decimals).ptr;
    if (*out == '-' && std::none_of(out, end, [](char c) { return c >= '1' && c <= '9'; })) {
        std::memmove(out, out + 1, static_cast<std::size_t>(end - out - 1));
        --end;
    }
    return end;
}

void appendFixed(std::string& out, double value, int decimals) {
    char text[kFixedMaxChars];
    out.append(text, static_cast<std::size_t>(writeFixed(text, value, decimals) - text));
}

}  // namespace caliper3d::io
