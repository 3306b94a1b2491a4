#pragma once

#include <cstdint>

namespace caliper3d::reconstruction {

// The wall's colour maps, packed 0xRRGGBBAA as Coin's orderedRGBA wants. Hand-written
// tables: neither Coin, Qt, Boost nor GLM ships perceptual colour maps.
enum class ColourMapKind : unsigned char {
    Diverging,   // departures either side of a reference (bit size): blue, grey, red
    Sequential,  // a value from low to high: viridis
    Categorical  // fixed colours, one per class
};

// t in [0, 1] (clamped): Moreland's "cool to warm" map through a neutral grey at 0.5, the
// reference value.
std::uint32_t divergingColour(double t);
// t in [0, 1] (clamped): matplotlib's viridis, perceptually uniform and legible in grey.
std::uint32_t sequentialColour(double t);
// A section that is drawn but has no value for the quantity coloured (a null in the
// coloured curve, no bit size at that depth): dark grey, outside every map.
inline constexpr std::uint32_t kNoValueColour = 0x4D4D4DFFu;

// The red, green and blue of a packed colour, 0-255.
inline constexpr int red(std::uint32_t c) {
    return static_cast<int>((c >> 24) & 0xFFu);
}
inline constexpr int green(std::uint32_t c) {
    return static_cast<int>((c >> 16) & 0xFFu);
}
inline constexpr int blue(std::uint32_t c) {
    return static_cast<int>((c >> 8) & 0xFFu);
}

}  // namespace caliper3d::reconstruction
