#include "io/survey_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string_view>

#include "io/curve_plan.h"
#include "io/curve_roles.h"
#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/section_table.h"
#include "io/text.h"

namespace caliper3d::io {

namespace {

struct Field {
    std::string_view text;
    std::size_t column = 1;  // 1-based character column of the field's start
};

// Delimiter of the table, chosen from the header line: ',' ';' '\t' or ' ' (white space).
char detectDelimiter(std::string_view header) {
    for (char c : {',', ';', '\t'})
        if (header.find(c) != std::string_view::npos) return c;
    return ' ';
}

std::vector<Field> split(std::string_view line, char delimiter) {
    std::vector<Field> out;
    if (delimiter == ' ') {
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
            if (i >= line.size()) break;
            const std::size_t start = i;
            while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
            out.push_back({line.substr(start, i - start), start + 1});
        }
        return out;
    }
    std::size_t start = 0;
    while (true) {
        const std::size_t end = line.find(delimiter, start);
        const std::string_view raw = line.substr(start, end == std::string_view::npos ? line.npos : end - start);
        std::size_t lead = 0;
        while (lead < raw.size() && std::isspace(static_cast<unsigned char>(raw[lead]))) ++lead;
        out.push_back({trim(raw), start + lead + 1});
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    return out;
}

// A unit written as "( ft )", "(m)" or a "_ft" suffix; empty when none.
std::optional<LengthUnit> unitOfName(std::string_view name) {
    const std::size_t open = name.find('(');
    if (open != std::string_view::npos) {
        const std::size_t close = name.find(')', open);
        const std::string_view inside = trim(name.substr(open + 1, close == name.npos ? name.npos : close - open - 1));
        if (auto u = parseLengthUnit(inside)) return u;
    }
    const std::size_t underscore = name.rfind('_');
    if (underscore != std::string_view::npos) return parseLengthUnit(trim(name.substr(underscore + 1)));
    return std::nullopt;
}

// Lower-case letters and digits of a column name, without a parenthesised
// unit or a "_unit" suffix: "Measured Depth ( ft )" -> "measureddepth",
// "MD_m" -> "md", "+N/S-" -> "ns", "AZIM_TN" -> "azimtn".
std::string normalise(std::string_view name) {
    const std::size_t open = name.find('(');
    if (open != std::string_view::npos) name = name.substr(0, open);
    const std::size_t underscore = name.rfind('_');
    if (underscore != std::string_view::npos) {
        const std::string_view suffix = trim(name.substr(underscore + 1));
        if (parseLengthUnit(suffix) || suffix == "deg" || suffix == "DEG") name = name.substr(0, underscore);
    }
    std::string out;
    for (char c : name)
        if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

enum Role { kMd, kInc, kAzi, kTvd, kNorth, kEast, kRoleCount };

// Accepted column names per role, after normalise(). Azimuths: true north
// names come before grid north ones so that a file with both gives true.
const std::vector<std::vector<std::string>>& aliases() {
    static const std::vector<std::vector<std::string>> kAliases = {
        {"md", "measureddepth", "mdepth", "depth", "dept"},
        {"inc", "incl", "inclination", "devi", "dev", "deviation"},
        {"azi", "azim", "azimuth", "azimuthtrue", "azimtn", "azimuthtn", "azm", "az", "hazi",
         "azimuthgrid", "azimgn", "azimuthgn"},
        {"tvd", "verticaldepth", "trueverticaldepth"},
        {"n", "ns", "north", "northing", "nsoffset", "dy", "localn"},
        {"e", "ew", "east", "easting", "ewoffset", "dx", "locale"},
    };
    return kAliases;
}

// Column index per role (-1 when absent); all of MD, Inc and Azi found means a header.
std::array<int, kRoleCount> matchHeader(const std::vector<Field>& fields) {
    std::array<int, kRoleCount> columns;
    columns.fill(-1);
    for (int role = 0; role < kRoleCount; ++role) {
        std::size_t bestRank = std::string::npos;
        const auto& names = aliases()[static_cast<std::size_t>(role)];
        for (std::size_t c = 0; c < fields.size(); ++c) {
            const std::string n = normalise(fields[c].text);
            const auto it = std::find(names.begin(), names.end(), n);
            if (it == names.end()) continue;
            const std::size_t rank = static_cast<std::size_t>(it - names.begin());
            if (rank < bestRank) {
                bestRank = rank;
                columns[static_cast<std::size_t>(role)] = static_cast<int>(c);
            }
        }
    }
    return columns;
}

bool isNumber(std::string_view s) {
    double v = 0.0;
    return parseNumber(trim(s), v);
}

std::string formatNumber(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", v);
    return buffer;
}

}  // namespace

SurveyTable parseSurvey(const std::string& text, const std::string& name, const SurveyReadOptions& options,
                        Diagnostics* diagnostics) {
    auto warn = [&](std::size_t line, std::string message) {
        if (diagnostics) diagnostics->warn(name, line, std::move(message));
    };
    // Lines, with a UTF-8 BOM and '\r' removed.
    std::vector<std::string_view> lines;
    {
        std::size_t pos = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
        while (pos < text.size()) {
            std::size_t end = text.find('\n', pos);
            if (end == std::string::npos) end = text.size();
            std::string_view line(text.data() + pos, end - pos);
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            lines.push_back(line);
            pos = end + 1;
        }
    }
    auto isComment = [](std::string_view line) {
        const std::string_view t = trim(line);
        return t.empty() || t.front() == '#';
    };

    SurveyTable table;
    table.source = name;
    std::size_t i = 0;
    std::array<int, kRoleCount> columns{};
    char delimiter = ',';
    for (; i < lines.size(); ++i) {
        if (isComment(lines[i])) continue;
        const char d = detectDelimiter(lines[i]);
        const auto found = matchHeader(split(lines[i], d));
        if (found[kMd] >= 0 && found[kInc] >= 0 && found[kAzi] >= 0) {
            columns = found;
            delimiter = d;
            break;
        }
    }
    if (i == lines.size())
        throw ParseError(name, 0, 0,
                         "expected a survey header, a line naming measured depth, inclination and azimuth "
                         "columns (e.g. MD,INC,AZI), found none in " + std::to_string(lines.size()) + " lines");
    table.headerLine = i + 1;
    table.delimiter = delimiter;
    const std::vector<Field> header = split(lines[i], delimiter);
    int wellColumn = -1;
    for (std::size_t c = 0; c < header.size(); ++c) {
        const std::string n = normalise(header[c].text);
        if (wellColumn < 0 && (n == "well" || n == "wellname" || n == "wellbore")) wellColumn = static_cast<int>(c);
    }
    {
        const std::string azimuthName = normalise(header[static_cast<std::size_t>(columns[kAzi])].text);
        if (azimuthName == "azimuthgrid" || azimuthName == "azimgn" || azimuthName == "azimuthgn")
            warn(table.headerLine, "azimuth read from the grid-north column '" + std::string(trim(header[static_cast<std::size_t>(columns[kAzi])].text)) +
                                       "' (no true-north column): grid convergence is not applied");
    }
    std::array<std::optional<LengthUnit>, kRoleCount> units;
    for (int role : {kMd, kTvd, kNorth, kEast})
        if (columns[static_cast<std::size_t>(role)] >= 0)
            units[static_cast<std::size_t>(role)] = unitOfName(header[static_cast<std::size_t>(columns[static_cast<std::size_t>(role)])].text);
    ++i;

    // An optional units line: "(m),(Deg),..." or "m , , m, ...".
    while (i < lines.size() && isComment(lines[i])) ++i;
    if (i < lines.size()) {
        const std::vector<Field> fields = split(lines[i], delimiter);
        const std::size_t mdAt = static_cast<std::size_t>(columns[kMd]);
        if (fields.size() > mdAt && !isNumber(fields[mdAt].text)) {
            bool allUnits = true;
            for (const Field& f : fields) {
                std::string_view t = trim(f.text);
                if (!t.empty() && t.front() == '(') t = trim(t.substr(1, t.find(')') == t.npos ? t.npos : t.find(')') - 1));
                if (!t.empty() && t.size() > 12) allUnits = false;
            }
            if (allUnits) {
                for (int role : {kMd, kTvd, kNorth, kEast}) {
                    const int c = columns[static_cast<std::size_t>(role)];
                    if (c < 0 || static_cast<std::size_t>(c) >= fields.size()) continue;
                    std::string_view t = trim(fields[static_cast<std::size_t>(c)].text);
                    if (!t.empty() && t.front() == '(') t = trim(t.substr(1, t.find(')') == t.npos ? t.npos : t.find(')') - 1));
                    if (auto u = parseLengthUnit(t)) units[static_cast<std::size_t>(role)] = u;
                }
                ++i;
            }
        }
    }

    const LengthUnit depthUnit = options.depthUnit ? *options.depthUnit
                                 : units[kMd]      ? *units[kMd]
                                                   : options.defaultDepthUnit;
    table.depthUnit = depthUnit;
    auto lengthUnitOf = [&](int role) {
        if (options.depthUnit) return *options.depthUnit;
        const auto& u = units[static_cast<std::size_t>(role)];
        return u ? *u : depthUnit;
    };
    auto scaleOf = [&](int role) { return toMetres(lengthUnitOf(role)); };
    const double mdScale = scaleOf(kMd);
    {
        const char* roleNames[kRoleCount] = {"measured depth", "inclination", "azimuth", "TVD (read for checking)",
                                             "north (read for checking)", "east (read for checking)"};
        for (std::size_t c = 0; c < header.size(); ++c) {
            SurveyColumn column{std::string(trim(header[c].text)), "", ""};
            for (int role = 0; role < kRoleCount; ++role)
                if (columns[static_cast<std::size_t>(role)] == static_cast<int>(c)) {
                    column.role = roleNames[role];
                    column.unit = role == kInc || role == kAzi ? "deg" : std::string(unitName(lengthUnitOf(role)));
                }
            if (static_cast<int>(c) == wellColumn) column.role = "well name";
            table.columns.push_back(std::move(column));
        }
    }
    const bool hasTvd = columns[kTvd] >= 0, hasNorth = columns[kNorth] >= 0, hasEast = columns[kEast] >= 0;

    // A data line is one whose MD field is a number.
    auto isDataLine = [&](std::string_view line) {
        const std::vector<Field> f = split(line, delimiter);
        return static_cast<int>(f.size()) > columns[kMd] && isNumber(f[static_cast<std::size_t>(columns[kMd])].text);
    };

    const int needed = std::max({columns[kMd], columns[kInc], columns[kAzi]}) + 1;
    // Free text after the last station is a footer; found once, from the end,
    // so that a long footer costs one pass, not one pass per line.
    std::size_t lastData = i;
    for (std::size_t j = lines.size(); j > i; --j)
        if (!isComment(lines[j - 1]) && isDataLine(lines[j - 1])) {
            lastData = j - 1;
            break;
        }
    std::vector<std::string> wells;  // names in the well column, in order of first appearance
    std::size_t otherWellStations = 0;
    for (; i < lines.size(); ++i) {
        if (isComment(lines[i])) continue;
        const std::size_t lineNumber = i + 1;
        const std::vector<Field> fields = split(lines[i], delimiter);
        if (!isDataLine(lines[i])) {
            // Free text after the table ends it; before more stations it is an error.
            if (i > lastData && (table.stationCount() > 0 || otherWellStations > 0)) {
                std::size_t footer = 0;
                for (std::size_t j = i; j < lines.size(); ++j) footer += !isComment(lines[j]);
                warn(lineNumber, std::to_string(footer) + " lines of text after the last station skipped");
                break;
            }
            const std::size_t col = static_cast<int>(fields.size()) > columns[kMd]
                                        ? fields[static_cast<std::size_t>(columns[kMd])].column
                                        : 1;
            const std::string found = static_cast<int>(fields.size()) > columns[kMd]
                                          ? std::string(trim(fields[static_cast<std::size_t>(columns[kMd])].text).substr(0, 40))
                                          : std::string(trim(lines[i]).substr(0, 40));
            throw ParseError(name, lineNumber, col, "expected a number (measured depth), found '" + found + "'");
        }
        if (wellColumn >= 0) {
            // Several wells in one table: read one, the first or the one asked for.
            const std::string well = static_cast<std::size_t>(wellColumn) < fields.size()
                                         ? std::string(trim(fields[static_cast<std::size_t>(wellColumn)].text))
                                         : std::string();
            if (std::find(wells.begin(), wells.end(), well) == wells.end()) wells.push_back(well);
            if (table.wellName.empty() && (options.well.empty() || well == options.well)) table.wellName = well;
            if (well != table.wellName || table.wellName.empty()) {
                ++otherWellStations;
                continue;
            }
        }
        if (static_cast<int>(fields.size()) < needed)
            throw ParseError(name, lineNumber, lines[i].size() + 1,
                             "expected " + std::to_string(needed) + " fields (MD, inclination, azimuth), found " +
                                 std::to_string(fields.size()));
        auto number = [&](int role, const char* what, bool required) {
            const int c = columns[static_cast<std::size_t>(role)];
            if (c < 0 || static_cast<std::size_t>(c) >= fields.size()) {
                if (required) throw ParseError(name, lineNumber, lines[i].size() + 1, std::string("missing ") + what);
                return kNaN;
            }
            const Field& f = fields[static_cast<std::size_t>(c)];
            double v = kNaN;
            if (trim(f.text).empty() && !required) return kNaN;
            if (!parseNumber(trim(f.text), v) || !std::isfinite(v))
                throw ParseError(name, lineNumber, f.column,
                                 std::string("expected a number (") + what + "), found '" + std::string(f.text) + "'");
            return v;
        };
        const double md = number(kMd, "measured depth", true) * mdScale;
        const double inc = number(kInc, "inclination", true);
        const double azi = number(kAzi, "azimuth", true);
        if (inc < 0.0 || inc > 180.0)
            throw ParseError(name, lineNumber, fields[static_cast<std::size_t>(columns[kInc])].column,
                             "expected an inclination between 0 and 180 degrees, found " +
                                 std::string(trim(fields[static_cast<std::size_t>(columns[kInc])].text)));
        if (!table.md_m.empty() && md < table.md_m.back())
            throw ParseError(name, lineNumber, fields[static_cast<std::size_t>(columns[kMd])].column,
                             "expected measured depths that do not decrease (at least the " +
                                 formatNumber(table.md_m.back() / mdScale) + " of the station before), found " +
                                 std::string(trim(fields[static_cast<std::size_t>(columns[kMd])].text)));
        table.md_m.push_back(md);
        table.inc_deg.push_back(inc);
        table.azi_deg.push_back(azi);
        if (hasTvd) table.tvd_m.push_back(number(kTvd, "TVD", false) * scaleOf(kTvd));
        if (hasNorth) table.north_m.push_back(number(kNorth, "north", false) * scaleOf(kNorth));
        if (hasEast) table.east_m.push_back(number(kEast, "east", false) * scaleOf(kEast));
    }
    if (wellColumn >= 0) {
        table.wellCount = wells.size();
        if (!options.well.empty() && table.wellName.empty()) {
            std::string names;
            for (const std::string& w : wells) names += (names.empty() ? "'" : ", '") + w + "'";
            throw ParseError(name, table.headerLine, header[static_cast<std::size_t>(wellColumn)].column,
                             "expected stations of well '" + options.well + "' in column '" +
                                 std::string(trim(header[static_cast<std::size_t>(wellColumn)].text)) + "', found only " +
                                 (names.empty() ? std::string("none") : names));
        }
        if (wells.size() > 1)
            warn(table.headerLine, "the table holds " + std::to_string(wells.size()) + " wells in column '" +
                                       std::string(trim(header[static_cast<std::size_t>(wellColumn)].text)) + "'; read '" +
                                       table.wellName + "' (" + std::to_string(table.stationCount()) + " stations), " +
                                       std::to_string(otherWellStations) + " stations of other wells skipped");
    }
    if (table.stationCount() < 2)
        throw ParseError(name, 0, 0, "expected at least two stations, found " +
                                         std::to_string(table.stationCount()));
    return table;
}

bool looksLikeSurvey(std::string_view head) {
    std::size_t pos = head.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    for (int line = 0; line < 400 && pos < head.size(); ++line) {
        std::size_t end = head.find('\n', pos);
        if (end == std::string_view::npos) end = head.size();
        const std::string_view text = trim(head.substr(pos, end - pos));
        pos = end + 1;
        if (text.empty() || text.front() == '#') continue;
        if (text.front() == '~') return false;  // LAS
        const char d = detectDelimiter(text);
        const std::vector<Field> fields = split(text, d);
        bool allNumbers = !fields.empty();
        for (const Field& f : fields) allNumbers = allNumbers && isNumber(f.text);
        if (allNumbers) return false;  // data before any survey header: not a survey
        const auto found = matchHeader(fields);
        if (found[kMd] < 0 || found[kInc] < 0 || found[kAzi] < 0) continue;
        // "DEPTH R1 .. R6 P1AZ DEVI HAZI" names depth, deviation and azimuth too: a caliper log.
        for (const Field& f : fields) {
            const CurveRole role = guessRole(splitColumnName(trim(f.text)).first).role;
            if (role == CurveRole::Radius || role == CurveRole::Finger || role == CurveRole::Diameter ||
                role == CurveRole::PadAzimuth)
                return false;
        }
        return true;
    }
    return false;
}

SurveyTable readSurvey(const std::string& path, const SurveyReadOptions& options, Diagnostics* diagnostics) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ParseError(path, 0, 0, "cannot open the survey file");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return parseSurvey(buffer.str(), path, options, diagnostics);
}

}  // namespace caliper3d::io
