#include "io/layout/column_text_layout.h"

#include <utility>
#include <vector>

#include "io/median.h"
#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/text.h"

namespace caliper3d::io {

namespace {

// Radii over this many inches (a hole 1.5 m wide) are far likelier millimetres.
constexpr double kMaxPlausibleRadius_in = 30.0;

// The first line of numbers, and the names before it.
struct FirstLines {
    std::vector<std::string_view> numbers;  // fields of the first line holding a number
    std::size_t numbersLine = 0;
    std::vector<std::string_view> names;  // a line of names before it
    std::size_t namesLine = 0;
    std::vector<std::string_view> commentNames;  // the '#' line right before it
    std::size_t commentLine = 0;
    std::size_t skipLines = 0;  // lines up to the last line of names
};

FirstLines readFirstLines(std::string_view text) {
    FirstLines f;
    forEachTrimmedLine(text, 1, [&](std::string_view l, std::size_t line) {
        if (l.empty()) return true;
        if (l.front() == '#') {
            const std::size_t first = l.find_first_not_of('#');
            f.commentNames = first == std::string_view::npos ? std::vector<std::string_view>()
                                                             : splitBlank(trim(l.substr(first)));
            f.commentLine = line;
            return true;
        }
        std::vector<std::string_view> tokens = splitBlank(l);
        double v = 0.0;
        bool anyNumber = false;
        for (std::string_view t : tokens) anyNumber = anyNumber || parseNumber(t, v);
        f.numbersLine = line;
        if (!anyNumber) {
            f.skipLines = line;  // a line of column names
            f.names = std::move(tokens);
            f.namesLine = line;
            f.commentNames.clear();
            return true;
        }
        f.numbers = std::move(tokens);
        return false;
    });
    return f;
}

// Column text without units: radii in inches, unless the first row's median
// radius is over kMaxPlausibleRadius_in inches: those are far likelier
// millimetres, read so with a warning.
LengthUnit unitlessRadiusUnit(std::vector<double> radii, const std::string& file, std::size_t line,
                              Diagnostics& diagnostics) {
    if (radii.empty()) return LengthUnit::Inch;
    const double median = medianInPlace(radii);
    if (!(median > kMaxPlausibleRadius_in)) return LengthUnit::Inch;
    diagnostics.warn(file, line,
                     "radii near " + std::to_string(median) +
                         " would be inches, far too large: read as millimetres (give "
                         "--radius-unit to choose)");
    return LengthUnit::Millimetre;
}

RowFormat columnTextFormat(const std::string& file, const LogLayout& layout) {
    RowFormat f;
    f.file = file;
    f.las = false;
    f.declared = layout.columns.size();
    f.tokens = layout.columns.size();
    f.textColumn.assign(layout.columns.size(), 0);
    f.depthColumn = layout.plan.depthColumn;
    return f;
}

// Named columns: roles from the mnemonics as in LAS, so any order and any
// extra curve (GR, RB, BS, ...) reads right.
LogLayout namedLayout(const std::vector<std::string_view>& names, std::size_t line,
                      const std::vector<std::string_view>& firstRow, const std::string& file,
                      const ReadOptions& given, LogInfo& info) {
    LogLayout layout;
    bool anyUnit = false;
    for (std::string_view n : names) {
        auto [mnemonic, unit] = splitColumnName(n);
        anyUnit = anyUnit || !unit.empty();
        layout.columns.push_back({std::string(mnemonic), std::string(unit), "", false, line});
    }
    ReadOptions options = given;
    if (!anyUnit) {
        if (!options.depthUnit) options.depthUnit = LengthUnit::Metre;
        if (!options.radiusUnit) {
            std::vector<double> radii;
            for (std::size_t c = 0; c < names.size() && c < firstRow.size(); ++c) {
                const CurveRole role = guessRole(layout.columns[c].mnemonic).role;
                double v = 0.0;
                if ((role == CurveRole::Radius || role == CurveRole::Finger) &&
                    parseNumber(firstRow[c], v))
                    radii.push_back(v);
            }
            options.radiusUnit = unitlessRadiusUnit(std::move(radii), file, line, info.diagnostics);
        }
    }
    layout.plan = makeCurvePlan(layout.columns, nullptr, options, file, info, info.diagnostics);
    if (!anyUnit) {
        // Say which units were assumed.
        info.depthUnit = std::string(unitName(*options.depthUnit));
        const std::string radius = std::string(unitName(*options.radiusUnit)) + " (assumed)";
        info.curves[static_cast<std::size_t>(layout.plan.depthColumn)].unit =
            info.depthUnit + " (assumed)";
        for (int c : layout.plan.armColumn) info.curves[static_cast<std::size_t>(c)].unit = radius;
        if (layout.plan.bitSizeColumn >= 0)
            info.curves[static_cast<std::size_t>(layout.plan.bitSizeColumn)].unit = radius;
    }
    info.format = "column text (" + std::to_string(names.size()) +
                  " named columns, names on line " + std::to_string(line) + ")";
    layout.format = columnTextFormat(file, layout);
    for (const ColumnSpec& c : layout.columns) layout.format.names.push_back(c.mnemonic);
    layout.format.layout = std::to_string(layout.columns.size()) + " named columns";
    return layout;
}

// The reference layout (depth R1..RN P1AZ DEVI HAZI), or radii only.
LogLayout referenceLayout(const FirstLines& first, const std::string& file,
                          const ReadOptions& options, LogInfo& info) {
    LogLayout layout;
    int arms = options.armCount;
    const int found = static_cast<int>(first.numbers.size());
    layout.radiiOnly = found != arms + 4 && options.allowRadiiOnly &&
                       found >= kMinRadiiOnlyColumns && found <= kMaxArms;
    const bool radiiOnly = layout.radiiOnly;
    if (radiiOnly) {
        arms = found;
        info.diagnostics.warn(file, first.numbersLine,
                              std::to_string(found) +
                                  " numbers per line and no depth column: read as " +
                                  std::to_string(found) + " radii per row, depth = row x " +
                                  std::to_string(options.rowStep_m) + " m");
    }
    LengthUnit radiusUnit = options.radiusUnit.value_or(LengthUnit::Inch);
    if (!options.radiusUnit && !first.numbers.empty()) {
        std::vector<double> radii;
        for (int k = 0; k < arms; ++k) {
            const std::size_t at = static_cast<std::size_t>(radiiOnly ? k : k + 1);
            double v = 0.0;
            if (at < first.numbers.size() && parseNumber(first.numbers[at], v)) radii.push_back(v);
        }
        radiusUnit =
            unitlessRadiusUnit(std::move(radii), file, first.numbersLine, info.diagnostics);
    }
    const LengthUnit depthUnit = options.depthUnit.value_or(LengthUnit::Metre);
    const std::string radiusUnitName(unitName(radiusUnit));
    layout.columns.push_back(
        {radiiOnly ? "ROW" : "DEPTH", std::string(unitName(depthUnit)), "", false, 0});
    for (int k = 1; k <= arms; ++k)
        layout.columns.push_back({"R" + std::to_string(k), radiusUnitName, "", false, 0});
    if (!radiiOnly)
        for (const char* angle : {"P1AZ", "DEVI", "HAZI"})
            layout.columns.push_back({angle, "deg", "", false, 0});
    ReadOptions plain = options;
    plain.roles = {};
    plain.radiusUnit = radiusUnit;
    plain.depthUnit = depthUnit;
    layout.plan = makeCurvePlan(layout.columns, nullptr, plain, file, info, info.diagnostics);
    const std::string armRange = "R1..R" + std::to_string(arms);
    if (radiiOnly) {
        info.curves.front().role = "depth (row x " + std::to_string(options.rowStep_m) + " m)";
        info.format = "column text (" + std::to_string(arms) + " radii per line, no depth)";
    } else {
        info.format = "column text (depth " + armRange + " P1AZ DEVI HAZI)";
    }
    info.depthUnit = std::string(unitName(depthUnit));
    info.armSource = "radii " + armRange + " (" + radiusUnitName + ")";
    layout.format = columnTextFormat(file, layout);
    layout.format.tokens = radiiOnly ? static_cast<std::size_t>(arms) : layout.columns.size();
    layout.format.firstColumn = radiiOnly ? 1 : 0;
    for (const ColumnSpec& c : layout.columns)
        layout.format.names.push_back(c.mnemonic == "DEPTH" ? "depth" : c.mnemonic);
    layout.format.layout =
        radiiOnly ? std::to_string(arms) + " radii"
                  : std::to_string(arms + 4) + " columns (depth " + armRange + " P1AZ DEVI HAZI)";
    layout.format.depthColumn = 0;
    return layout;
}

}  // namespace

LogLayout columnTextLayout(std::string_view start, const std::string& file,
                           const ReadOptions& options, LogInfo& info) {
    if (options.armCount < kMinArms || options.armCount > kMaxArms)
        throw ParseError(file, 0, 0,
                         "arm count must be between " + std::to_string(kMinArms) + " and " +
                             std::to_string(kMaxArms));
    const FirstLines first = readFirstLines(start);
    const std::size_t found = first.numbers.size();
    std::vector<std::string_view> names = first.names;
    std::size_t namesLine = first.namesLine;
    if (!names.empty() && names.size() != found)
        info.diagnostics.warn(
            file, namesLine,
            std::to_string(names.size()) + " column names over " + std::to_string(found) +
                " columns of numbers: names ignored, columns read as the reference layout");
    if (names.size() != found) {
        names.clear();
        // A comment line of names counts only when it matches and starts with a depth.
        if (first.commentNames.size() == found && found > 0 &&
            guessRole(splitColumnName(first.commentNames.front()).first).role == CurveRole::Depth) {
            names = first.commentNames;
            namesLine = first.commentLine;
        }
    }
    LogLayout layout = names.empty()
                           ? referenceLayout(first, file, options, info)
                           : namedLayout(names, namesLine, first.numbers, file, options, info);
    layout.namesLines = first.skipLines;
    return layout;
}

}  // namespace caliper3d::io
