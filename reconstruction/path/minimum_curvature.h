#pragma once

#include <vector>

#include "reconstruction/path/hole_direction.h"

namespace caliper3d::reconstruction {

// A survey station: measured depth, inclination (0 = vertical down) and
// azimuth (clockwise from north), degrees.
struct SurveyStation {
    double md = 0.0;
    double inc_deg = 0.0;
    double azi_deg = 0.0;
};

// Position of a station in the analysis frame, relative to the first station:
// north, east, and true vertical depth positive down, in the length unit of md.
struct PathPoint {
    double md = 0.0;
    double north = 0.0;
    double east = 0.0;
    double tvd = 0.0;
    double inc_deg = 0.0;
    double azi_deg = 0.0;
    double dogleg_deg = 0.0;     // dogleg angle from the previous station
    double dls_degPer30m = 0.0;  // dogleg severity of the course that ends here (md in metres)
};

// Result of one minimum-curvature step between two stations.
struct MinimumCurvatureStep {
    double dNorth = 0.0;
    double dEast = 0.0;
    double dTvd = 0.0;
    double dogleg_rad = 0.0;
};

// Minimum curvature (Taylor & Mason; SPE/ISCWSA standard):
//   cos b = cos(I2-I1) - sin I1 sin I2 (1 - cos(A2-A1)),  RF = 2/b tan(b/2),
//   dN = dMD/2 (sin I1 cos A1 + sin I2 cos A2) RF, and alike for E and TVD.
// RF uses the series 1 + b^2/12 + b^4/120 for tiny b, where 2/b tan(b/2) loses digits.
MinimumCurvatureStep minimumCurvatureStep(const SurveyStation& a, const SurveyStation& b);
// The same from the stations' sines and cosines, for a caller that already has
// them (every section of a log is the end of one step and the start of the next).
MinimumCurvatureStep minimumCurvatureStep(double mdA, const HoleDirection& a, double mdB,
                                          const HoleDirection& b);

// Positions of every station; the first is at the origin.
std::vector<PathPoint> minimumCurvaturePath(const std::vector<SurveyStation>& stations);

// Dogleg severity in degrees per 30 m (md in metres).
double doglegSeverity_degPer30m(double dogleg_deg, double courseLength_m);

}  // namespace caliper3d::reconstruction
