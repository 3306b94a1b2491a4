#pragma once

#include <cstdint>

namespace caliper3d::reconstruction {

// Colour of a wall point by how far its radius departs from the bit radius:
// blue under gauge, grey within +-3 mm, yellow to red as the hole enlarges
// (red at +25 mm and beyond). Packed 0xRRGGBBAA as Coin's orderedRGBA wants.
std::uint32_t gaugeColour(double radius_mm, double bitRadius_mm);

}  // namespace caliper3d::reconstruction
