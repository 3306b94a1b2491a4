#include "io/las_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "io/layout/las_layout.h"
#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/stream/row_parser.h"
#include "io/text.h"

namespace caliper3d::io {

namespace {

bool allOf(std::string_view s, char c) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [c](char x) { return x == c; });
}

void splitArrayName(LasCurve& curve) {
    const std::size_t open = curve.mnemonic.find('[');
    const std::size_t close = curve.mnemonic.find(']', open == std::string::npos ? 0 : open);
    if (open == std::string::npos || close == std::string::npos || close <= open + 1) return;
    // A whole number that fits an int, nothing else ("NMR[4e21]" is a name, not an element).
    const char* first = curve.mnemonic.data() + open + 1;
    const char* last = curve.mnemonic.data() + close;
    int index = 0;
    const auto [end, ec] = std::from_chars(first, last, index);
    if (ec != std::errc() || end != last || index < 1) return;
    curve.arrayName = curve.mnemonic.substr(0, open);
    curve.arrayIndex = index;
}

}  // namespace

bool isCommonNullNumber(double v) {
    // Cheap rejection first: this runs on every value of a large log.
    if (v > -999.0 && v < 999.25) return false;
    return v == -999.25 || v == 999.25 || v == -9999.25 || v == 9999.25 || v == -9999.0 ||
           v == 9999.0 || v == -999.0;
}

std::vector<ColumnSpec> lasColumns(const LasHeader& h, Diagnostics* diagnostics) {
    auto warn = [&](std::size_t line, std::string message) {
        if (diagnostics) diagnostics->warn(h.file, line, std::move(message));
    };
    std::vector<ColumnSpec> columns;
    for (const LasItem& item : h.curves)
        columns.push_back({item.mnemonic, item.unit, item.description,
                           item.description.find("{S}") != std::string::npos, item.line});
    // One pass with a map: a header may declare thousands of curves.
    std::unordered_map<std::string, int> declaredTimes;
    for (ColumnSpec& c : columns) {
        const int times = ++declaredTimes[upper(c.mnemonic)];
        if (times == 1) continue;
        warn(c.line, "curve '" + c.mnemonic + "' is declared again; read as '" + c.mnemonic + ":" +
                         std::to_string(times) + "'");
        c.mnemonic += ":" + std::to_string(times);
    }
    for (const ColumnSpec& c : columns)
        if (c.text) warn(c.line, "curve '" + c.mnemonic + "' holds text; skipped");
    return columns;
}

bool isNullToken(std::string_view token, NullPolicy policy) {
    if (allOf(token, '*')) return true;  // Fortran field overflow
    if (policy == NullPolicy::Declared) return false;
    if (allOf(token, '-')) return true;
    const std::string u = upper(token);
    return u == "ERR" || u == "ERROR" || u == "NAN" || u == "NULL" || u == "N/A";
}

namespace {

// Rows as parsed, stored curve by curve.
class CurveSink : public RowSink {
public:
    explicit CurveSink(LasLog& log) : m_log(log) {}
    void row(const double* raw, std::size_t line) override {
        for (std::size_t c = 0; c < m_log.curves.size(); ++c)
            m_log.curves[c].values.push_back(raw[c]);
        m_log.rowLines.push_back(line);
    }

private:
    LasLog& m_log;
};

}  // namespace

// The ~A section goes through the same layout (io/layout/las_layout) and row
// parser (io/stream/row_parser) as the streamed caliper reader: one LAS data path.
LasLog readLas(std::string_view text, const std::string& file, const LasReadOptions& options,
               Diagnostics* diagnostics) {
    LasLog log;
    log.header = parseLasHeader(text, file, diagnostics);
    const LasHeader& h = log.header;
    if (h.curves.empty())
        throw ParseError(file, 0, 0, "expected a ~C (curve information) section, found none");
    if (!h.hasData) throw ParseError(file, 0, 0, "expected a ~A (data) section, found none");

    Diagnostics local;
    Diagnostics& d = diagnostics ? *diagnostics : local;
    const std::vector<ColumnSpec> columns = lasColumns(h, &d);
    for (const ColumnSpec& spec : columns) {
        LasCurve curve;
        curve.mnemonic = spec.mnemonic;
        curve.unit = spec.unit;
        curve.description = spec.description;
        curve.text = spec.text;
        splitArrayName(curve);
        log.curves.push_back(std::move(curve));
    }
    RowFormat format = lasRowFormat(h, columns, options.nullPolicy, file, 0);
    // Every curve but the index: a value that is not a number is read as null and counted.
    format.lenient.assign(columns.size(), 1);
    format.lenient.front() = 0;
    const std::string_view data = text.substr(h.dataBegin, h.dataEnd - h.dataBegin);
    if (!h.wrap) settleLasColumns(data, h.dataFirstLine - 1, columns, format, d);
    CurveSink sink(log);
    RowRun run;
    parseRows(format, data, h.dataFirstLine, true, sink, run);
    if (run.error) std::rethrow_exception(run.error);
    d.merge(run.diagnostics);
    warnBadValues(format, run.bad, d);
    for (std::size_t c = 0; c < log.curves.size(); ++c)
        log.curves[c].nulls = log.curves[c].text ? 0 : run.nulls[c];
    return log;
}

}  // namespace caliper3d::io
