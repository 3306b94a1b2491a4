#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "reconstruction/analysis/depth_match.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/parallel/fill_array.h"

namespace caliper3d::reconstruction {

// One run of a well as the comparison reads it: its geometry (for the earth-frame outlines) and
// its analysis (shape, class, zones, casing check).
struct ComparedRun {
    const WellGeometry* geometry = nullptr;
    const WellAnalysis* analysis = nullptr;
};

// What the 95 % limit of a diameter's repeat-pass difference is for a tool (docs/analysis.md,
// "Repeatability"): an eight-pad imager's pad-pair diameters repeat within about 1.3 mm SD (95 %
// within 3 mm), a four-arm tool's pad pairs within about 2.1-2.5 mm SD (95 % within 5 mm).
inline constexpr double kImagerRepeatability95_mm = 3.0;
inline constexpr double kFourArmRepeatability95_mm = 5.0;
// The limit for a tool of `armCount` arms (pads or radii): six or more, the imager's; fewer (two
// diameters of a four-arm or four-pad tool), the four-arm one.
double repeatabilityLimit_mm(int armCount);

struct RunComparisonOptions {
    DepthMapping mapping;  // where each depth of run 1 lies in run 2
    // A diameter change beyond this is significant (the larger of the two tools' limits).
    double repeatability95_mm = kFourArmRepeatability95_mm;
    int azimuthBins = 72;  // earth-frame outlines compared every 5 degrees
    // Subtract each run's reading offset in casing of known inner diameter (CasingCheck).
    bool removeBias = true;
    int threads = 1;  // sections are compared in this many chunks at once
    // Compare the outlines (the wall at each azimuth) only where the orientation-free figures
    // say the section may have changed: a diameter (equivalent, dmin or dmax) differs by more
    // than this fraction of repeatability95_mm, or the major axes' azimuths (where both runs
    // have one) by more than kOutlineAxisTurn_deg. Elsewhere the outline is not compared
    // (SectionChange::outlineSkipped: no wall growth is reported there, and the note says why). 0,
    // the default: every section of two oriented runs (docs/analysis.md, "Two runs of one well").
    double outlineGate = 0.0;
    // Called for each section whose outlines are compared, with its run-1 row and the wall's
    // growth (run 2 minus run 1, each run's bias removed) at each of azimuthBins bins, bin k at
    // k * 360 / azimuthBins degrees clockwise from north (SectionProfiler). Called from the
    // comparing threads, each row once.
    std::function<void(std::size_t row1, const double* growth_mm)> outlineSink;
};

// The gate `caliper3d compare` uses: half the repeatability limit (1.5 mm for an imager).
inline constexpr double kCompareOutlineGate = 0.5;
// A major axis that turned by more than this between the runs opens the gate whatever the
// diameters say (a breakout that rotated keeps its size).
inline constexpr double kOutlineAxisTurn_deg = 10.0;

// Why a depth of the overlap is not compared: a run without data there (too few arms), with
// arms that did not open, or inside casing.
enum class NotCompared : unsigned char {
    None,
    NoData1,
    ArmsNotOpen1,
    Cased1,
    NoData2,
    ArmsNotOpen2,
    Cased2
};
// "", "run 1 no data", "run 1 arms not open", "run 1 cased", "run 2 ...".
std::string_view notComparedText(NotCompared reason);

// One depth of the overlap (run 1's sampling). Diameters and areas are corrected for each run's
// bias; a quantity that is not compared is NaN.
struct SectionChange {
    double md1_m = 0.0, md2_m = 0.0;
    BoreholeClass class1 = BoreholeClass::InGauge, class2 = BoreholeClass::InGauge;
    NotCompared notCompared = NotCompared::None;
    double deq1_mm = io::kNaN, deq2_mm = io::kNaN;
    double dmin1_mm = io::kNaN, dmin2_mm = io::kNaN;
    double dmax1_mm = io::kNaN, dmax2_mm = io::kNaN;
    double area1_mm2 = io::kNaN, area2_mm2 = io::kNaN;
    double majorAzimuth1_deg = io::kNaN, majorAzimuth2_deg = io::kNaN;  // [0, 180); NaN: none
    // Both runs oriented: the largest growth of the wall's distance from the hole centre at one
    // azimuth (run 2 minus run 1; negative where the wall only closed in) and that azimuth.
    bool oriented = false;
    double maxGrowth_mm = io::kNaN;
    double maxGrowthAzimuth_deg = io::kNaN;  // [0, 360); NaN where the growth is uniform
    bool significant = false;  // a diameter changed by more than the repeatability limit
    // Both runs oriented, but the outline not compared: every diameter within the gate and the
    // major axis turned less than kOutlineAxisTurn_deg (RunComparisonOptions::outlineGate).
    bool outlineSkipped = false;

