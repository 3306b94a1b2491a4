#pragma once

#include <optional>
#include <string>

#include <QCommandLineParser>

#include "io/log_reader.h"
#include "io/diagnostics.h"
#include "io/section_table.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::app {

// Options shared by every verb that reads a log (design section 8, "common").
struct InputOptions {
    io::ReadOptions read;
    int splinePoints = 48;
    double segmentLength_m = 10.0;
    double radialExaggeration = 1.0;
};

// Thrown for bad command-line usage (exit status 2).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void addInputOptions(QCommandLineParser& parser);
// Throws UsageError on a malformed value.
InputOptions inputOptionsFrom(const QCommandLineParser& parser);

reconstruction::GeometryOptions geometryOptions(const InputOptions& options);

// Reads a caliper log in any supported format (io::readCaliperLog). Throws
// io::ParseError (file, line, what was expected) on bad input.
io::SectionTable readWellFile(const std::string& path, const InputOptions& options,
                              io::Diagnostics* diagnostics);

}  // namespace caliper3d::app
