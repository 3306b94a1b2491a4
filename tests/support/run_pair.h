#pragma once

// Two runs of one well with known differences, as the tests of comparing runs, colouring by
// change and the window's runs write them.

#include "reconstruction/synthetic/synthetic_well.h"

namespace caliper3d::reconstruction {

struct RunPairSpecs {
    SyntheticWellSpec first;
    SyntheticWellSpec second;
};

// A vertical hole `length_m` long logged every 5 cm by a 24-arm tool with a gamma ray, a round
// washout of 265.9 mm over [washoutTop_m, washoutTop_m + 2]. The second run: its counter
// 0.35 m deeper, its tool 90 degrees round, the washout 10 mm wider (as
// `synth --depth-offset 0.35 --tool-azimuth 90 --widen 10`).
RunPairSpecs widenedWashoutRuns(double length_m, double washoutTop_m);

}  // namespace caliper3d::reconstruction
