#pragma once

#include "reconstruction/section/section_frame.h"

namespace caliper3d::reconstruction {

// Where a well starts: map easting and northing (metres, the same projected
// grid for every well of a scene) and the elevation of its depth reference
// (metres above datum, positive up), as given by --wellhead E,N,ELEV.
struct Wellhead {
    double easting_m = 0.0;
    double northing_m = 0.0;
    double elevation_m = 0.0;
};
inline bool operator==(const Wellhead& a, const Wellhead& b) {
    return a.easting_m == b.easting_m && a.northing_m == b.northing_m &&
           a.elevation_m == b.elevation_m;
}
inline bool operator!=(const Wellhead& a, const Wellhead& b) {
    return !(a == b);
}

// Offset of `well` from the scene origin `origin` (the first wellhead) in the
// analysis frame: north, east, and down (a higher wellhead has a negative
// down offset). Put it in GeometryOptions::wellheadOffset.
inline Ned wellheadOffset(const Wellhead& well, const Wellhead& origin) {
    return {well.northing_m - origin.northing_m, well.easting_m - origin.easting_m,
            origin.elevation_m - well.elevation_m};
}

}  // namespace caliper3d::reconstruction
