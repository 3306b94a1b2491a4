#pragma once

#include <vector>

#include <QStringList>

#include "app/input_options.h"

namespace caliper3d::app {

// The window's wells turned back into the command line that loads them the same way, so a
// child `caliper3d export` reads them as the window did: each option of the table
// (app/well_option_table.h) that differs from its default, to full precision. Pure
// functions: parseWellArguments(wellArguments(w, o)) gives back w and o.

// The options, the PerWell ones once per file, then "--" and the files. Throws
// std::invalid_argument when only some of the wells have a survey (or a wellhead): the
// command line takes them for every file or for none.
QStringList wellArguments(const std::vector<WellSource>& wells, const LoadOptions& options);

// `caliper3d export` writing `wells` to `out`, with --progress.
QStringList exportArguments(const std::vector<WellSource>& wells, const LoadOptions& options,
                            const QString& out);

// Files and options as the command line reads them (inputOptionsFrom, colourRequestFrom,
// wellSourcesFrom). Throws UsageError for an unknown option or a malformed value.
struct ParsedWells {
    std::vector<WellSource> wells;
    LoadOptions options;
};
ParsedWells parseWellArguments(const QStringList& arguments);

}  // namespace caliper3d::app
