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
#include "reconstruction/well_geometry.h"
#include "reconstruction/path/wellhead.h"

namespace caliper3d::app {

// Options shared by every verb that reads a log (design section 8, "common").
struct InputOptions {
    io::ReadOptions read;
    int splinePoints = 48;
    double segmentLength_m = 10.0;
    double radialExaggeration = 1.0;
    double steepInclination_deg = 15.0;  // above this, arm 1 comes from RB when present
    double toolReach_mm = 1.0e9;         // arm readings beyond this are repaired
};

// One well to read: its log, and optionally its deviation survey (replacing
// the log's DEVI/HAZI for the path) and its wellhead (placing it beside the
// other wells of a scene).
struct WellSource {
    std::string path;
    std::string surveyPath;  // empty: the path comes from the log's own DEVI/HAZI
    std::optional<reconstruction::Wellhead> wellhead;
};

// Thrown for bad command-line usage (exit status 2).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void addInputOptions(QCommandLineParser& parser);
// Throws UsageError on a malformed value.
InputOptions inputOptionsFrom(const QCommandLineParser& parser);
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

// Geometry options of a plain well (no survey, at the scene origin).
reconstruction::GeometryOptions geometryOptions(const InputOptions& options);
// Geometry options of one well of a scene whose origin is the wellhead
// `origin`: reads the well's survey (throws io::ParseError naming the survey
// file and line) and offsets it by its wellhead. The survey's warnings, and one
// when the positions it writes disagree with minimum curvature, go to `diagnostics`.
reconstruction::GeometryOptions geometryOptions(const InputOptions& options, const WellSource& well,
                                                const reconstruction::Wellhead& origin,
                                                io::Diagnostics* diagnostics = nullptr);
// The scene origin: the first well's wellhead (zero when none is given).
reconstruction::Wellhead sceneOrigin(const std::vector<WellSource>& wells);

// Prints a file's warnings on stderr ("file:line: warning: ..."), and how
// many more there were than the diagnostics kept.
void printWarnings(const io::Diagnostics& diagnostics);

// Reads a well's caliper log in any supported format and settles its hole
// azimuth (reconstruction::loadWellTable; a --survey gives the azimuth).
// Throws io::ParseError (file, line, what was expected) on bad input.
io::SectionTable readWellFile(const WellSource& well, const InputOptions& options,
                              io::Diagnostics* diagnostics);
// The same for a log without a survey.
io::SectionTable readWellFile(const std::string& path, const InputOptions& options,
                              io::Diagnostics* diagnostics);

}  // namespace caliper3d::app
