#include "reconstruction/mesh/colour_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace caliper3d::reconstruction {

namespace {

struct Rgb {
    double r, g, b;
};

std::uint32_t pack(const Rgb& c) {
    auto q = [](double v) {
        return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    };
    return (q(c.r) << 24) | (q(c.g) << 16) | (q(c.b) << 8) | 0xFFu;
}

// Linear interpolation between equally spaced control colours.
template <std::size_t N>
std::uint32_t sample(const std::array<Rgb, N>& stops, double t) {
    if (!std::isfinite(t)) return kNoValueColour;
    const double x = std::clamp(t, 0.0, 1.0) * static_cast<double>(N - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), N - 2);
    const double f = x - static_cast<double>(i);
    const Rgb &a = stops[i], &b = stops[i + 1];
    return pack({a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f});
}

// K. Moreland, "Diverging Color Maps for Scientific Visualization" (2009), the cool-to-warm
// map at 0, 1/4, 1/2, 3/4 and 1.
constexpr std::array<Rgb, 5> kCoolWarm{{{0.230, 0.299, 0.754},
                                        {0.552, 0.690, 0.996},
                                        {0.865, 0.865, 0.865},
                                        {0.958, 0.604, 0.482},
                                        {0.706, 0.016, 0.150}}};

// matplotlib's viridis (CC0) at 0, 0.1, ..., 1: #440154 ... #FDE725.
constexpr std::array<Rgb, 11> kViridis{{{0x44 / 255.0, 0x01 / 255.0, 0x54 / 255.0},
                                        {0x48 / 255.0, 0x24 / 255.0, 0x75 / 255.0},
                                        {0x41 / 255.0, 0x44 / 255.0, 0x87 / 255.0},
                                        {0x35 / 255.0, 0x5F / 255.0, 0x8D / 255.0},
                                        {0x2A / 255.0, 0x78 / 255.0, 0x8E / 255.0},
                                        {0x21 / 255.0, 0x91 / 255.0, 0x8C / 255.0},
                                        {0x22 / 255.0, 0xA8 / 255.0, 0x84 / 255.0},
                                        {0x44 / 255.0, 0xBF / 255.0, 0x70 / 255.0},
                                        {0x7A / 255.0, 0xD1 / 255.0, 0x51 / 255.0},
                                        {0xBD / 255.0, 0xDF / 255.0, 0x26 / 255.0},
                                        {0xFD / 255.0, 0xE7 / 255.0, 0x25 / 255.0}}};

}  // namespace

std::uint32_t divergingColour(double t) {
    return sample(kCoolWarm, t);
}

std::uint32_t sequentialColour(double t) {
    return sample(kViridis, t);
}

}  // namespace caliper3d::reconstruction
