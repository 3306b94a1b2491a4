#include "support/run_pair.h"

namespace caliper3d::reconstruction {

RunPairSpecs widenedWashoutRuns(double length_m, double washoutTop_m) {
    RunPairSpecs runs;
    SyntheticWellSpec& first = runs.first;
    first.armCount = 24;
    first.length_m = length_m;
    first.step_m = 0.05;
    first.gammaRay = true;
    first.features.push_back({SyntheticFeature::Kind::Washout, washoutTop_m, washoutTop_m + 2.0,
                              265.9, 265.9, 0.0, 0.0});
    SyntheticWellSpec& second = runs.second;
    second = first;
    second.depthOffset_m = 0.35;
    second.initialToolAzimuth_deg = 90.0;
    second.features[0].dmax_mm += 10.0;
    second.features[0].dmin_mm += 10.0;
    return runs;
}

}  // namespace caliper3d::reconstruction
