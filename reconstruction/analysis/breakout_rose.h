#pragma once

#include <vector>

#include "reconstruction/analysis/zone_detection.h"

namespace caliper3d::reconstruction {

// The length-weighted rose of a well's breakout azimuths. Breakout azimuths are axial (an
// orientation, modulo 180 degrees), so the data are binned over [0, 180) and drawn twice,
// mirrored 180 degrees; each zone adds its length to the bin of its mean azimuth.
struct BreakoutRose {
    double binWidth_deg = 10.0;
    // Metres of breakout per bin over [0, 180): bin i covers [i w, (i + 1) w). Their sum is the
    // combined length of the breakouts that have an azimuth.
    std::vector<double> axial_m;
    // Metres per bin all round, [0, 360): bin i and bin i + 180 / w hold the same length.
    std::vector<double> mirrored() const;
    double largest_m() const;  // the longest bin (0 when there is none)
};

// The rose of the zones of class Breakout. A zone whose azimuth is NaN (a horizontal hole
// whose major axis is vertical) has no direction and is left out. `binWidth_deg` must
// divide 180 (10: the usual rose); other widths throw std::invalid_argument.
BreakoutRose breakoutRose(const std::vector<Zone>& zones, double binWidth_deg = 10.0);

}  // namespace caliper3d::reconstruction
