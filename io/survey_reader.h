#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/units.h"

namespace caliper3d::io {

// A deviation survey as read from a file, in metres and degrees. MD,
// inclination and azimuth are always present; TVD, north and east are read,
// when the file carries them, only to check a computed path against them
// (they are empty otherwise). North and east are kept as written: some files
// give offsets from the wellhead, others grid coordinates, so compare
// differences from the first station.
struct SurveyTable {
    std::string source;
    std::vector<double> md_m;
    std::vector<double> inc_deg;
    std::vector<double> azi_deg;
    std::vector<double> tvd_m;    // NaN where the cell is empty
    std::vector<double> north_m;
    std::vector<double> east_m;
    LengthUnit depthUnit = LengthUnit::Metre;  // unit of MD as written in the file
    std::size_t headerLine = 0;                // 1-based line of the column names

    std::size_t stationCount() const { return md_m.size(); }
};

struct SurveyReadOptions {
    // Unit of MD/TVD/N/E when neither the header names ("MD_ft",
    // "Measured Depth ( ft )") nor a units line ("(m),(Deg),...") say it.
    LengthUnit defaultDepthUnit = LengthUnit::Metre;
    // Overrides whatever the file says.
    std::optional<LengthUnit> depthUnit;
};

// Reads a survey table: free text before the column names is skipped (report
// headers, "# ..." comments); the header line is the first that names a
// measured depth, an inclination and an azimuth column (see
// docs/formats.md for the accepted names); a units line may follow it; the
// delimiter is a comma, semicolon or tab when the header has one, otherwise
// white space; a decimal comma is accepted in whitespace or semicolon files.
// Free text after the last station (report footers) is skipped. Throws
// ParseError (file, line, column) on a station that is not numbers, on
// depths that decrease, on an inclination outside [0, 180], on fewer than
// two stations, or when no header is found.
SurveyTable parseSurvey(const std::string& text, const std::string& name,
                        const SurveyReadOptions& options = {});
SurveyTable readSurvey(const std::string& path, const SurveyReadOptions& options = {});

}  // namespace caliper3d::io
