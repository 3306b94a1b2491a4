#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/section_table.h"

namespace caliper3d::reconstruction {

// A section needs at least this fraction of its arms valid to have a shape;
// with fewer it is "no data" (docs/analysis.md): half the arms of a six-arm
// tool span at least a half-circle, so the spline between them follows the
// wall; fewer would make most of the section an interpolation.
constexpr double kDefaultMinValidArmFraction = 0.5;

// The fewest valid arms a section of `armCount` arms needs to be measured:
// ceil(fraction * armCount), at least 2 (one arm alone gives no shape, and a
// two-pad tool's one diameter needs both pads) and at most armCount.
int minValidArms(int armCount, double fraction);

// Arms of one section whose reading lies in (minRadius_mm, maxRadius_mm].
int countValidArms(const double* radii_mm, int armCount, double minRadius_mm, double maxRadius_mm);

// The sections of `rows` that have a shape (at least minValidArms(rows.armCount, fraction)
// arms read in (minRadius_mm, maxRadius_mm]): what every verb draws and analyses, and what
// `caliper3d info` counts as measured.
std::size_t countMeasuredSections(const io::SectionTable& rows, double minValidArmFraction,
                                  double minRadius_mm, double maxRadius_mm);

// A run of consecutive sections without data, rows [firstRow, lastRow].
struct NoDataInterval {
    std::size_t firstRow = 0;
    std::size_t lastRow = 0;
    double top_m = 0.0;     // measured depth of the first section without data
    double bottom_m = 0.0;  // ... and of the last
    std::size_t sections() const { return lastRow - firstRow + 1; }
};

// The runs of `measured` (one flag per row) that are false, in depth order.
std::vector<NoDataInterval> noDataIntervals(const std::vector<unsigned char>& measured,
                                            const std::vector<double>& depth_m);

// "26.97-40.69 m (275 sections)" style text of one interval.
std::string describeNoDataInterval(const NoDataInterval& interval);

}  // namespace caliper3d::reconstruction
