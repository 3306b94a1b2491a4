#include "io/las_writer.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "io/atomic_output.h"

namespace caliper3d::io {

namespace {

void put(std::string& line, double value, double null, int decimals = -1) {
    char buffer[64];
    const double v = std::isfinite(value) ? value : null;
    const auto result = decimals < 0 || !std::isfinite(value)
                            ? std::to_chars(buffer, buffer + sizeof buffer, v)
                            : std::to_chars(buffer, buffer + sizeof buffer, v == 0.0 ? 0.0 : v,
                                            std::chars_format::fixed, decimals);
    // A value too large for the buffer (|v| > 1e40 in fixed form) falls back to the shortest form.
    if (result.ec != std::errc()) {
        line.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
        return;
    }
    line.append(buffer, result.ptr);
}

void item(std::ostream& out, const std::string& mnemonic, const std::string& unit,
          const std::string& value, const std::string& description) {
    std::string left = " " + mnemonic + "." + unit;
    if (left.size() < 16) left.resize(16, ' ');
    std::string middle = " " + value;
    if (middle.size() < 24) middle.resize(24, ' ');
    out << left << middle << " : " << description << "\n";
}

// A NULL value that no true value equals, so that no reading turns into a null.
double nullAbsentFrom(const std::vector<LasColumn>& columns, std::size_t rows, double preferred) {
    std::vector<double> candidates;
    if (std::isfinite(preferred)) candidates.push_back(preferred);
    for (double power = 1e3; power <= 1e12; power *= 10.0)
        candidates.push_back(-(power - 0.75));  // -999.25, -9999.25, ...
    std::vector<char> taken(candidates.size(), 0);
    for (std::size_t c = 1; c < columns.size(); ++c)  // the index is never read as null
        for (std::size_t r = 0; r < rows; ++r) {
            const double v = columns[c].values[r * columns[c].stride];
            for (std::size_t k = 0; k < candidates.size(); ++k) taken[k] |= v == candidates[k];
        }
    for (std::size_t k = 0; k < candidates.size(); ++k)
        if (!taken[k]) return candidates[k];
    throw std::invalid_argument("writeLas: every candidate NULL value occurs in the data");
}

}  // namespace

void writeLasColumns(std::ostream& out, std::size_t rows, const std::vector<LasColumn>& columns,
                     const LasWriteOptions& options) {
    if (columns.empty()) throw std::invalid_argument("LAS output needs a depth column");
    std::string text;
    auto number = [&](double v) {
        text.clear();
        put(text, v, options.null);
        return text;
    };
    const LasColumn& index = columns.front();
    auto depth = [&](std::size_t row) { return index.values[row * index.stride]; };
    out << "~Version information\n";
    item(out, "VERS", "", "2.0", "CWLS log ASCII standard - version 2.0");
    item(out, "WRAP", "", "NO", "one line per depth step");
    out << "~Well information\n";
    item(out, "STRT", index.unit, rows ? number(depth(0)) : "0", "start depth");
    item(out, "STOP", index.unit, rows ? number(depth(rows - 1)) : "0", "stop depth");
    double step = 0.0;
    if (rows > 1) {
        // Regular within a part in a thousand (decimal steps do not add up exactly in binary).
        const double nominal = (depth(rows - 1) - depth(0)) / static_cast<double>(rows - 1);
        step = nominal;
        for (std::size_t r = 1; r < rows && step != 0.0; ++r)
            if (!(std::abs(depth(r) - depth(r - 1) - nominal) <= 1e-3 * std::abs(nominal)))
                step = 0.0;
    }
    // "%.10g", locale-free: 0.0025, not 0.0024999999999988864.
    char stepText[32];
    const auto stepEnd =
        std::to_chars(stepText, stepText + sizeof stepText, step, std::chars_format::general, 10);
    item(out, "STEP", index.unit, std::string(stepText, stepEnd.ptr), "step (0: irregular)");
    item(out, "NULL", "", number(options.null), "null value");
    item(out, "WELL", "", options.wellName, "well");
    out << "~Curve information\n";
    for (const LasColumn& c : columns) item(out, c.mnemonic, c.unit, "", c.description);
    if (!options.parameters.empty()) {
        out << "~Parameter information\n";
        for (const LasParameter& p : options.parameters)
            item(out, p.mnemonic, p.unit, p.value, p.description);
    }
    if (!options.other.empty()) {
        out << "~Other information\n" << options.other;
        if (options.other.back() != '\n') out << '\n';
    }
    out << "~ASCII\n";
    std::string line;
    for (std::size_t r = 0; r < rows; ++r) {
        line.clear();
        for (std::size_t c = 0; c < columns.size(); ++c) {
            if (c) line.push_back(' ');
            put(line, columns[c].values[r * columns[c].stride], options.null, columns[c].decimals);
        }
        line.push_back('\n');
        out.write(line.data(), static_cast<std::streamsize>(line.size()));
    }
}

void writeLas(std::ostream& out, const SectionTable& t, const LasWriteOptions& options) {
    const std::size_t rows = t.rowCount();
    for (std::size_t r = 0; r < rows; ++r)
        if (!std::isfinite(t.depth_m[r]))
            throw std::invalid_argument("writeLas: depth of row " + std::to_string(r) +
                                        " is not finite");
    std::vector<LasColumn> columns;
    columns.push_back({"DEPT", "M", "measured depth", t.depth_m.data(), 1});
    for (int k = 1; k <= t.armCount; ++k)
        columns.push_back({"R" + std::to_string(k), "MM", "radius of arm " + std::to_string(k),
                           t.radius_mm.data() + (k - 1), static_cast<std::size_t>(t.armCount)});
    // The azimuths of a table are from true north (docs/conventions.md, "North") unless the
    // reader left them from magnetic or grid north for want of a declination or convergence:
    // the description says so, so that the file reads back unmoved and without a warning.
    const bool trueNorth = t.north.find("left from ") == std::string::npos;
    const struct {
        const char* mnemonic;
        const char* unit;
        const char* description;
        const std::vector<double>* values;
    } optional[] = {
        {"P1AZ", "DEG", trueNorth ? "pad 1 azimuth from true north" : "pad 1 azimuth", &t.p1az_deg},
        {"DEVI", "DEG", "deviation", &t.devi_deg},
        {"HAZI", "DEG", trueNorth ? "hole azimuth from true north" : "hole azimuth", &t.hazi_deg},
        {"RB", "DEG", "relative bearing", &t.rb_deg},
        {"BS", "MM", "bit size", &t.bitSize_mm}};
    for (const auto& o : optional)
        if (o.values->size() == rows && rows > 0)
            columns.push_back({o.mnemonic, o.unit, o.description, o.values->data(), 1});
    for (const ExtraCurve& e : t.extraCurves)
        if (e.values.size() == rows && rows > 0)
            columns.push_back({e.mnemonic, e.unit, e.description, e.values.data(), 1});
    LasWriteOptions exact = options;
    exact.null = nullAbsentFrom(columns, rows, options.null);
    exact.parameters.push_back({"NULLS", "", "DECLARED", "only NULL marks a missing value"});
    writeLasColumns(out, rows, columns, exact);
}

void writeLasFile(const std::string& path, const SectionTable& table,
                  const LasWriteOptions& options) {
    AtomicOutput file(path);
    writeLas(file.stream(), table, options);
    file.commit();
}

}  // namespace caliper3d::io
