#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/diagnostics.h"
#include "io/units.h"

namespace caliper3d::io {

// A deviation survey as read from a file, in metres and degrees. MD,
// inclination and azimuth are always present; TVD, north and east are read,
// when the file carries them, only to check a computed path against them
// (they are empty otherwise). North and east are kept as written: some files
// give offsets from the wellhead, others grid coordinates, so compare
// differences from the first station.
// A column of the survey table as its header names it, and what it is read as.
struct SurveyColumn {
    std::string name;  // as written ("Measured Depth ( ft )")
    std::string role;  // "measured depth", "inclination", ...; empty when not read
    std::string unit;  // unit the column is read in ("ft", "deg"); empty when not read
};

struct SurveyTable {
    std::string source;
    std::vector<double> md_m;
    std::vector<double> inc_deg;
    std::vector<double> azi_deg;
    std::vector<double> tvd_m;  // NaN where the cell is empty
    std::vector<double> north_m;
    std::vector<double> east_m;
    LengthUnit depthUnit = LengthUnit::Metre;  // unit of MD as written in the file
    std::size_t headerLine = 0;                // 1-based line of the column names
    char delimiter = ',';                      // ',' ';' '\t', or ' ' for white space
    std::vector<SurveyColumn> columns;         // every column of the header line
    std::string wellName;                      // from a well-name column, when there is one
    std::size_t wellCount = 1;                 // wells in that column

    std::size_t stationCount() const { return md_m.size(); }
};

struct SurveyReadOptions {
    // Unit of MD/TVD/N/E when neither the header names ("MD_ft",
    // "Measured Depth ( ft )") nor a units line ("(m),(Deg),...") say it.
    LengthUnit defaultDepthUnit = LengthUnit::Metre;
    // Overrides whatever the file says.
    std::optional<LengthUnit> depthUnit;
    // A table with a well-name column (well, well name, wellbore) holding
    // several wells: the well to read (default: the first one listed).
    std::string well;
};

// Reads a survey table: free text before the column names is skipped (report
// headers, "# ..." comments); the header line is the first that names a
// measured depth, an inclination and an azimuth column (see
// docs/formats.md for the accepted names); a units line may follow it; the
// delimiter is a comma, semicolon or tab when the header has one, otherwise
// white space; a decimal comma is accepted in whitespace or semicolon files.
// Free text after the last station (report footers) is skipped, with a
// warning. A table with a well-name column gives one well's stations (see
// SurveyReadOptions::well), with a warning when it holds several. An azimuth
// taken from a grid-north column (no true-north one) is warned about. Throws
// ParseError (file, line, column, expected, found) on a station that is not
// numbers, on depths that decrease, on an inclination outside [0, 180], on
// fewer than two stations, or when no header is found.
SurveyTable parseSurvey(const std::string& text, const std::string& name,
                        const SurveyReadOptions& options = {}, Diagnostics* diagnostics = nullptr);
SurveyTable readSurvey(const std::string& path, const SurveyReadOptions& options = {},
                       Diagnostics* diagnostics = nullptr);

// True when `head` (the start of a text file) reads as a deviation survey and
// not as a caliper log: a line naming measured depth, inclination and azimuth
// columns and no caliper curve (R1, RAD1, F01, C1, ...) comes before any line
// of numbers. LAS files are not surveys here.
bool looksLikeSurvey(std::string_view head);

}  // namespace caliper3d::io
