#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "io/diagnostics.h"
#include "io/read_options.h"
#include "io/section_table.h"

namespace caliper3d::io {

// Puts the rows of a log in increasing depth as they are parsed, one run of
// rows at a time, and hands on the rows that are ready. A log recorded
// downwards streams: rows without a depth, rows repeating the depth before and
// rows going back up are skipped (counted), or the read is refused at the
// first row going back up (DepthOrder::Reject). A log recorded upwards (the
// trend of the first run decides, not its first pair of rows) is held whole,
// then sorted and handed on at the end.
class DepthOrdering {
public:
    using Emit = std::function<void(const SectionTable& rows)>;

    // `empty`: a table with the log's curves and no rows. `depthScale` turns
    // metres back into the file's unit for messages.
    DepthOrdering(const SectionTable& empty, DepthOrder policy, std::string file, double depthScale,
                  std::size_t chunkRows);

    // Takes a run of rows in file order (`lines`: the line of each). A run
    // wholly in order and of at least chunkRows rows goes to `emit` at once,
    // without a copy; other rows are gathered.
    void add(const SectionTable& rows, const std::vector<std::size_t>& lines, const Emit& emit);

    // Hands on the gathered rows once they are chunkRows or more (downwards only).
    void emitReady(const Emit& emit);

    // Hands on what is left (a log recorded upwards: sorted, in chunks, while
    // `keepGoing` says so; nothing when `deliver` is false) and adds the
    // warnings for the rows skipped or sorted.
    void finish(bool deliver, const Emit& emit, const std::function<bool()>& keepGoing,
                Diagnostics& diagnostics);

private:
    void decideDirection(const SectionTable& rows);
    void holdEverything();

    std::string m_file;
    DepthOrder m_policy;
    double m_depthScale;
    std::size_t m_chunkRows;
    SectionTable m_current, m_held;
    std::vector<std::pair<std::size_t, std::size_t>> m_kept;
    bool m_haveLast = false, m_directionKnown = false, m_descending = false, m_haveFirst = false;
    double m_last = 0.0, m_first = 0.0;
    std::size_t m_nullDepths = 0, m_repeated = 0, m_backwards = 0;
    std::size_t m_firstNullDepthLine = 0, m_firstRepeatedLine = 0, m_firstBackwardsLine = 0;
};

}  // namespace caliper3d::io
