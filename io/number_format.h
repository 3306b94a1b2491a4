#pragma once

#include <string>

namespace caliper3d::io {

// Appends `value` with `decimals` digits after the point, exactly as std::to_chars in
// std::chars_format::fixed writes it (the exact value of the double, correctly rounded; a
// decimal point whatever the locale), except that a value which rounds to zero is written
// without a sign ("0.00", never "-0.00": a difference that rounds to nothing has none).
// Written by hand where the rounding is clear (values below 1e15 units of the last decimal,
// at most 6 decimals, away from a half), which is several times faster; std::to_chars
// otherwise.
void appendFixed(std::string& out, double value, int decimals);

// Decimals are taken from 0 to kFixedMaxDecimals (more are written as that many). The most
// characters writeFixed writes: the largest double's 309 digits, a sign, the point and the
// decimals, rounded up.
inline constexpr int kFixedMaxDecimals = 17;
inline constexpr int kFixedMaxChars = 330;

// appendFixed's text written at `out` (room for kFixedMaxChars), for a writer that builds a
// whole line in a buffer of its own; returns the end of what it wrote.
char* writeFixed(char* out, double value, int decimals);

}  // namespace caliper3d::io
