#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "io/curve_plan.h"
#include "io/diagnostics.h"
#include "io/las_header.h"
#include "io/read_options.h"

namespace caliper3d::io {

struct LasReadOptions {
    NullPolicy nullPolicy = NullPolicy::Common;
};

// One curve of a LAS file, values as written (no unit conversion).
struct LasCurve {
    std::string mnemonic;
    std::string unit;
    std::string description;
    std::vector<double> values;  // NaN where null
    std::size_t nulls = 0;
    bool text = false;      // a string column (LAS 3.0 {S}): skipped, values NaN
    std::string arrayName;  // LAS 3.0 array channel "NMR[3]": "NMR"
    int arrayIndex = 0;     //   and 3 (1-based); 0 for a plain curve
};

struct LasLog {
    LasHeader header;
    std::vector<LasCurve> curves;
    std::vector<std::size_t> rowLines;  // 1-based line where each row starts
    std::size_t rowCount() const { return curves.empty() ? 0 : curves.front().values.size(); }
};

// Reads a whole LAS 1.2/2.0/3.0 text. Throws ParseError (file, line, column,
// expected, found) for what cannot be read safely; counts skipped rows and
// repaired fields in `diagnostics`.
LasLog readLas(std::string_view text, const std::string& file, const LasReadOptions& options,
               Diagnostics* diagnostics);

// The ~C curves as data columns: a duplicated mnemonic is renamed NAME:2,
// NAME:3 (as lasio does) and a LAS 3.0 string column ({S}) is marked text;
// both are noted in `diagnostics`.
std::vector<ColumnSpec> lasColumns(const LasHeader& header, Diagnostics* diagnostics);

// True for -999.25, 999.25, +-9999.25, +-9999 and -999: nulls under NullPolicy::Common.
bool isCommonNullNumber(double v);

// True for a token that means "no value" under `policy` (declared NULL aside).
bool isNullToken(std::string_view token, NullPolicy policy);

}  // namespace caliper3d::io
