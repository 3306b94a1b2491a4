#include "io/layout/las_layout.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "io/casing_program.h"
#include "io/las_reader.h"
#include "io/parse_error.h"
#include "io/text.h"
#include "io/well_location.h"

namespace caliper3d::io {

std::string lasVersionText(const LasHeader& h) {
    std::ostringstream version;
    version << "LAS " << h.version << (h.version == std::floor(h.version) ? ".0" : "")
            << (h.wrap ? ", wrapped" : "");
    return version.str();
}

RowFormat lasRowFormat(const LasHeader& h, const std::vector<ColumnSpec>& columns,
                       NullPolicy policy, const std::string& file, int depthColumn) {
    RowFormat f;
    f.file = file;
    f.las = true;
    f.wrapped = h.wrap;
    f.delimiter = h.delimiter;
    f.declared = columns.size();
    f.tokens = columns.size();
    f.hasNull = h.hasNull;
    f.null = h.null;
    f.nullPolicy = h.onlyDeclaredNull ? NullPolicy::Declared : policy;
    f.depthColumn = depthColumn;
    for (const ColumnSpec& c : columns) {
        f.textColumn.push_back(c.text);
        f.names.push_back(c.mnemonic);
    }
    f.layout = std::to_string(columns.size()) + " values";  // one per ~C curve
    return f;
}

LogLayout lasLayout(const LasHeader& h, const std::string& file, const ReadOptions& options,
                    LogInfo& info) {
    info.format = lasVersionText(h);
    if (const LasItem* well = h.wellItem("WELL")) info.wellName = well->value;
    if (h.hasNull)
        if (const LasItem* null = h.wellItem("NULL")) info.declaredNull = null->value;
    info.location = readWellLocation(h, file, &info.diagnostics);
    info.casing = readCasingProgram(h, file, &info.diagnostics);
    if (h.curves.empty())
        throw ParseError(file, 0, 0, "expected a ~C (curve information) section, found none");
    LogLayout layout;
    layout.columns = lasColumns(h, &info.diagnostics);
    layout.plan = makeCurvePlan(layout.columns, &h, options, file, info, info.diagnostics);
    layout.format =
        lasRowFormat(h, layout.columns, options.nullPolicy, file, layout.plan.depthColumn);
    // A value that is not a number in a curve the reader does not need (a
    // picks file's "BREAKOUT", one "12.3.4") is read as null and counted; in
    // the depth, an arm, an orientation angle or the bit size it is refused.
    const CurvePlan& plan = layout.plan;
    layout.format.lenient.assign(layout.columns.size(), 1);
    layout.format.lenient[static_cast<std::size_t>(plan.depthColumn)] = 0;
    for (int c : plan.armColumn) layout.format.lenient[static_cast<std::size_t>(c)] = 0;
    for (int c : plan.angleColumn)
        if (c >= 0) layout.format.lenient[static_cast<std::size_t>(c)] = 0;
    if (plan.bitSizeColumn >= 0)
        layout.format.lenient[static_cast<std::size_t>(plan.bitSizeColumn)] = 0;
    return layout;
}

void settleLasColumns(std::string_view text, std::size_t linesBefore,
                      const std::vector<ColumnSpec>& columns, RowFormat& format,
                      Diagnostics& diagnostics) {
    // The first data line, if any before another section.
    std::string_view first;
    std::size_t line = 0;
    forEachTrimmedLine(text, linesBefore + 1, [&](std::string_view l, std::size_t number) {
        if (l.empty() || l.front() == '#') return true;
        if (l.front() != '~') {
            first = l;
            line = number;
        }
        return false;
    });
    if (first.empty()) return;
    const bool tabs = format.delimiter == '\t' && first.find('\t') != std::string_view::npos;
    const char separator = format.delimiter == ',' ? ',' : tabs ? '\t' : ' ';
    const std::size_t count =
        separator != ' '
            ? static_cast<std::size_t>(std::count(first.begin(), first.end(), separator)) + 1
            : splitBlank(first).size();
    const std::size_t declared = columns.size();
    if (count >= declared || count == 0 || separator != ' ') return;
    std::string missing;
    for (std::size_t c = count; c < declared; ++c)
        missing += (missing.empty() ? "" : ", ") + columns[c].mnemonic;
    if (static_cast<std::size_t>(format.depthColumn) >= count)
        throw ParseError(format.file, line, 0,
                         "expected the depth curve among the data columns, found " +
                             std::to_string(count) + " values");
    diagnostics.warn(format.file, line,
                     std::to_string(declared) + " curves declared but rows hold " +
                         std::to_string(count) + " values; no data for " + missing);
    format.tokens = count;
    format.layout = std::to_string(count) + " values";
}

}  // namespace caliper3d::io
