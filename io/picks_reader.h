#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/diagnostics.h"
#include "io/section_table.h"

namespace caliper3d::io {

// One feature interpreted on an image log (a breakout, a drilling-induced tensile fracture, ...):
// `--picks FILE`, shown beside the caliper's own zones (docs/formats.md, "Picks").
struct Pick {
    double top_m = 0.0;
    double bottom_m = 0.0;      // the top again for a pick at one depth
    double azimuth_deg = kNaN;  // clockwise from north, [0, 360): one side of a breakout
    std::string type;           // as the file writes it ("BREAKOUT", "DITF"); "" when untyped
    std::size_t line = 0;       // in the file, for messages
};

struct PickFile {
    std::string path;
    std::vector<Pick> picks;  // in the file's order
    Diagnostics diagnostics;  // rows skipped (a bad number, no azimuth), units assumed
};

// Reads picks from a LAS file (a ~C section naming the columns, text allowed in the type
// column) or a delimited text file whose first line names the columns (comma, tab or blanks):
// a depth (DEPT, DEPTH, MD, TOP), an optional bottom (BOTTOM, BASE, BOT), an azimuth (AZIMUTH,
// AZIM, AZI, AZ, BO_AZ, ...) and an optional type (TYPE, CLASS, FEATURE, ...). Depths in M or
// FT (metres when no unit is given, with a warning), azimuths in degrees or radians. A row
// whose depth or azimuth is not a number is skipped and counted. Throws ParseError naming the
// file and line when the file cannot be read or has no depth or azimuth column.
PickFile readPicks(const std::string& path);

// A breakout's two sides are one direction: the axial difference of two azimuths, [0, 90].
double axialDifference_deg(double a_deg, double b_deg);

}  // namespace caliper3d::io
