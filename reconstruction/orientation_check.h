#pragma once

#include <cstddef>

#include "io/section_table.h"

namespace caliper3d::reconstruction {

// P1AZ against the pad-1 azimuth that HAZI, DEVI and RB predict (design
// section 3): the azimuth of the horizontal projection of the direction RB
// clockwise from the high side, which is HAZI + RB in a near-vertical hole.
// Vendors agree in some files and carry a constant offset in others, so the
// offset is measured, never assumed. Circular mean in (-180, 180] and
// circular SD sqrt(-2 ln R) (Mardia 1972), over rows where all four exist and
// the hole is inclined at least `minInclination_deg` (the high side is
// undefined in a vertical hole).
struct OrientationOffset {
    std::size_t samples = 0;
    double mean_deg = 0.0;  // NaN when no samples
    double sd_deg = 0.0;
};
OrientationOffset padAzimuthOffset(const io::SectionTable& table, double minInclination_deg = 0.5);

}  // namespace caliper3d::reconstruction
