#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "io/diagnostics.h"
#include "io/las_header.h"

namespace caliper3d::io {

// Which values mean "no reading" in a LAS data section. Never applied to the
// depth index (index_null.las holds a real depth equal to its NULL value).
enum class NullPolicy {
    Declared,  // the header's NULL only, plus text overflow ("****")
    Common     // also -999.25, 999.25, +-9999.25, +-9999, -999, ERR, NaN, dashes
};

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
    bool text = false;           // a string column (LAS 3.0 {S}): skipped, values NaN
    std::string arrayName;       // LAS 3.0 array channel "NMR[3]": "NMR"
    int arrayIndex = 0;          //   and 3 (1-based); 0 for a plain curve
};

struct LasLog {
    LasHeader header;
    std::vector<LasCurve> curves;
    std::size_t rowCount() const { return curves.empty() ? 0 : curves.front().values.size(); }
};

// Reads a whole LAS 1.2/2.0/3.0 text. Throws ParseError (file, line, column,
// expected, found) for what cannot be read safely; counts skipped rows and
// repaired fields in `diagnostics`.
LasLog readLas(std::string_view text, const std::string& file, const LasReadOptions& options,
               Diagnostics* diagnostics);

// True for a token that means "no value" under `policy` (declared NULL aside).
bool isNullToken(std::string_view token, NullPolicy policy);

}  // namespace caliper3d::io
