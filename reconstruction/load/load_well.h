#pragma once

#include <atomic>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/diagnostics.h"
#include "io/read_options.h"
#include "io/section_table.h"
#include "io/survey_reader.h"
#include "reconstruction/analysis/wall_colour_request.h"
#include "reconstruction/path/survey_interpolation.h"
#include "reconstruction/path/wellhead.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// One well to load: its log, and optionally its deviation survey (replacing
// the log's DEVI/HAZI for the path) and its wellhead (placing it beside the
// other wells of a scene).
struct WellSource {
    std::string path;
    std::string surveyPath{};  // empty: the path comes from the log's own DEVI/HAZI
    std::optional<Wellhead> wellhead{};
    std::string picksPath{};  // image-log picks shown beside the caliper (io::readPicks); "" none
    // This log's casing program (--casing-each), replacing its header's and any program given
    // for all wells; nullopt: those. Runs of one well logged weeks apart each see the casing
    // set when they were logged.
    std::optional<std::vector<io::CasingString>> casing{};
};
inline bool operator==(const WellSource& a, const WellSource& b) {
    return a.path == b.path && a.surveyPath == b.surveyPath && a.wellhead == b.wellhead &&
           a.picksPath == b.picksPath && a.casing == b.casing;
}
inline bool operator!=(const WellSource& a, const WellSource& b) {
    return !(a == b);
}

// How a well is read and reconstructed: the reader's options and the geometry
// settings every verb and the window share (design section 8, "common").
struct LoadOptions {
    io::ReadOptions read;
    int splinePoints = 48;
    double segmentLength_m = 0.0;    // 0: automatic (autoSegmentLength, well_geometry.h)
    double shapeTolerance_mm = 0.5;  // level-of-detail shape error of the finest coarse level
    double radialExaggeration = 1.0;
    // What the wall is coloured by. Applied by the callers that draw (the window after its
    // streamed load, app::assembleScene), with makeWallColouring and WellGeometry::restyled.
    ColourRequest colour;
    double steepInclination_deg = 15.0;  // above this, arm 1 comes from RB when present
    double toolReach_mm = 1.0e9;         // arm readings beyond this are repaired
    // A section with fewer valid arms than minValidArms(armCount, this) has no data.
    double minValidArmFraction = kDefaultMinValidArmFraction;
    // Add warnGeometry's warnings (no-data intervals, interpolated arms) to the
    // diagnostics. A caller that analyses the well sets it false and adds
    // warnAnalysis's instead: the same warnings from the analysis's counts,
    // without a second scan of every row.
    bool geometryWarnings = true;
    // Set from another thread, stops the log's read within a block (io::ReadCancelled).
    const std::atomic<bool>* cancel = nullptr;
    // Threads parsing the log (io::StreamOptions::threads, 1 or 2): 1 where several wells are
    // read at once, each in its own process (caliper3d batch -j 2).
    int readThreads = 2;
};
// Every field, the cancel token by identity: two wells loaded alike compare equal, so the
// window can tell whether its wells share one set of options without formatting them.
bool operator==(const LoadOptions& a, const LoadOptions& b);
inline bool operator!=(const LoadOptions& a, const LoadOptions& b) {
    return !(a == b);
}

// A loaded well: its table, its geometry (path and frames; segments are built
// on demand), and every warning met on the way, in order: the survey's (and
// its position check), the log reader's, the hole azimuth's, the geometry's.
struct LoadedWell {
    std::shared_ptr<const io::SectionTable> table;
    std::shared_ptr<const WellGeometry> geometry;
    io::Diagnostics diagnostics;
};

// The one recipe for loading a well, used by every verb, the window and the
// load pipeline: reads and checks the survey (when given), reads the log
// (reconstruction::loadWellTable: refuses a log without caliper curves, settles
// the hole azimuth), places the wellhead relative to the scene origin `origin`
// and builds the geometry. The survey is read first: it is small, and a bad
// one fails the well before a large log is read. Throws io::ParseError naming
// the file, line and what was expected; makes no Coin or Qt call.
LoadedWell loadWell(const WellSource& source, const LoadOptions& options,
                    const Wellhead& origin = {});

// Geometry options of a plain well (no survey, at the scene origin).
GeometryOptions geometryOptions(const LoadOptions& options);
// How `source` is read under `options`: its own casing program (WellSource::casing) in place
// of the one given for all wells.
io::ReadOptions readOptionsFor(const WellSource& source, const LoadOptions& options);
// Geometry options of `source`: its survey read and checked first (its warnings to
// `diagnostics`, may be null) and its wellhead placed relative to `origin`.
GeometryOptions wellGeometryOptions(const WellSource& source, const LoadOptions& options,
                                    const Wellhead& origin, io::Diagnostics* diagnostics);

// A deviation survey as read, and how the positions it writes (TVD, N, E)
// agree with minimum curvature from its own MD, inclination and azimuth.
struct CheckedSurvey {
    io::SurveyTable table;
    SurveyPositionCheck check;
};
// Reads a survey (its depth unit from options.depthUnit when given) and checks
// its positions. Its warnings, and one when the positions disagree by more
// than kSurveyPositionTolerance_m, go to `diagnostics` (may be null). Throws
// io::ParseError naming the survey file and line.
CheckedSurvey readCheckedSurvey(const std::string& path, const io::ReadOptions& options,
                                io::Diagnostics* diagnostics);

// The scene origin: the first well's wellhead, by --wellhead or from its header
// (wellhead_placement.h), with the field frame its header defines (Wellhead::frame); zero
// with no frame when neither gives one. A well without --wellhead is placed from its header
// in that frame (wellGeometryOptions), relative to this origin.
Wellhead sceneOrigin(const std::vector<WellSource>& wells);

}  // namespace caliper3d::reconstruction
