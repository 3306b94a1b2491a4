#include "reconstruction/load/load_well.h"

#include <atomic>
#include <cmath>
#include <exception>

#include "io/hole_azimuth_plan.h"
#include "io/log_stream.h"
#include "reconstruction/load/hole_azimuth.h"
#include "reconstruction/load/well_input.h"
#include "reconstruction/load/well_warnings.h"
#include "reconstruction/load/wellhead_placement.h"

namespace caliper3d::reconstruction {

GeometryOptions geometryOptions(const LoadOptions& options) {
    GeometryOptions g;
    g.splinePoints = options.splinePoints;
    g.segmentLength_m = options.segmentLength_m;
    g.shapeTolerance_mm = options.shapeTolerance_mm;
    g.radialExaggeration = options.radialExaggeration;
    g.steepInclination_deg = options.steepInclination_deg;
    g.maxArmRadius_mm = options.toolReach_mm;
    g.minValidArmFraction = options.minValidArmFraction;
    g.cancel = options.cancel;
    return g;
}

CheckedSurvey readCheckedSurvey(const std::string& path, const io::ReadOptions& options,
                                io::Diagnostics* diagnostics) {
    io::SurveyReadOptions survey;
    if (options.depthUnit) survey.depthUnit = options.depthUnit;
    CheckedSurvey out;
    out.table = io::readSurvey(path, survey, diagnostics);
    out.check = checkSurveyPositions(out.table);
    if (diagnostics && (out.check.maxTvdDifference_m > kSurveyPositionTolerance_m ||
                        out.check.maxHorizontalDifference_m > kSurveyPositionTolerance_m))
        diagnostics->warn(path, out.table.headerLine,
                          "the positions the file writes disagree with minimum curvature from its "
                          "own MD, inclination and azimuth: " +
                              describeSurveyPositionCheck(out.check) +
                              " (the path drawn is the minimum-curvature one)");
    return out;
}

GeometryOptions wellGeometryOptions(const WellSource& source, const LoadOptions& options,
                                    const Wellhead& origin, io::Diagnostics* diagnostics) {
    GeometryOptions geometry = geometryOptions(options);
    if (!source.surveyPath.empty())
        geometry.survey =
            surveyStations(readCheckedSurvey(source.surveyPath, options.read, diagnostics).table);
    // A well without --wellhead is placed from its header in the field frame of the first
    // well (sceneOrigin); with no frame, at the origin as before.
    if (source.wellhead) {
        geometry.wellheadOffset = wellheadOffset(*source.wellhead, origin);
    } else if (!origin.frame.empty()) {
        const WellPlacement placed = placeWell(source, origin);
        if (placed.wellhead)
            geometry.wellheadOffset = wellheadOffset(*placed.wellhead, origin);
        else if (diagnostics)
            diagnostics->warn(source.path, 0,
                              "not placed in the field (" + placed.description +
                                  "): drawn at the first well's head; give --wellhead E,N,ELEV");
    }
    return geometry;
}

bool operator==(const LoadOptions& a, const LoadOptions& b) {
    return a.read == b.read && a.splinePoints == b.splinePoints &&
           a.segmentLength_m == b.segmentLength_m && a.shapeTolerance_mm == b.shapeTolerance_mm &&
           a.radialExaggeration == b.radialExaggeration && a.colour == b.colour &&
           a.steepInclination_deg == b.steepInclination_deg && a.toolReach_mm == b.toolReach_mm &&
           a.minValidArmFraction == b.minValidArmFraction &&
           a.geometryWarnings == b.geometryWarnings && a.cancel == b.cancel &&
           a.readThreads == b.readThreads;
}

io::ReadOptions readOptionsFor(const WellSource& source, const LoadOptions& options) {
    io::ReadOptions read = options.read;
    if (source.casing) read.casing = *source.casing;
    return read;
}

LoadedWell loadWell(const WellSource& source, const LoadOptions& options, const Wellhead& origin) {
    LoadedWell out;
    const GeometryOptions geometry = wellGeometryOptions(source, options, origin, &out.diagnostics);
    io::StreamOptions stream;
    stream.cancel = options.cancel;  // checked per block: ReadCancelled
    stream.threads = options.readThreads;
    out.table = std::make_shared<const io::SectionTable>(
        loadWellTable(source.path, readOptionsFor(source, options), !source.surveyPath.empty(),
                      &out.diagnostics, stream));
    out.geometry = std::make_shared<const WellGeometry>(out.table, geometry);
    if (options.geometryWarnings) warnGeometry(*out.geometry, out.diagnostics);
    return out;
}

Wellhead sceneOrigin(const std::vector<WellSource>& wells) {
    if (wells.empty()) return {};
    const WellSource& first = wells.front();
    const io::WellLocation location = io::readWellLocationOf(first.path, nullptr);
    const std::string frame = fieldFrameOf(location);
    Wellhead origin;
    if (first.wellhead) {
        origin = *first.wellhead;  // its values are taken to be in the frame of its header
    } else {
        const WellPlacement placed = placeFromHeader(location, frame);
        if (!placed.wellhead) return {};  // nothing to place the others from
        origin = *placed.wellhead;
        if (!std::isfinite(origin.elevation_m)) origin.elevation_m = 0.0;
    }
    origin.frame = frame;
    origin.trueNorthGridAzimuth_deg =
        trueNorthGridAzimuth(frame, origin.easting_m, origin.northing_m);
    return origin;
}

}  // namespace caliper3d::reconstruction
