#pragma once

#include <utility>
#include <vector>

namespace caliper3d::reconstruction {

// Hole and cement volumes over [top_m, bottom_m] (measured depth), by the
// trapezoid rule along the hole on section areas (perpendicular to the hole
// axis, so the integral along MD is the volume).
struct VolumeOptions {
    double top_m = -1e300;  // interval; clipped to the sections
    double bottom_m = 1e300;
    double casingOd_mm = 0.0;  // casing outer diameter; 0 = open hole only
    double excess = 0.0;       // cement excess as a fraction (0.3 = 30 %)
};
struct HoleVolume {
    double top_m = 0.0, bottom_m = 0.0;
    double hole_m3 = 0.0;          // from the true section areas
    double gaugeHole_m3 = 0.0;     // from the bit size (nominal hole)
    double annulus_m3 = 0.0;       // true hole minus casing
    double gaugeAnnulus_m3 = 0.0;  // bit-size hole minus casing
    double cement_m3 = 0.0;        // annulus * (1 + excess)
    double gaugeCement_m3 = 0.0;   // gaugeAnnulus * (1 + excess)
    double casingOd_mm = 0.0;      // as asked for
    double excess = 0.0;
    // Where a step touches a section without data neither volume is
    // integrated: these [top, bottom] MD intervals (clipped to the interval,
    // in depth order) are not in any figure above, gauge ones included.
    std::vector<std::pair<double, double>> uncovered;
    double uncovered_m = 0.0;  // their combined length
    // Where a step touches a section inside casing (class cased) neither volume is
    // integrated either: these intervals, in depth order, are the cased hole the figures
    // above leave out (open hole only).
    std::vector<std::pair<double, double>> cased;
    double cased_m = 0.0;
};

// The hole and cement volumes, one step from section to section in depth order (md
// ascending; a bit size of NaN adds nothing to the gauge volumes).
class HoleVolumeAccumulator {
public:
    // firstMd_m and lastMd_m: measured depths of the first and last sections.
    HoleVolumeAccumulator(const VolumeOptions& options, double firstMd_m, double lastMd_m);
    // The step from one section (md, area, bit size) to the next.
    void addStep(double md0_m, double area0_mm2, double bit0_mm, double md1_m, double area1_mm2,
                 double bit1_mm);
    // A step from or to a section without data: not integrated, recorded as uncovered.
    void addUncoveredStep(double md0_m, double md1_m);
    // A step from or to a section inside casing: not integrated, recorded as cased.
    void addCasedStep(double md0_m, double md1_m);
    HoleVolume result() const;

private:
    VolumeOptions m_options;
    HoleVolume m_volume;
    double m_casing_m2 = 0.0;
};

}  // namespace caliper3d::reconstruction
