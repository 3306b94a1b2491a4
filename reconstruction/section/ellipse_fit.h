#pragma once

namespace caliper3d::reconstruction {

// An ellipse in a plane: centre, full axes and the direction of the major axis.
struct Ellipse {
    double centreX = 0.0;
    double centreY = 0.0;
    double major = 0.0;           // full length of the major axis (a diameter)
    double minor = 0.0;           // full length of the minor axis
    double majorAngle_rad = 0.0;  // angle of the major axis from +X towards +Y, in [0, pi)
    bool valid = false;           // false when the points do not determine an ellipse
};

// Least-squares ellipse through n >= 5 points: the conic
//   a x^2 + b xy + c y^2 + d x + e y = 1
// (coordinates taken about the points' mean, so the origin lies inside a
// closed section) minimising the algebraic residual (Bookstein 1979; Fitzgibbon
// et al. 1999, with the constant fixed instead of the ellipse constraint,
// which is enough for points that go all around a section). Exact for points on
// an ellipse. A 5x5 normal system solved by Cholesky: GLM stops at 4x4 and a
// general solver would cost more than the fit in the per-section loop.
Ellipse fitEllipse(const double* x, const double* y, int n);

}  // namespace caliper3d::reconstruction
