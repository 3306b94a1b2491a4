#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include <QCommandLineParser>

#include "app/well_option_table.h"
#include "io/diagnostics.h"
#include "io/log_reader.h"
#include "io/section_table.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/path/wellhead.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::app {

// The command line fills the library's load settings (reconstruction/load): the options
// and their parsing are the rows of app/well_option_table.h; these functions register and
// read each group of them.

// The Reading options (curves, units, bit size, geometry settings).
void addInputOptions(QCommandLineParser& parser);
// The Colour options (--colour-by NAME, --colour-range LO,HI), for the verbs that draw
// (view, render, export).
void addColourOptions(QCommandLineParser& parser);
// The PerWell options (--survey FILE, --wellhead E,N,ELEV), each given once per well in
// the order of the files (or not at all).
void addWellSourceOptions(QCommandLineParser& parser);

// The Reading options given; throws UsageError on a malformed value.
LoadOptions inputOptionsFrom(const QCommandLineParser& parser);
// The Colour options given. Throws UsageError on a malformed range; an unknown NAME is found
// when a well is loaded (the names of its extra curves are valid too).
reconstruction::ColourRequest colourRequestFrom(const QCommandLineParser& parser);
// Pairs `files` with the PerWell options' values; throws UsageError when their counts
// differ from the number of files or a value is malformed.
std::vector<WellSource> wellSourcesFrom(const QCommandLineParser& parser,
                                        const std::vector<std::string>& files);

// Throws UsageError when a Reading option with one of `effects` was given to `verb`, which
// cannot use it (`why` says so: an option that is silently ignored misleads).
void rejectInapplicable(const QCommandLineParser& parser, const std::string& verb,
                        std::initializer_list<OptionEffect> effects, const std::string& why);

// --summary FILE.jsonl: one JSON line per input (app/input_summary.h).
void addSummaryOption(QCommandLineParser& parser);

// Prints io::formatWarnings on stderr.
void printWarnings(const io::Diagnostics& diagnostics);

}  // namespace caliper3d::app
