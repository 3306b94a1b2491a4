#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace caliper3d::io {

struct LasHeader;
struct ColumnSpec;
struct CurvePlan;
struct Diagnostics;

// Which north an azimuth is measured from (docs/conventions.md, "North").
enum class North : unsigned char { Unknown, True, Magnetic, Grid };

// "true north", "magnetic north", "grid north", "unknown north".
const char* northName(North north);
// "true", "magnetic" or "grid" (the option's words) as a North; Unknown for anything else.
North parseNorthWord(std::string_view word);

// Which north a curve's description (or a header item's value) names: "0 = TRUE NORTH",
// "Borehole Azimuth (True)", "relative to magnetic north", "grid azimuth", ... (the
// phrases are listed in docs/formats.md). Unknown when it names none, or several.
North northFromText(std::string_view text);

// One azimuth curve of a log and the north it is measured from.
struct CurveNorth {
    std::string mnemonic;
    std::string role;  // "pad-1 azimuth" or "hole azimuth"
    int angle = 0;     // its slot in CurvePlan::angleColumn (0 P1AZ, 2 HAZI)
    North north = North::Unknown;
    bool stated = false;   // its own description says (not inferred from the header or a sibling)
    std::string evidence;  // what said so: "its description 'HOLE AZIMUTH ... TRUE NORTH'"
};

// An angle a header gives (a declination or a grid convergence), east positive.
struct HeaderAngle {
    double deg = std::numeric_limits<double>::quiet_NaN();
    std::string source;  // "MDEC (~Parameter, line 123)", "~Other line 98: 'Magnetic ...'"
    bool found() const { return deg == deg; }
};

// What a log says about the north of its azimuths, read by the LAS reader; the
// declination itself is settled by reconstruction::resolveNorth (an option, this header
// or the magnetic model).
struct AzimuthNorth {
    std::vector<CurveNorth> curves;      // the log's pad-1 and hole azimuth curves, if any
    North headerNorth = North::Unknown;  // a header item naming the azimuth reference
    std::string headerNorthSource;
    HeaderAngle declination;  // MDEC, DECL, MAGDEC, ... or a ~Other remark
    HeaderAngle convergence;  // GRIDCONV, GCONV, ...
    double logYear = std::numeric_limits<double>::quiet_NaN();  // fractional year of the log
    std::string dateSource;  // "DATE 23-Feb-2014 (~Well, line 26)"
    // Settled by reconstruction::resolveNorth: which north every azimuth is from and the
    // declination applied, as `info`, the report and the window show it ("" not settled).
    std::string resolved;
};

// Reads the north of each azimuth curve of `plan` from its description, the
// declination, grid convergence, azimuth reference and log date from the header
// (mnemonics and phrases in docs/formats.md, "North"). Values it cannot read
// (a declination "N/A") are skipped with a warning in `diagnostics`.
AzimuthNorth readAzimuthNorth(const LasHeader* header, const std::vector<ColumnSpec>& columns,
                              const CurvePlan& plan, Diagnostics* diagnostics);

// A date as a LAS header writes it ("23-Feb-2014", "2014/02/23", "2014-02-23",
// "16-JAN-2016 0830AM", "09-Jan-18", "02/23/2014") as a fractional year (mid-day);
// NaN when it is none of these. A day-month order that cannot be told (03/04/2015)
// is read day first.
double parseLogYear(std::string_view text);

// "14.38", "13.39 EAST", "5.2 W", "-3.1 deg" as degrees east positive; NaN otherwise.
double parseEastAngle(std::string_view text);

}  // namespace caliper3d::io
