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

// The sums behind padAzimuthOffset, for a caller that goes through the rows
// in blocks (in parallel, say) and adds the blocks in order. padAzimuthOffset
// adds blocks of kPadAzimuthBlockRows rows in row order: the same blocks added
// in the same order give its result bit for bit.
inline constexpr std::size_t kPadAzimuthBlockRows = 4096;
struct PadAzimuthSums {
    double cosSum = 0.0;  // of P1AZ minus the predicted azimuth
    double sinSum = 0.0;
    std::size_t samples = 0;
    void add(const PadAzimuthSums& other) {
        cosSum += other.cosSum;
        sinSum += other.sinSum;
        samples += other.samples;
    }
};
// True when the table has all four curves (P1AZ, HAZI, RB, DEVI) on every row.
bool hasPadAzimuthCurves(const io::SectionTable& table);
// Sums over rows [first, last) of a table that has the four curves.
PadAzimuthSums padAzimuthSums(const io::SectionTable& table, std::size_t first, std::size_t last,
                              double minInclination_deg = 0.5);
// Mean and spread from the sums of all rows.
OrientationOffset padAzimuthOffset(const PadAzimuthSums& sums);

}  // namespace caliper3d::reconstruction
