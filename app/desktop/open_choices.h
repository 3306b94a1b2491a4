#pragma once

#include <QString>

#include "app/desktop/command_arguments.h"

namespace caliper3d::app {

// What the Open dialog lets a user set for one file, as the text the command line takes for
// the same option (empty: the file's own, or detected). Mapped to a well and its load options
// by openRequestFrom, through the command line's own parsing.
struct OpenChoices {
    QString path;
    QString radii;       // --radii: "R1,R2,..." or "NAME[]"
    QString diameters;   // --diameters: "C1,C2"
    QString depthUnit;   // --depth-unit: m, ft
    QString radiusUnit;  // --radius-unit: in, mm, cm
    QString bitSize;     // --bit-size: "8.5in", "215.9mm" (empty: the log's own, if any)
    int arms = 6;        // --arms, for column text
    QString survey;      // --survey FILE
    QString wellhead;    // --wellhead E,N,ELEV
};

// The well and its options for `choices`. Nothing comes from another well but the look:
// `look`'s radial exaggeration and colouring (what the window draws every well with). Throws
// UsageError, with the command line's message, for a malformed value.
ParsedWells openRequestFrom(const OpenChoices& choices, const LoadOptions& look);

// The arguments openRequestFrom parses: the options given, then "--" and the file.
QStringList openArguments(const OpenChoices& choices);

}  // namespace caliper3d::app
