#include "io/las_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/text.h"

namespace caliper3d::io {

namespace {

constexpr double kNull = std::numeric_limits<double>::quiet_NaN();

bool allOf(std::string_view s, char c) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [c](char x) { return x == c; });
}

// Splits a data line into tokens: runs of blanks, or commas (LAS 3.0 DLM COMMA).
void tokenize(std::string_view line, char delimiter, std::vector<std::string_view>& tokens,
              std::vector<std::size_t>& columns) {
    tokens.clear();
    columns.clear();
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    // A quoted string ("SAND, SHALY") is one token, delimiters and blanks inside it included.
    auto quotedEnd = [&](std::size_t at) {
        while (at < line.size() && blank(line[at])) ++at;
        if (at >= line.size() || line[at] != '"') return std::string_view::npos;
        const std::size_t close = line.find('"', at + 1);
        return close == std::string_view::npos ? line.size() : close + 1;
    };
    if (delimiter == ',') {
        std::size_t start = 0;
        while (start <= line.size()) {
            const std::size_t quoted = quotedEnd(start);
            std::size_t end = line.find(',', quoted == std::string_view::npos ? start : quoted);
            if (end == std::string_view::npos) end = line.size();
            std::size_t a = start, b = end;
            while (a < b && blank(line[a])) ++a;
            while (b > a && blank(line[b - 1])) --b;
            tokens.push_back(line.substr(a, b - a));
            columns.push_back(a + 1);
            start = end + 1;
        }
        return;
    }
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        if (i == line.size()) break;
        std::size_t j = quotedEnd(i);
        if (j == std::string_view::npos)
            for (j = i; j < line.size() && !blank(line[j]);) ++j;
        tokens.push_back(line.substr(i, j - i));
        columns.push_back(i + 1);
        i = j;
    }
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
    return v == -999.25 || v == 999.25 || v == -9999.25 || v == 9999.25 || v == -9999.0 || v == 9999.0 ||
           v == -999.0;
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

LasLog readLas(std::string_view text, const std::string& file, const LasReadOptions& options,
               Diagnostics* diagnostics) {
    LasLog log;
    log.header = parseLasHeader(text, file, diagnostics);
    const LasHeader& h = log.header;
    auto warn = [&](std::size_t line, std::string message) {
        if (diagnostics) diagnostics->warn(file, line, std::move(message));
    };
    if (h.curves.empty()) throw ParseError(file, 0, 0, "expected a ~C (curve information) section, found none");
    const NullPolicy nullPolicy = h.onlyDeclaredNull ? NullPolicy::Declared : options.nullPolicy;
    if (!h.hasData) throw ParseError(file, 0, 0, "expected a ~A (data) section, found none");

    for (const ColumnSpec& spec : lasColumns(h, diagnostics)) {
        LasCurve curve;
        curve.mnemonic = spec.mnemonic;
        curve.unit = spec.unit;
        curve.description = spec.description;
        curve.text = spec.text;
        splitArrayName(curve);
        log.curves.push_back(std::move(curve));
    }
    const std::size_t declared = log.curves.size();
    std::size_t columns = declared;  // values per row, settled on the first row
    bool settled = false;
    std::vector<std::string_view> tokens;
    std::vector<std::size_t> tokenColumns;
    std::vector<double> row;
    row.reserve(declared);
    std::size_t rowLine = 0;

    auto storeRow = [&](std::size_t line) {
        for (std::size_t c = 0; c < declared; ++c) log.curves[c].values.push_back(c < row.size() ? row[c] : kNull);
        log.rowLines.push_back(line);
        row.clear();
    };
    auto valueOf = [&](std::string_view token, std::size_t curve, std::size_t lineNo, std::size_t column) {
        LasCurve& target = log.curves[curve];
        if (target.text) return kNull;
        double v = 0.0;
        if (parseNumber(token, v)) {
            if (curve > 0 && ((h.hasNull && v == h.null) ||
                              (nullPolicy == NullPolicy::Common && isCommonNullNumber(v)))) {
                ++target.nulls;
                return kNull;
            }
            return v;
        }
        if (curve > 0 && isNullToken(token, nullPolicy)) {
            ++target.nulls;
            return kNull;
        }
        throw ParseError(file, lineNo, column,
                         "expected a number for curve " + target.mnemonic + ", found '" + std::string(token) + "'");
    };

    std::size_t pos = h.dataBegin, lineNumber = h.dataFirstLine - 1;
    const std::string_view data = text.substr(0, h.dataEnd);
    while (pos < data.size()) {
        std::size_t end = data.find('\n', pos);
        if (end == std::string_view::npos) end = data.size();
        std::string_view line = data.substr(pos, end - pos);
        const bool lastLine = end >= data.size() || data.find_first_not_of(" \t\r\n", end) == std::string_view::npos;
        pos = end + 1;
        ++lineNumber;
        tokenize(line, h.delimiter, tokens, tokenColumns);
        if (tokens.empty() || (tokens.size() == 1 && tokens[0].empty())) continue;
        if (tokens.front().size() > 0 && tokens.front().front() == '#') continue;

        if (h.wrap) {
            if (row.empty()) rowLine = lineNumber;
            for (std::size_t t = 0; t < tokens.size(); ++t) {
                if (row.size() == declared)
                    throw ParseError(file, lineNumber, tokenColumns[t],
                                     "expected " + std::to_string(declared) + " values per depth in wrapped data, found more");
                row.push_back(valueOf(tokens[t], row.size(), lineNumber, tokenColumns[t]));
            }
            if (row.size() == declared) storeRow(rowLine);
            continue;
        }

        if (!settled) {
            settled = true;
            columns = tokens.size();
            if (columns > declared)
                throw ParseError(file, lineNumber, tokenColumns[declared],
                                 "expected " + std::to_string(declared) + " values (one per ~C curve), found " +
                                     std::to_string(columns));
            if (columns < declared) {
                std::string missing;
                for (std::size_t c = columns; c < declared; ++c) missing += (missing.empty() ? "" : ", ") + log.curves[c].mnemonic;
                warn(lineNumber, std::to_string(declared) + " curves declared but rows hold " + std::to_string(columns) +
                                     " values; no data for " + missing);
            }
        }
        if (tokens.size() > columns)
            throw ParseError(file, lineNumber, tokenColumns[columns],
                             "expected " + std::to_string(columns) + " values, found " + std::to_string(tokens.size()));
        if (tokens.size() < columns) {
            if (allOf(tokens.back(), '*')) {
                // An overflowed field ran into the next ones: they are unknown, not lost.
                warn(lineNumber, "field overflow ('" + std::string(tokens.back()) + "') covers the last " +
                                     std::to_string(columns - tokens.size() + 1) + " values; read as null");
            } else if (lastLine) {
                warn(lineNumber, "last line holds " + std::to_string(tokens.size()) + " of " + std::to_string(columns) +
                                     " values (truncated file?); skipped");
                break;
            } else {
                throw ParseError(file, lineNumber, 0,
                                 "expected " + std::to_string(columns) + " values, found " + std::to_string(tokens.size()));
            }
        }
        for (std::size_t t = 0; t < tokens.size(); ++t) row.push_back(valueOf(tokens[t], t, lineNumber, tokenColumns[t]));
        while (row.size() < columns) {
            ++log.curves[row.size()].nulls;
            row.push_back(kNull);
        }
        storeRow(lineNumber);
    }
    if (h.wrap && !row.empty())
        warn(rowLine, "last depth holds " + std::to_string(row.size()) + " of " + std::to_string(declared) +
                          " wrapped values (truncated file?); skipped");
    return log;
}

}  // namespace caliper3d::io
