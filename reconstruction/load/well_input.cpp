#include "reconstruction/load/well_input.h"

#include <sstream>
#include <string>

#include "io/log_reader.h"
#include "io/parse_error.h"
#include "reconstruction/load/hole_azimuth.h"
#include "reconstruction/path/north_reference.h"

namespace caliper3d::reconstruction {

namespace {

// The unit of the first caliper curve named in info.armSource ("radii R1 R2 ...",
// "diameters C1 C2"); empty when the file gave none.
std::string caliperUnit(const io::LogInfo& info) {
    std::istringstream words(info.armSource);
    std::string kind, first;
    words >> kind >> first;
    for (const io::CurveInfo& curve : info.curves)
        if (curve.mnemonic == first) return curve.unit;
    return {};
}

}  // namespace

io::SectionTable loadWellTable(const std::string& path, const io::ReadOptions& options,
                               bool surveyGiven, io::Diagnostics* diagnostics,
                               const std::atomic<bool>* cancel) {
    io::StreamOptions stream;
    stream.cancel = cancel;  // checked per block: ReadCancelled
    return loadWellTable(path, options, surveyGiven, diagnostics, stream);
}

io::SectionTable loadWellTable(const std::string& path, const io::ReadOptions& options,
                               bool surveyGiven, io::Diagnostics* diagnostics,
                               const io::StreamOptions& stream) {
    io::LoadedLog loaded = io::loadCaliperLog(path, options, stream);
    if (loaded.table.armCount == 0)
        throw io::ParseError(path, 0, 0,
                             "expected caliper curves (radii R1..Rn, RAD1..n, fingers F01..Fnn, "
                             "diameters C1, C2, or one diameter CALI), found none among " +
                                 std::to_string(loaded.info.curves.size()) +
                                 " curves; name them with --radii or --diameters");
    if (diagnostics) diagnostics->merge(loaded.info.diagnostics);
    loaded.table.wellName = loaded.info.wellName;
    loaded.table.fileDepthUnit = loaded.info.depthUnit;
    loaded.table.fileCaliperUnit = caliperUnit(loaded.info);
    // Azimuths to true north before a hole azimuth is derived from the pad-1 azimuth.
    const NorthCorrection north = resolveNorth(loaded.info.north, loaded.info.location, options);
    applyNorth(loaded.table, north);
    if (diagnostics)
        for (const std::string& warning : north.warnings) diagnostics->warn(path, 0, warning);
    loaded.table.casing = options.casing.empty() ? loaded.info.casing : options.casing;
    resolveHoleAzimuth(loaded.table, io::holeAzimuthPlan(loaded.info, surveyGiven), diagnostics);
    return std::move(loaded.table);
}

}  // namespace caliper3d::reconstruction
