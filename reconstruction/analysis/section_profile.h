#pragma once

#include <cstddef>
#include <vector>

#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// A section's outline about its own centre, in the earth frame: the distance from the centroid
// of the section's area to its wall at `bins` equal angles clockwise from north
// (AngleReference::North: the in-plane direction whose horizontal projection points north;
// north itself in a vertical hole), bin k at k * 360 / bins degrees. Two runs of one well, whose
// tools sit differently and off centre differently, compare wall to wall at the same azimuth
// this way (docs/analysis.md, "Two runs of one well").
class SectionProfiler {
public:
    SectionProfiler(const WellGeometry& geometry, int bins);

    int bins() const { return m_bins; }
    // Fills `radius_mm` (bins() values) for `row`; false, leaving it untouched, where the row
    // has no data or no known north (an unoriented tool, or an inclined hole of unknown
    // azimuth oriented from the high side).
    bool profile(std::size_t row, double* radius_mm);

private:
    const WellGeometry& m_geometry;
    int m_bins;
    std::vector<double> m_knots, m_sampled, m_x, m_y, m_angle;
    std::vector<double> m_cos, m_sin;              // of the bins' angles
    std::vector<double> m_sampleCos, m_sampleSin;  // of the spline samples' angles from arm 1
};

// The azimuth (clockwise from north, [0, 360)) of the in-plane direction at `angle_deg`
// clockwise from north in the section plane of `frame` (the angles of a SectionProfiler); NaN
// where that direction is within 0.06 degrees of vertical.
double profileAngleAzimuth_deg(const SectionFrame& frame, double angle_deg);

}  // namespace caliper3d::reconstruction
