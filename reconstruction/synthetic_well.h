#pragma once

#include <string>
#include <vector>

#include "io/section_table.h"

namespace caliper3d::reconstruction {

// A hole shape over a depth interval, with exact known geometry.
// Shapes are centred on the tool axis. Angles that orient a shape are "shape
// azimuths": P1AZ + clockwise arm angle, which is the true azimuth in a
// vertical hole.
struct SyntheticFeature {
    enum class Kind { Breakout, Washout };
    Kind kind = Kind::Breakout;
    double top_m = 0.0;
    double bottom_m = 0.0;
    double dmax_mm = 0.0;          // breakout: major axis; washout: diameter
    double dmin_mm = 0.0;          // breakout: minor axis
    double majorAzimuth_deg = 0.0; // breakout: azimuth of the major axis
};

// Trajectory: vertical to kickoff, then a constant build rate to the end of
// build, then hold; constant hole azimuth.
struct SyntheticWellSpec {
    double length_m = 300.0;
    double step_m = 0.05;
    int armCount = 6;
    double bitSize_mm = 215.9;     // 8.5 in
    double kickoff_m = 1e9;        // no build by default
    double buildRate_degPer30m = 0.0;
    double endOfBuild_m = 1e9;
    double holeAzimuth_deg = 0.0;
    double toolRotation_degPerM = 2.0;  // slow, steady pad-1 rotation
    std::vector<SyntheticFeature> features;
};

// Named profiles: "example" (vertical, breakout 60-80 m, washout 150-160 m,
// build from 100 m at 3 deg/30 m, hold), "circle" (gauge hole, vertical).
SyntheticWellSpec syntheticProfile(const std::string& name, double length_m, double step_m);
std::vector<std::string> syntheticProfileNames();

// Exact inclination at a measured depth for the spec's trajectory.
double syntheticInclination_deg(const SyntheticWellSpec& spec, double md_m);

// Samples the spec into a section table (radii in mm, P1AZ/DEVI/HAZI filled,
// bit size per row).
io::SectionTable makeSyntheticWell(const SyntheticWellSpec& spec);

// Radius from the centre of an ellipse with full axes dmax/dmin (mm) to its
// boundary along a direction `angle_deg` from the major axis.
double ellipseRadius_mm(double dmax_mm, double dmin_mm, double angle_deg);

}  // namespace caliper3d::reconstruction
