#pragma once

#include <cstddef>
#include <functional>
#include <string_view>
#include <vector>

#include "reconstruction/section/section_coverage.h"

namespace caliper3d::reconstruction {

// Cased: inside a casing string, measured against its inner diameter (never a shape class;
// WellAnalysis sets it). NoData: too few valid arms to define the section, or arms that did
// not open (never a shape class; WellAnalysis sets it). Both are left out of zones,
// statistics and volumes.
enum class BoreholeClass : unsigned char {
    InGauge,
    Undergauge,
    Washout,
    Breakout,
    Keyseat,
    Cased,
    NoData
};

// "in_gauge", "undergauge", "washout", "breakout", "keyseat", "cased", "no_data": the
// report's names.
std::string_view className(BoreholeClass c);

// Every threshold of the classification (docs/analysis.md, "Classes"), with the
// published defaults: Plumb & Hickman 1985 (JGR 90, B7) for the elongation
// and bit-size tests; Reinecker, Tingay & Mueller 2003 (WSM guidelines) for
// zone length and tool rotation; Zoback, Reservoir Geomechanics (2007) pp.
// 184-185 for the key-seat test; JewelSuite caliper-filter defaults for the
// millimetre tolerances.
struct ClassificationRules {
    double gaugeTolerance_mm = 6.0;        // in_gauge: dmin and dmax within this of bit size
    double undergauge_mm = 6.0;            // undergauge: dmax < bit - this
    double washout_mm = 12.7;              // washout: dmin > bit + this (0.5 in)
    double elongation_mm = 6.0;            // breakout/keyseat: dmax - dmin >= this
    double breakoutMinGauge_mm = 12.7;     // ... with dmin within this of bit size
    double minBreakoutLength_m = 1.0;      // a breakout zone is at least this long
    double maxToolRotation_deg = 45.0;     // ... and the tool turns less than this
    double rotationWindow_m = 5.0;         //     per this length
    double deviatedInclination_deg = 5.0;  // above this the high-side test applies
    double highSideTolerance_deg = 15.0;   // major axis within this of high/low side: keyseat
    // Below this dmax - dmin the section is round: it has no major axis, and its
    // major_azimuth_deg and major_from_high_side_deg are empty (a fit through six
    // pads of a round hole 15 mm off the tool gives 0.13 mm of false elongation).
    double axisMinElongation_mm = 0.5;
    // A section with fewer valid arms than this fraction of its arms (at least
    // 2) has no data (section_coverage.h, docs/analysis.md).
    double minValidArmFraction = kDefaultMinValidArmFraction;
    // Arms that did not open (docs/analysis.md, "Arms not open"): a run of at least
    // armsClosedMinSections measured sections whose largest diameter stays more than
    // armsClosedFraction of the gauge below it (bit size, or the casing's inner diameter) is
    // no_data "arms not open", never undergauge.
    double armsClosedFraction = 0.15;
    double armsClosedMinSections = 5.0;  // a count of sections
};

// What the classifier needs of one section.
struct ClassifierInput {
    double md_m = 0.0;
    double dmin_mm = 0.0;
    double dmax_mm = 0.0;
    double bit_mm = 0.0;  // NaN: unknown (the section is in_gauge)
    double inc_deg = 0.0;
    double majorFromHighSide_deg = 0.0;  // major axis angle from the high side
    double toolAzimuth_deg = 0.0;        // pad-1 azimuth (or RB), NaN when unknown
};

// Class of one section from its shape alone; breakouts are only candidates
// here (see applyBreakoutZoneRules).
BoreholeClass classifyShape(const ClassifierInput& s, const ClassificationRules& rules);

// What tells a breakout from an elongation the tool made (docs/analysis.md, "Classes").
enum class BreakoutEvidence : unsigned char {
    // Pad-pair (four-arm) tools: pads lock into a breakout, so the tool stops turning there
    // (Plumb & Hickman 1985; Reinecker et al. 2003). `azimuth_deg` is the tool's (pad 1).
    ToolStops,
    // Tools that measure the whole section (six arms or more): the major axis stays fixed in
    // the earth frame whether or not the tool turns. `azimuth_deg` is the major axis's.
    AxisFixedInEarth,
};

// The evidence the zone rule asks of a tool with `arms` arms: the tool stopping for pad-pair
// tools (four arms or fewer), the major axis fixed in the earth frame for the others.
BreakoutEvidence breakoutEvidenceFor(int arms);

// The zone rules of breakouts over shape classes already in `classes` (ordered by depth): a
// run of breakout candidates shorter than minBreakoutLength_m, or over which the tool
// (ToolStops) or the major axis (AxisFixedInEarth, an axial angle) turns by
// maxToolRotation_deg or more within any rotationWindow_m (pro rata for shorter runs), is not
// a breakout: its sections become in_gauge. md_m(i) and azimuth_deg(i) give section i's
// measured depth and azimuth (asked only for breakout candidates and their neighbours; NaN
// where unknown, which turns nothing).
void applyBreakoutZoneRules(std::vector<BoreholeClass>& classes,
                            const std::function<double(std::size_t)>& md_m,
                            const std::function<double(std::size_t)>& azimuth_deg,
                            const ClassificationRules& rules,
                            BreakoutEvidence evidence = BreakoutEvidence::ToolStops);

}  // namespace caliper3d::reconstruction