    bool compared() const { return notCompared == NotCompared::None; }
};

// Below this spread of the wall's growth round the section (largest minus smallest), the growth
// is uniform and has no azimuth (the report's axisMinElongation_mm for a change of shape).
inline constexpr double kUniformGrowth_mm = 0.5;

// A zone of either run, paired with the other run's zone of the same class over the same depths.
struct ZoneChange {
    enum class Kind : unsigned char { Appeared, Grew, Shrank, Unchanged, Closed };
    Kind kind = Kind::Unchanged;
    BoreholeClass cls = BoreholeClass::Breakout;
    double top1_m = 0.0, bottom1_m = 0.0;     // in run 1's depths (both runs' zones together)
    double top2_m = 0.0, bottom2_m = 0.0;     // the same in run 2's depths
    double length1_m = 0.0, length2_m = 0.0;  // each run's zone (0 where it has none)
    double meanDeqChange_mm = io::kNaN;       // over the compared sections of the zone
    double maxDmaxChange_mm = io::kNaN;       // the largest |change| of dmax, signed
    double maxDmaxChangeAt_m = io::kNaN;      // its depth (run 1)
};
// "appeared", "grew", "shrank", "unchanged", "closed".
std::string_view zoneChangeName(ZoneChange::Kind kind);

// Where the runs differ by more than the repeatability: consecutive significant sections.
struct ChangedInterval {
    double top1_m = 0.0, bottom1_m = 0.0;
    std::size_t sections = 0;
    double maxDeqChange_mm = 0.0;  // the largest |change|, signed
    double maxDeqChangeAt_m = 0.0;
};

// The reading offset removed from one run: the median reading in casing of known inner diameter
// minus that diameter (WellAnalysis::casing); NaN when the run has no such reading.
struct RunBias {
    double offset_mm = io::kNaN;
    double casingId_mm = io::kNaN;
    std::size_t sections = 0;
};

// The largest change of one quantity and where.
struct LargestChange {
    double change = io::kNaN;  // signed; NaN: nothing compared
    double md1_m = io::kNaN;
    double azimuth_deg = io::kNaN;  // for the wall's growth
};

struct RunComparison {
    DepthMapping mapping;
    double repeatability95_mm = 0.0;
    FillArray<SectionChange> sections;  // every depth of run 1 that run 2 also logged
    double overlapTop1_m = io::kNaN, overlapBottom1_m = io::kNaN;
    std::size_t compared = 0;         // sections compared
    std::size_t oriented = 0;         // of which both runs oriented (azimuths compared)
    std::size_t outlinesSkipped = 0;  // of which both runs oriented, outline not compared
    double outlineGate_mm = 0.0;      // the diameter change below which it was not (0: none)
    std::size_t notCompared[7] = {};  // by NotCompared reason
    std::size_t significant = 0;
    double significant_m = 0.0;    // their combined length (one step each)
    std::size_t classChanges = 0;  // compared sections whose class differs
    RunBias bias1, bias2;
    LargestChange deq, dmin, dmax, growth;
    std::vector<ZoneChange> zones;
    std::vector<ChangedInterval> changed;
    // Hole volume of each run over the compared steps of the overlap (both ends compared),
    // trapezoid rule along run 1's depths, and that length.
    double volume1_m3 = 0.0, volume2_m3 = 0.0, volumeLength_m = 0.0;
    bool unoriented1 = false, unoriented2 = false;  // a run with no oriented section compared

    bool agree() const { return compared > 0 && significant == 0; }
};

// Compares run 2 with run 1 depth by depth over their overlap, in the earth frame
// (docs/analysis.md, "Two runs of one well"). Throws std::runtime_error when no depth of run 1
// maps into run 2's logged interval.
RunComparison compareRuns(const ComparedRun& run1, const ComparedRun& run2,
                          const RunComparisonOptions& options);

}  // namespace caliper3d::reconstruction
