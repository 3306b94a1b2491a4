#pragma once

#include <cstddef>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "io/diagnostics.h"
#include "io/read_options.h"

namespace caliper3d::io {

// What a data line looks like: the one description of a row that the column
// text and LAS layouts (io/layout/) produce and the row parser reads.
struct RowFormat {
    std::string file;
    bool las = false;              // '~' ends the data; null values and tokens apply
    bool wrapped = false;          // LAS WRAP YES: one depth's values run over several lines
    char delimiter = ' ';          // ' ' = runs of blanks; ',' = commas; '\t' = tabs (LAS 3.0
                                   //   DLM TAB: a value may hold spaces; a line without a tab
                                   //   is read as runs of blanks)
    std::size_t declared = 0;      // columns of the raw row
    std::size_t tokens = 0;        // values per row in the file
    std::size_t firstColumn = 0;   // raw column of the first value (1 for radii-only text)
    std::vector<char> textColumn;  // per raw column: text, never parsed (NaN)
    std::vector<char> lenient;     // per raw column (empty: none): a value that is not a
                                   //   number is read as null and counted (RowRun::bad), not
                                   //   refused; for the curves a reader does not need
    bool hasNull = false;          // LAS: the header's NULL value
    double null = 0.0;
    NullPolicy nullPolicy = NullPolicy::Common;
    int depthColumn = 0;             // never read as null
    std::string layout;              // for messages: "10 columns (depth R1..R6 ...)"
    std::vector<std::string> names;  // per raw column, for messages
};

// Receives rows as parsed: `raw` holds one value per declared column, as
// written (no unit conversion), NaN where null; `line` is the 1-based line
// where the row starts.
class RowSink {
public:
    virtual ~RowSink() = default;
    virtual void row(const double* raw, std::size_t line) = 0;
};

// Values of one lenient column that were not numbers.
struct BadValues {
    std::size_t count = 0;
    std::size_t firstLine = 0;  // 1-based, numbered as in parseRows
    std::string first;          // the first such value, as written (at most 40 characters)
    // Adds `other` (a later run whose lines are numbered from `linesBefore` + 1).
    void add(const BadValues& other, std::size_t linesBefore);
};

// What parsing one run of lines found besides its rows.
struct RowRun {
    std::vector<std::size_t> nulls;  // per declared column
    std::vector<BadValues> bad;      // per declared column
    Diagnostics diagnostics;         // lines numbered as in parseRows
    std::size_t linesConsumed = 0;
    bool stopped = false;        // a '~' section line ended the data (LAS)
    std::size_t stopOffset = 0;  //   at this offset of the text
    std::exception_ptr error;    // the ParseError that stopped it, if any
};

// Parses the data lines of `text`, numbering them from `firstLine`; blank and
// '#' lines are skipped. `finalRun` says the text ends the file (a short last
// line is then a counted warning, not an error). Runs on any thread and never
// throws: the error is kept in `out.error` for the caller to rethrow.
// One counted warning per lenient column with values that were not numbers
// (`bad` per declared column, lines numbered in the file), at its first line.
void warnBadValues(const RowFormat& format, const std::vector<BadValues>& bad,
                   Diagnostics& diagnostics);

void parseRows(const RowFormat& format, std::string_view text, std::size_t firstLine, bool finalRun,
               RowSink& sink, RowRun& out);

}  // namespace caliper3d::io
