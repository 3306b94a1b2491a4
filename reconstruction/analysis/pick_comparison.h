#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/picks_reader.h"
#include "reconstruction/analysis/well_analysis.h"

namespace caliper3d::reconstruction {

// One image-log pick beside what the caliper says at its depth (docs/analysis.md, "Picks").
struct PickAgreement {
    io::Pick pick;
    bool inLog = false;     // the pick lies within the logged interval
    bool breakout = false;  // typed as a breakout (or untyped): its azimuth is compared
    BoreholeClass caliperClass = BoreholeClass::NoData;  // at the pick's middle depth
    int zone = -1;  // the caliper zone (index in WellAnalysis::zones) the pick overlaps, -1 none
    // The caliper's major-axis azimuth there: the zone's mean, else the section's; NaN when
    // the caliper has none (round, no data, no orientation).
    double caliperAzimuth_deg = io::kNaN;
    double difference_deg = io::kNaN;  // axial difference, [0, 90]
};

struct PicksComparison {
    std::vector<PickAgreement> picks;
    std::size_t outsideLog = 0;
    std::size_t breakoutPicks = 0;         // picks typed as breakouts within the log
    std::size_t inCaliperBreakout = 0;     // ... overlapping a caliper breakout zone
    std::size_t compared = 0;              // ... with a caliper azimuth to compare
    double meanDifference_deg = io::kNaN;  // mean axial difference of those compared
    std::size_t within20 = 0;              // compared within 20 degrees
    std::size_t caliperZonesPicked = 0;    // caliper breakout zones that a pick overlaps
    std::size_t caliperBreakoutZones = 0;
};

// Whether a pick's type names a breakout: empty, containing BREAKOUT, or BO or BK (any case).
bool isBreakoutPick(const std::string& type);

// Each pick beside the caliper's class, zone and major-axis azimuth at its depth.
PicksComparison comparePicks(const std::vector<io::Pick>& picks, const WellAnalysis& analysis);

// The report's lines on the picks: the agreement, then one line per pick (at most `lines`).
std::string formatPicksComparison(const PicksComparison& comparison, std::size_t lines = 20);

}  // namespace caliper3d::reconstruction
