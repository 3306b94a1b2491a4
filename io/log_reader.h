#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "io/curve_roles.h"
#include "io/diagnostics.h"
#include "io/las_reader.h"
#include "io/section_table.h"
#include "io/units.h"

namespace caliper3d::io {

// How to read a caliper log of any supported format. Every lenient behaviour
// is a named option here with its default.
struct ReadOptions {
    int armCount = 6;                       // column text: radii per line
    std::optional<LengthUnit> depthUnit;    // overrides the file's (column text default: metres)
    std::optional<LengthUnit> radiusUnit;   // overrides the file's (column text default: inches)
    double rowStep_m = 0.01;                // column text with radii only: depth step per row
    NullPolicy nullPolicy = NullPolicy::Common;
    RoleOverrides roles;
    std::optional<double> bitSize_mm;       // overrides the file's BS
};

// What `caliper3d info` prints about a log.
struct CurveInfo {
    std::string mnemonic;
    std::string unit;
    std::string role;
    std::size_t nulls = 0;
};
struct LogInfo {
    std::string file;
    std::string format;       // "LAS 2.0", "column text (depth R1..R6 P1AZ DEVI HAZI)", ...
    std::string wellName;
    std::string depthUnit;    // as written in the file
    std::size_t rows = 0;     // sections read
    double top_m = 0.0;
    double bottom_m = 0.0;
    double step_m = 0.0;      // median step
    int arms = 0;
    std::string armSource;    // "radii R1..R6", "diameters C1, C2", ...
    double bitSize_mm = kNaN;
    std::vector<CurveInfo> curves;
    Diagnostics diagnostics;
};

struct LoadedLog {
    SectionTable table;
    LogInfo info;
};

// Reads a column-text or LAS 1.2/2.0/3.0 file (detected from its content)
// into a section table in metres, millimetres and degrees, sorted by depth.
// Throws ParseError naming file, line and what was expected.
LoadedLog loadCaliperLog(const std::string& path, const ReadOptions& options);
SectionTable readCaliperLog(const std::string& path, const ReadOptions& options, Diagnostics* diagnostics);

// The same from text in memory (`name` is used in messages).
LoadedLog loadCaliperText(std::string text, const std::string& name, const ReadOptions& options);

std::string formatLogInfo(const LogInfo& info);

// Turns a read LAS log into a section table by curve roles and units.
LoadedLog sectionsFromLas(const LasLog& las, const ReadOptions& options, Diagnostics& diagnostics);

}  // namespace caliper3d::io
