#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "io/diagnostics.h"
#include "io/log_info.h"
#include "io/log_stream.h"
#include "io/read_options.h"
#include "io/section_table.h"

namespace caliper3d::io {

// A whole log and its description.
struct LoadedLog {
    SectionTable table;
    LogInfo info;
};

// Thrown by the whole-log readers when StreamOptions::cancel stopped them.
class ReadCancelled : public std::runtime_error {
public:
    explicit ReadCancelled(const std::string& file)
        : std::runtime_error(file + ": reading cancelled") {}
};

// Reads a column-text or LAS 1.2/2.0/3.0 file (detected from its content)
// into a section table in metres, millimetres and degrees, sorted by depth.
// Throws ParseError naming file, line and what was expected.
LoadedLog loadCaliperLog(const std::string& path, const ReadOptions& options,
                         const StreamOptions& stream = {});

// The same, refusing a log without caliper curves; warnings go to `diagnostics`.
SectionTable readCaliperLog(const std::string& path, const ReadOptions& options,
                            Diagnostics* diagnostics);

// The same from text in memory (`name` is used in messages).
LoadedLog loadCaliperText(std::string_view text, const std::string& name,
                          const ReadOptions& options, const StreamOptions& stream = {});

// What `caliper3d info FILE` prints, read without keeping the rows. A
// deviation survey (io::looksLikeSurvey) is described too: its stations,
// MD range and columns with the role each is read in. Throws ParseError for
// what is neither (JSON, binary) or cannot be read.
LogInfo describeLog(const std::string& path, const ReadOptions& options);
// The same, handing each chunk of a caliper log's rows to `onRows` (never
// called for a survey), for a caller that checks the data as it streams by.
// `surveyGiven`: a --survey gives the path, so the hole azimuth is known.
LogInfo describeLog(const std::string& path, const ReadOptions& options,
                    const std::function<void(const SectionTable&)>& onRows,
                    bool surveyGiven = false);
std::string formatLogInfo(const LogInfo& info);

}  // namespace caliper3d::io
