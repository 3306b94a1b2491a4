#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "reconstruction/analysis/borehole_classifier.h"
#include "reconstruction/analysis/hole_volume.h"
#include "reconstruction/analysis/section_results.h"
#include "reconstruction/analysis/zone_detection.h"
#include "reconstruction/path/orientation_check.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// The tool's reading inside one casing string against the casing's nominal inner diameter: a
// calibration check of the run (docs/analysis.md, "Cased hole").
struct CasingCheck {
    io::CasingString casing;
    double top_m = io::kNaN, bottom_m = io::kNaN;  // the cased sections logged (NaN: none)
    std::size_t sections = 0;                      // measured sections inside it
    double medianDiameter_mm = io::kNaN;           // median equivalent diameter of those sections
    double offset_mm = io::kNaN;  // median - nominal inner diameter (NaN: either unknown)
};

struct AnalysisOptions {
    ClassificationRules rules;
    WsmQualityRules wsm;
    VolumeOptions volume;          // interval, casing and excess for the volumes
    double bitSize_mm = io::kNaN;  // --bit-size: overrides the log's BS when finite
    int threads = 1;               // sections are analysed in this many chunks at once
};

// The interval results and the counts the command reports as warnings.
struct WellAnalysis {
    SectionResults sections;  // one per section, in depth order
    std::vector<Zone> zones;  // every class but in_gauge, in depth order
    BreakoutSummary breakouts;
    HoleVolume volume;
    OrientationOffset padAzimuthOffset;  // P1AZ - f(HAZI, DEVI, RB); samples 0 when not all present
    std::size_t repairedSections = 0;    // sections with at least one arm interpolated
    std::size_t repairedArms = 0;
    std::size_t unorientedSections = 0;  // no P1AZ nor RB: azimuths unknown (measured sections)
    std::vector<NoDataInterval> noData;  // runs of sections without data (class no_data)
    std::size_t noDataSections = 0;      // in noData (too few valid arms)
    // Runs of sections whose arms did not open (class no_data, reason "arms not open";
    // ClassificationRules::armsClosedFraction): not in noData.
    std::vector<NoDataInterval> armsNotOpen;
    std::size_t armsNotOpenSections = 0;
    std::vector<CasingCheck> casing;   // one per casing string of the table, shallowest first
    bool bitSizeFromSections = false;  // no bit size anywhere: median equivalent diameter used
    bool holeAzimuthUnknown = false;   // inclined, no HAZI nor survey: see docs/conventions.md
    std::string north;                 // which north the azimuths are from: io::SectionTable::north
    bool twoPads = false;  // a two-pad tool: round sections, no breakout nor keyseat seen
};

// Analyses every section of the well (path, spline, shape, class), then the
// zones, breakout statistics and volumes. Pure; `threads` workers at most.
WellAnalysis analyseWell(const WellGeometry& geometry, const AnalysisOptions& options);

}  // namespace caliper3d::reconstruction
