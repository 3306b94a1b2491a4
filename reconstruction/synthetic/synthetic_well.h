#pragma once

#include <string>
#include <vector>

#include "io/section_table.h"

namespace caliper3d::reconstruction {

// A hole shape over a depth interval, with exact known geometry. The radii
// are exact ray intersections from the tool axis with the shape in the
// section plane. An orienting angle is a true azimuth (the azimuth of the
// in-plane direction's horizontal projection, docs/conventions.md, "Azimuth of an
// in-plane direction"), or, for a
// key seat, an angle clockwise from the high side.
struct SyntheticFeature {
    // Breakout: ellipse dmax x dmin, major axis at majorAzimuth_deg.
    // Washout and Undergauge: circle of diameter dmax.
    // Keyseat: ellipse dmax x dmin with the major axis majorAzimuth_deg from the
    // high side, its centre shifted `offset_mm` that way (a groove on one side).
    enum class Kind { Breakout, Washout, Keyseat, Undergauge };
    Kind kind = Kind::Breakout;
    double top_m = 0.0;
    double bottom_m = 0.0;
    double dmax_mm = 0.0;
    double dmin_mm = 0.0;
    double majorAzimuth_deg = 0.0;
    double offset_mm = 0.0;
};

// Trajectory: vertical to kickoff, then a constant build rate to the end of
// build (or until maxInclination_deg, whichever comes first), then hold;
// constant hole azimuth.
struct SyntheticWellSpec {
    double length_m = 300.0;
    double step_m = 0.05;
    int armCount = 6;
    double bitSize_mm = 215.9;  // 8.5 in
    double kickoff_m = 1e9;     // no build by default
    double buildRate_degPer30m = 0.0;
    double endOfBuild_m = 1e9;
    // Real wells land near horizontal and hold: a build never goes past this,
    // however long the well (a 4 km "example" would otherwise turn past 180
    // degrees and climb back up, which no reader accepts).
    double maxInclination_deg = 90.0;
    double holeAzimuth_deg = 0.0;
    double toolRotation_degPerM = 2.0;  // slow, steady pad-1 rotation
    std::vector<SyntheticFeature> features;
    // Inclination above the kickoff (a slant or a hold from the top).
    double initialInclination_deg = 0.0;
    // Constant turn rate of the hole azimuth from turnStart_m (a helix when
    // the inclination is constant).
    double turnRate_degPer30m = 0.0;
    double turnStart_m = 0.0;
    // The hole centre lies this far from the tool axis, towards this azimuth.
    double toolOffset_mm = 0.0;
    double toolOffsetAzimuth_deg = 0.0;
    // Arm `stuckArm` (1-based; 0: none) reads stuckValue_mm (0 = closed) over [stuckTop_m,
    // stuckBottom_m].
    int stuckArm = 0;
    double stuckTop_m = 0.0;
    double stuckBottom_m = 0.0;
    double stuckValue_mm = 0.0;
    // A second run of the same hole (docs/analysis.md, "Two runs of one well"):
    // the first row's written depth (rows run from it over length_m);
    double top_m = 0.0;
    // the run's depth counter reads this much deeper than the true depth (every feature, the
    // path and the tool's turn are those of the true depth: written depth - depthOffset_m);
    double depthOffset_m = 0.0;
    // pad 1's azimuth at true depth 0 (a tool that sits differently in another pass);
    double initialToolAzimuth_deg = 0.0;
    // every arm reads closedRadius_mm over [closedTop_m, closedBottom_m] (true depths): a pass
    // whose arms did not open (closedBottom_m < closedTop_m: none);
    double closedTop_m = 0.0;
    double closedBottom_m = -1.0;
    double closedRadius_mm = 0.0;
    // and a gamma-ray curve GR (gAPI) of the true depth (syntheticGammaRay_api), which both
    // runs share.
    bool gammaRay = false;
};

// Named profiles, each with an exact known answer (lengths scale with L):
//   example     breakout 0.2-0.267 L (245.9 x 217.9 at 135 deg), washout 0.5-0.533 L
//               (265.9), build from L/3 at 3 deg/30 m to 5/6 L, hold; azimuth 45
//   circle      gauge hole (215.9 mm), vertical      vertical  the same
//   ellipse     245.9 x 217.9 mm ellipse, major axis at azimuth 60, whole well, vertical
//   washout     circle of 255.9 mm over 0.4-0.6 L    undergauge  circle of 203.9 mm there
//   keyseat     build from 0.2 L at 6 deg/30 m, azimuth 120; over 0.6-0.8 L an ellipse
//               240.9 x 215.9 with its major axis on the high side, shifted 12.5 mm up
//   offcentre   gauge hole, tool 15 mm off centre (hole centre east of the tool)
//   stuck-arm   gauge hole, arm 3 reads 0 over 0.4-0.6 L
//   build       kickoff 0.1 L, 3 deg/30 m to TD, azimuth 30
//   hold        kickoff 0.1 L, 3 deg/30 m to 0.4 L, then hold, azimuth 30
//   turn        30 deg inclination from the top, azimuth 10 turning 3 deg/30 m (a helix)
SyntheticWellSpec syntheticProfile(const std::string& name, double length_m, double step_m);
std::vector<std::string> syntheticProfileNames();

// Exact inclination and hole azimuth at a measured depth for the spec's trajectory.
double syntheticInclination_deg(const SyntheticWellSpec& spec, double md_m);
double syntheticAzimuth_deg(const SyntheticWellSpec& spec, double md_m);

// A gamma-ray log of the formation at true depth `md_m` (gAPI): beds of every thickness from
// 0.4 m to 50 m as a sum of sinusoids of incommensurate periods, so that it repeats nowhere
// over a few kilometres and two runs correlate at one lag only.
double syntheticGammaRay_api(double md_m);

// Samples the spec into a section table (radii in mm, P1AZ/DEVI/HAZI and the
// matching RB filled, bit size per row).
io::SectionTable makeSyntheticWell(const SyntheticWellSpec& spec);

// Radius from the centre of an ellipse with full axes dmax/dmin (mm) to its
// boundary along a direction `angle_deg` from the major axis.
double ellipseRadius_mm(double dmax_mm, double dmin_mm, double angle_deg);

}  // namespace caliper3d::reconstruction
