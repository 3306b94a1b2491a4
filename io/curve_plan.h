#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/diagnostics.h"
#include "io/las_header.h"
#include "io/log_info.h"
#include "io/read_options.h"
#include "io/section_table.h"

namespace caliper3d::io {

// One column of a log as the file declares it (a LAS ~C line, or a column of
// the reference text layout).
struct ColumnSpec {
    std::string mnemonic;
    std::string unit;
    std::string description;
    bool text = false;     // a string column (LAS 3.0 {S}): never parsed, NaN
    std::size_t line = 0;  // header line, for messages
};

// How one row of raw column values becomes one row of a SectionTable: which
// column plays which role and the factor that converts it to internal units.
// Built once from the header, then applied to every row (possibly on several
// threads: mapRow only reads the plan).
struct CurvePlan {
    int depthColumn = 0;
    double depthScale = 1.0;  // file unit -> metres
    int armCount = 0;
    std::vector<int> armColumn;             // per arm
    std::vector<double> armScale;           // file unit -> millimetres of radius (diameters halved)
    int angleColumn[4] = {-1, -1, -1, -1};  // P1AZ, DEVI, HAZI, RB
    double angleScale[4] = {1.0, 1.0, 1.0, 1.0};
    std::array<std::string, 4> angleName;  // the mnemonics, for messages
    // Added to the pad-1 azimuth and the relative bearing, so that the table holds arm 1's:
    // the angle from pad 1 to arm 1 (45 degrees for pairs 2-6 and 4-8 of an eight-pad tool).
    double arm1FromPad1_deg = 0.0;
    int bitSizeColumn = -1;
    double bitSizeScale = 1.0;
    double bitSizeConstant = kNaN;  // from a parameter or an override
    std::vector<int> extraColumns;
    std::vector<int> otherDepthColumns;  // second depth curves, compared with the index

    // An empty table whose optional curves and extra-curve list match the plan.
    SectionTable emptyTable(const std::vector<ColumnSpec>& columns) const;
    // Appends one row; `raw` holds one value per column, as written, NaN where null.
    void mapRow(const double* raw, SectionTable& out) const;
    // Throws ParseError naming `file` and `line` when an inclination lies
    // outside [0, 180] degrees or a pad or hole azimuth outside [0, 360]: such a
    // reading is bad input, not a well that turns back on itself. RB is not
    // checked (vendors write it in [0, 360) or in (-180, 180]).
    void checkAngles(const double* raw, const std::string& file, std::size_t line) const;
};

// Chooses roles and unit factors for `columns` (refusing, with the header
// line, a caliper curve in an unknown unit), fills `info` (curves and their
// roles, arm source, units) and notes lenient choices in `diagnostics`.
// `header` (LAS only) supplies STRT's unit and the BS parameter.
CurvePlan makeCurvePlan(const std::vector<ColumnSpec>& columns, const LasHeader* header,
                        const ReadOptions& options, const std::string& file, LogInfo& info,
                        Diagnostics& diagnostics);

// A column name of column text as mnemonic and unit: "R1_in", "BS(mm)",
// "DEVI[deg]" and "DEPTH" (no unit). A suffix after the last '_' is a unit only
// when it is a length or angle unit we know, so that "GR_API" or "RAD1_QH" stay whole.
std::pair<std::string_view, std::string_view> splitColumnName(std::string_view name);

// Factor to degrees for an angle unit (empty, DEG, RAD, ...); NaN when not an angle.
double angleScaleOf(const std::string& unit);

}  // namespace caliper3d::io
