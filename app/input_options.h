#pragma once

#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <QCommandLineParser>

#include "io/diagnostics.h"
#include "io/log_reader.h"
#include "io/section_table.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/path/wellhead.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::app {

// The command line fills the library's load settings (reconstruction/load):
// this file only parses options into them.
using reconstruction::LoadOptions;
using reconstruction::WellSource;

// Thrown for bad command-line usage (exit status 2).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void addInputOptions(QCommandLineParser& parser);
// --colour-by NAME and --colour-range LO,HI, for the verbs that draw (view, render, export).
void addColourOptions(QCommandLineParser& parser);
// Throws UsageError on a malformed range; an unknown NAME is found when a well is loaded
// (the names of its extra curves are valid too).
reconstruction::ColourRequest colourRequestFrom(const QCommandLineParser& parser);
// Throws UsageError on a malformed value.
LoadOptions inputOptionsFrom(const QCommandLineParser& parser);
// Throws UsageError when any of `names` was given to `verb`, which cannot use
// it (`why` says so: an option that is silently ignored misleads).
void rejectInapplicable(const QCommandLineParser& parser, const std::string& verb,
                        std::initializer_list<const char*> names, const std::string& why);
// A length such as "8.5in", "215.9mm" or "21.59cm" (a bare number is inches),
// in millimetres; throws UsageError naming `option` unless it is positive.
double parseLength_mm(const std::string& text, const std::string& option);

// Adds --survey FILE and --wellhead E,N,ELEV, each given once per well in
// the order of the files (or not at all).
void addWellSourceOptions(QCommandLineParser& parser);
// Pairs `files` with the --survey and --wellhead values; throws UsageError
// when their counts differ from the number of files or a value is malformed.
std::vector<WellSource> wellSourcesFrom(const QCommandLineParser& parser,
                                        const std::vector<std::string>& files);
// "E,N,ELEV" in metres; throws UsageError.
reconstruction::Wellhead parseWellhead(const std::string& text);

// --summary FILE.jsonl: one JSON line per input (app/input_summary.h).
void addSummaryOption(QCommandLineParser& parser);

// Prints io::formatWarnings on stderr.
void printWarnings(const io::Diagnostics& diagnostics);

}  // namespace caliper3d::app
