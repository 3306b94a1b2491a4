#pragma once

#include <QString>

#include "app/desktop/command_arguments.h"

namespace caliper3d::app {

// What the Open dialog lets a user set for one file: the text of each of its fields by option
// name, as the command line takes it (app/well_option_table.h; empty or absent: the file's
// own, or detected). Mapped to a well and its load options by openRequestFrom, through the
// table's own parsing; a recent file keeps the same texts.
struct OpenChoices {
    QString path;
    OptionTexts options;
};

// The well and its options for `choices`. Nothing comes from another well but the look:
// `look`'s radial exaggeration and colouring (what the window draws every well with). Throws
// UsageError, with the command line's message, for a malformed value or an unknown option.
ParsedWells openRequestFrom(const OpenChoices& choices, const LoadOptions& look);

}  // namespace caliper3d::app
