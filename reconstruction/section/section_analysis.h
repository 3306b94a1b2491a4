#pragma once

#include <vector>

#include "reconstruction/section/periodic_spline.h"
#include "reconstruction/section/section_frame.h"

namespace caliper3d::reconstruction {

// The shape of one section, from its closed spline sampled at M points, in
// the section plane. In-plane coordinates: u along arm 1, v along the frame's
// `side` (90 degrees clockwise from arm 1 looking down the hole); the tool
// axis is the origin.
struct SectionShape {
    double area_mm2 = 0.0;               // shoelace on the sampled curve
    double equivalentDiameter_mm = 0.0;  // circle of the same area
    double centroidU_mm = 0.0;           // hole centre (centroid of the area)
    double centroidV_mm = 0.0;
    double centreOffset_mm = 0.0;  // tool axis to hole centre
    double dmax_mm = 0.0;          // least-squares ellipse, full axes
    double dmin_mm = 0.0;
    double ellipticity = 1.0;     // dmax / dmin
    double majorAngle_deg = 0.0;  // major axis, clockwise from arm 1, [0, 180)
    bool ellipseFitted = false;   // false: dmax/dmin from the area's second moments
};

// Analyses sections of `knots` pads sampled at `samples` points (design
// section 4). Immutable; safe to share between threads.
class SectionAnalyzer {
public:
    SectionAnalyzer(int knots, int samples);

    int knots() const { return m_sampler.knots(); }
    int samples() const { return m_sampler.samples(); }

    // `sampled` receives the M spline radii (mm); it must hold samples() values.
    SectionShape analyse(const double* padRadii_mm, double* sampled) const;

private:
    PeriodicSplineSampler m_sampler;
    std::vector<double> m_cos, m_sin;  // of the sample angles
};

// Azimuth (clockwise from north, [0, 360)) of the in-plane direction at
// `clockwise_deg` from arm 1: the azimuth of its horizontal projection; NaN
// when the direction is within 0.06 degrees of vertical (its horizontal
// projection shorter than 1e-3), where no azimuth exists.
double inPlaneAzimuth_deg(const SectionFrame& frame, double clockwise_deg);

// Angle of that direction from the high side, clockwise looking down the
// hole, [0, 360); in a vertical hole the high side is north.
double angleFromHighSide_deg(const SectionFrame& frame, double inc_deg, double azi_deg,
                             double clockwise_deg);

}  // namespace caliper3d::reconstruction
