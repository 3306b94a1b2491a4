#pragma once

#include <cmath>
#include <string>

#include "reconstruction/section/section_frame.h"

namespace caliper3d::reconstruction {

// Where a well starts: map easting and northing (metres, the same projected
// grid for every well of a scene) and the elevation of its depth reference
// (metres above datum, positive up), as given by --wellhead E,N,ELEV or read
// from the log's header (reconstruction/load/wellhead_placement.h).
struct Wellhead {
    double easting_m = 0.0;
    double northing_m = 0.0;
    double elevation_m = 0.0;
    // On a scene origin (sceneOrigin): the field frame the other wells' header
    // coordinates are projected into ("EPSG:32631"; kHeaderGrid; "" when the
    // first well's header gives no location). Empty on a --wellhead.
    std::string frame{};
    // On a scene origin placed in a named frame: the grid azimuth of true north at the origin
    // (degrees; minus the meridian convergence). Offsets are turned by it, so the scene's
    // north is true north at the first wellhead, as the paths' azimuths are.
    double trueNorthGridAzimuth_deg = 0.0;
};
inline bool operator==(const Wellhead& a, const Wellhead& b) {
    return a.easting_m == b.easting_m && a.northing_m == b.northing_m &&
           a.elevation_m == b.elevation_m && a.frame == b.frame &&
           a.trueNorthGridAzimuth_deg == b.trueNorthGridAzimuth_deg;
}
inline bool operator!=(const Wellhead& a, const Wellhead& b) {
    return !(a == b);
}

// Offset of `well` from the scene origin `origin` (the first wellhead) in the
// analysis frame: north, east (the grid offset turned to true north at the origin),
// and down (a higher wellhead has a negative down offset). Put it in
// GeometryOptions::wellheadOffset.
inline Ned wellheadOffset(const Wellhead& well, const Wellhead& origin) {
    const double dn = well.northing_m - origin.northing_m;
    const double de = well.easting_m - origin.easting_m;
    const double down = origin.elevation_m - well.elevation_m;
    if (origin.trueNorthGridAzimuth_deg == 0.0) return {dn, de, down};
    // A grid azimuth a is the true azimuth a - t, t the grid azimuth of true north.
    const double t = origin.trueNorthGridAzimuth_deg * 3.14159265358979323846 / 180.0;
    return {dn * std::cos(t) + de * std::sin(t), de * std::cos(t) - dn * std::sin(t), down};
}

}  // namespace caliper3d::reconstruction
