#pragma once

#include <cstddef>
#include <vector>

#include "io/section_table.h"
#include "reconstruction/analysis/section_angle_reference.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// A point of a section in polar form about the tool axis, in the section plane: the clockwise
// angle from the outline's reference (north or the high side) and the distance from the axis.
struct PolarPoint {
    double angle_deg = 0.0;  // [0, 360)
    double radius_mm = 0.0;
};

// The section's fitted ellipse (as the report's dmax, dmin and major axis come from it).
struct OutlineEllipse {
    PolarPoint centre;      // the ellipse's centre seen from the tool axis
    double major_mm = 0.0;  // full axes
    double minor_mm = 0.0;
    double majorAngle_deg = 0.0;  // direction of the major axis from the reference, [0, 180)
    bool fitted = false;          // false: the ellipse of the area's second moments (the analyser's
                                  // fallback) or the two-pad circle
};

// What a section looks like, for a polar plot of it.
struct SectionOutline {
    AngleReference reference = AngleReference::North;
    bool measured = false;       // false: no data (too few valid arms); pads, spline, ellipse empty
    double arm1Angle_deg = 0.0;  // arm 1's angle from the reference
    std::vector<PolarPoint> pads;    // the arm tips, arm 1 first, missing arms repaired
    std::vector<PolarPoint> spline;  // the closed spline through the pads, at equal angles
    OutlineEllipse ellipse;
    // Where north and the high side lie; NaN where not known (referenceKnown) and for the high
    // side of a vertical hole.
    double northAngle_deg = io::kNaN;
    double highSideAngle_deg = io::kNaN;
    double bitRadius_mm = io::kNaN;  // the log's bit size at the row, halved
};

// The outline of `row`'s section from the geometry's own knots, spline and frame (the shape the
// report analyses), the spline sampled at `samples` equal angles from arm 1 (0: the geometry's
// splinePoints).
SectionOutline sectionOutline(const WellGeometry& geometry, std::size_t row,
                              AngleReference reference, int samples = 0);

// The ellipse as `n` points, and one of its axes (major or minor) as `n` points from end to
// end, in the same polar form (for a plot that joins points by straight lines).
std::vector<PolarPoint> ellipsePoints(const OutlineEllipse& ellipse, int n);
std::vector<PolarPoint> ellipseAxis(const OutlineEllipse& ellipse, bool major, int n);

}  // namespace caliper3d::reconstruction
