#pragma once

#include <optional>
#include <string>

#include "io/diagnostics.h"
#include "io/section_table.h"
#include "io/units.h"

namespace caliper3d::io {

// The reference tool's plain column text: per line
//   depth R1 .. RN P1AZ DEVI HAZI
// separated by spaces or tabs, decimal point or decimal comma. Blank lines and
// lines starting with '#' are skipped; CRLF line ends are accepted. A line of
// names with one name per column (or a '#' line of them right before the data,
// starting with a depth) names the columns instead: "depth_m R1_in ... GR"
// (docs/formats.md). Refuses LAS and other formats (ParseError).
//
// Multi-finger tools often write only the finger radii: a file whose lines all
// hold kMinRadiiOnlyColumns or more numbers (io/read_options.h), but not
// armCount + 4, is read as radii only, depth = row index x rowStep_m (a counted
// warning says so).
struct ColumnTextOptions {
    int armCount = 6;
    std::optional<LengthUnit> depthUnit;   // overrides the names' units; default metres
    std::optional<LengthUnit> radiusUnit;  // overrides the names' units; default inches
                                           //   (millimetres when inches would be implausible)
    bool allowRadiiOnly = true;
    double rowStep_m = 0.01;
};

// Reads the whole file. Throws ParseError naming file, line and column when a
// line has the wrong number of columns or a field is not a number.
SectionTable readColumnText(const std::string& path, const ColumnTextOptions& options,
                            Diagnostics* diagnostics = nullptr);

// Same, from text already in memory; `name` is used in messages.
SectionTable parseColumnText(const std::string& text, const std::string& name,
                             const ColumnTextOptions& options, Diagnostics* diagnostics = nullptr);

}  // namespace caliper3d::io
