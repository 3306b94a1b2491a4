#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "reconstruction/analysis/borehole_classifier.h"

namespace caliper3d::reconstruction {

// Mean and spread of axial data (orientations defined modulo 180 degrees) by
// doubled angles (Mardia 1972; as the WSM guidelines prescribe for breakouts):
// mean = atan2(sum w sin 2a, sum w cos 2a) / 2, R = |resultant| / sum w,
// circular SD = sqrt(-2 ln R) / 2 (in degrees). NaN inputs are skipped.
struct AxialStatistics {
    double mean_deg = 0.0;  // [0, 180), NaN when no data
    double sd_deg = 0.0;    // NaN when no data
    double weight = 0.0;    // sum of the weights used
};
AxialStatistics axialStatistics(const std::vector<double>& angles_deg,
                                const std::vector<double>& weights = {});

// A run of consecutive sections of one class (not in_gauge, cased nor no_data).
struct Zone {
    BoreholeClass kind = BoreholeClass::Breakout;
    double top_m = 0.0;
    double bottom_m = 0.0;
    double length_m = 0.0;  // bottom - top, plus half a step at each end
    std::size_t firstSection = 0;
    std::size_t lastSection = 0;
    double meanAzimuth_deg = 0.0;  // of the major axis, doubled-angle mean, [0, 180)
    double circularSd_deg = 0.0;
    double meanDmax_mm = 0.0;
    double meanDmin_mm = 0.0;
};

// Zones of every class but in_gauge, cased and no_data, in depth order. `majorAzimuth_deg` may
// hold NaN (a horizontal hole with a vertical major axis): skipped in the mean.
std::vector<Zone> detectZones(const std::vector<double>& md_m,
                              const std::vector<BoreholeClass>& classes,
                              const std::vector<double>& majorAzimuth_deg,
                              const std::vector<double>& dmax_mm,
                              const std::vector<double>& dmin_mm);
// The same for a caller that keeps its sections in another layout: the
// functions give section i's values (asked only for sections in a zone and
// their neighbours).
std::vector<Zone> detectZones(const std::vector<BoreholeClass>& classes,
                              const std::function<double(std::size_t)>& md_m,
                              const std::function<double(std::size_t)>& majorAzimuth_deg,
                              const std::function<double(std::size_t)>& dmax_mm,
                              const std::function<double(std::size_t)>& dmin_mm);

// World Stress Map quality of the breakouts of one well (Heidbach et al.
// 2010, WSM Technical Report 16-01, table 2; also Zoback 2007, table 6.1):
// A: >= 10 zones, combined length >= 300 m, SD <= 12 deg;
// B: >= 6 zones, >= 100 m, SD <= 20; C: >= 4 zones, >= 30 m, SD <= 25;
// D: fewer zones or less length, SD <= 40; E: no breakouts or SD > 40.
// (Reinecker et al. 2003 used 100, 40 and 20 m: set the lengths to those.)
struct WsmQualityRules {
    int zonesA = 10, zonesB = 6, zonesC = 4;
    double lengthA_m = 300.0, lengthB_m = 100.0, lengthC_m = 30.0;
    double sdA_deg = 12.0, sdB_deg = 20.0, sdC_deg = 25.0, sdD_deg = 40.0;
};
struct BreakoutSummary {
    int zoneCount = 0;
    double combinedLength_m = 0.0;
    double meanAzimuth_deg = 0.0;  // length-weighted doubled-angle mean of the zones (NaN: none)
    double circularSd_deg = 0.0;
    double shmaxAzimuth_deg = 0.0;  // breakouts form along Shmin: SHmax = mean + 90 (vertical well)
    char quality = 'E';
};
BreakoutSummary summariseBreakouts(const std::vector<Zone>& zones,
                                   const WsmQualityRules& rules = {});

}  // namespace caliper3d::reconstruction
