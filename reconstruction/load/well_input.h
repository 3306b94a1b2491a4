#pragma once

#include <atomic>

#include <string>

#include "io/diagnostics.h"
#include "io/log_stream.h"
#include "io/read_options.h"
#include "io/section_table.h"

namespace caliper3d::reconstruction {

// The one recipe that turns a log file into the table a well is drawn and
// analysed from, for every verb and the window: reads it (io::loadCaliperLog,
// refusing a log without caliper curves), then settles its hole azimuth
// (read, derived by a known tool's convention, or unknown: hole_azimuth.h).
// `surveyGiven`: the path's azimuth comes from a --survey. Throws
// io::ParseError naming file, line and what was expected; the log's warnings
// go to `diagnostics`.
io::SectionTable loadWellTable(const std::string& path, const io::ReadOptions& options,
                               bool surveyGiven, io::Diagnostics* diagnostics,
                               const std::atomic<bool>* cancel = nullptr);
// The same with the reader's hooks (io::StreamOptions::onStart, onChunk) and cancel token.
io::SectionTable loadWellTable(const std::string& path, const io::ReadOptions& options,
                               bool surveyGiven, io::Diagnostics* diagnostics,
                               const io::StreamOptions& stream);

}  // namespace caliper3d::reconstruction
