#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "reconstruction/analysis/section_angle_reference.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// The wall unrolled: rows of measured depth, columns of angle around the section.
struct UnrolledImageRequest {
    double top_m = 0.0;     // the window's shallow end
    double bottom_m = 0.0;  // its deep end
    int rows = 0;
    int columns = 360;
    AngleReference reference = AngleReference::North;
};

// The departure of the wall's radius from a gauge radius (the bit's), millimetres, at
// `rows` x `columns` cells: row r is the depth band r of (top_m, bottom_m), top first; column c
// the angle band c of [0, 360) clockwise from the reference. NaN where there is no data: beyond
// the log, a section without data, no gauge, a row whose reference is not known
// (referenceKnown: an inclined hole without an azimuth).
struct UnrolledImage {
    double top_m = 0.0, bottom_m = 0.0;
    int rows = 0, columns = 0;
    AngleReference reference = AngleReference::North;
    std::vector<float> departure_mm;  // row-major

    float at(int row, int column) const {
        return departure_mm[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                            static_cast<std::size_t>(column)];
    }
    // The centres of a row's depth band and a column's angle band.
    double rowDepth_m(int row) const { return top_m + (row + 0.5) * (bottom_m - top_m) / rows; }
    double columnAngle_deg(int column) const { return (column + 0.5) * 360.0 / columns; }
};

// Each cell takes the table row nearest its depth and the geometry's closed spline through that
// row's knots at the cell's angle (the 3D wall's radius there). `gaugeRadius_mm(row)` gives the
// radius departures are measured from; without it, the log's bit radius.
UnrolledImage unrolledImage(const WellGeometry& geometry, const UnrolledImageRequest& request,
                            const std::function<double(std::size_t)>& gaugeRadius_mm = {});

}  // namespace caliper3d::reconstruction
