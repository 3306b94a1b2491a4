#pragma once

#include <cstddef>

#include "reconstruction/synthetic/synthetic_well.h"

namespace caliper3d::reconstruction {

// One well of a synthetic field (`caliper3d synth --field N`): its profile, where its head
// lies and which way it is drilled.
struct SyntheticFieldWell {
    SyntheticWellSpec spec;  // the profile, its hole azimuth the well's bearing on the ring
    std::string profile;
    double north_m = 0.0;      // wellhead, metres north of the first well's
    double east_m = 0.0;       // wellhead, metres east of the first well's
    double elevation_m = 0.0;  // kelly bushing elevation above the datum
};

// The wellhead spacing of a synthetic field: neighbours on the ring lie this far apart.
constexpr double kSyntheticFieldSpacing_m = 25.0;

// Well `index` (from 0) of a synthetic field of `wells` wells `length_m` long logged every
// `step_m`. The profiles come in turn (syntheticProfileNames()). The wellheads lie on a ring
// with kSyntheticFieldSpacing_m between neighbours (well 0 at the origin, the others clockwise
// from it seen from above), and each well is drilled away from the ring's centre: its hole
// azimuth is its own bearing from the centre (well 0's, 45 degrees, is the example profile's).
// So the wells of a field never cross, as planned wells must not (anti-collision), and the
// exaggeration of a field picture is capped by their spacing rather than a crossing. The
// kelly bushings stand 25, 26 and 27 m high in turn.
SyntheticFieldWell syntheticFieldWell(std::size_t index, std::size_t wells, double length_m,
                                      double step_m);

}  // namespace caliper3d::reconstruction
