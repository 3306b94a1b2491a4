#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/azimuth_north.h"
#include "io/diagnostics.h"
#include "io/section_table.h"
#include "io/well_location.h"

namespace caliper3d::io {

// One curve as `caliper3d info` lists it.
struct CurveInfo {
    std::string mnemonic;
    std::string unit;
    std::string role;
    std::size_t nulls = 0;
    std::string description;  // the file's own (LAS ~C description), for choosing by hand
};

// What `caliper3d info` prints about a log.
struct LogInfo {
    std::string file;
    std::string format;  // "LAS 2.0", "column text (depth R1..R6 P1AZ DEVI HAZI)", ...
    std::string wellName;
    WellLocation location;  // from the LAS header (empty for column text)
    // The casing program: --casing, else the LAS ~Parameter section (io/casing_program.h).
    std::vector<CasingString> casing;
    std::string holeAzimuth;  // where the hole azimuth comes from (io::holeAzimuthPlan)
    AzimuthNorth north;       // the north of its azimuth curves (docs/conventions.md, "North")
    std::string depthUnit;    // as written in the file
    std::size_t rows = 0;     // sections read
    double top_m = 0.0;
    double bottom_m = 0.0;
    double step_m = 0.0;  // median step
    int arms = 0;
    std::string armSource;          // "radii R1..R6", "diameters C1, C2", ...
    double bitSize_mm = kNaN;       // smallest bit size over the log
    double bitSizeMax_mm = kNaN;    // largest (differs when a BS curve steps down the hole)
    std::string declaredNull;       // LAS: the header's NULL as written ("" when none is declared)
    std::size_t firstDataLine = 0;  // 1-based line of the first data row in the file
    std::vector<CurveInfo> curves;
    // What a structured format says beyond the curves, as `info` prints it, one line each
    // (DLIS: origin, logical files, frames, channels with their dimensions, parameters).
    std::vector<std::string> details;
    Diagnostics diagnostics;
    bool cancelled = false;  // the read was stopped by its cancellation token
    bool survey = false;     // a deviation survey, described by describeLog: rows are stations
};

}  // namespace caliper3d::io
