#include "io/survey_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/section_table.h"

namespace caliper3d::io {

namespace {

struct Field {
    std::string_view text;
    std::size_t column = 1;  // 1-based character column of the field's start
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

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

}  // namespace

SurveyTable parseSurvey(const std::string& text, const std::string& name,
                        const SurveyReadOptions& options) {
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
                         "no survey header found: expected a line naming measured depth, "
                         "inclination and azimuth columns (e.g. MD,INC,AZI)");
    table.headerLine = i + 1;
    const std::vector<Field> header = split(lines[i], delimiter);
    std::array<std::optional<LengthUnit>, kRoleCount> units;
    for (int role : {kMd, kTvd, kNorth, kEast})
        if (columns[static_cast<std::size_t>(role)] >= 0)
            units[static_cast<std::size_t>(role)] = unitOfName(header[static_cast<std::size_t>(columns[static_cast<std::size_t>(role)])].text);
    ++i;

    // An optional units line: "(m),(Deg),..." or "m , , m, ...".
    while (i < lines.size() && isComment(lines[i])) ++i;
    if (i < lines.size()) {
        const std::vector<Field> fields = split(lines[i], delimiter);
        if (!fields.empty() && !isNumber(fields[0].text)) {
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
    auto scaleOf = [&](int role) {
        if (options.depthUnit) return toMetres(*options.depthUnit);
        const auto& u = units[static_cast<std::size_t>(role)];
        return toMetres(u ? *u : depthUnit);
    };
    const double mdScale = scaleOf(kMd);
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
    for (; i < lines.size(); ++i) {
        if (isComment(lines[i])) continue;
        const std::size_t lineNumber = i + 1;
        const std::vector<Field> fields = split(lines[i], delimiter);
        if (!isDataLine(lines[i])) {
            // Free text after the table ends it; before more stations it is an error.
            if (i > lastData && table.stationCount() > 0) break;
            const std::size_t col = static_cast<int>(fields.size()) > columns[kMd]
                                        ? fields[static_cast<std::size_t>(columns[kMd])].column
                                        : 1;
            throw ParseError(name, lineNumber, col, "expected a number (measured depth)");
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
                             "inclination must be between 0 and 180 degrees");
        if (!table.md_m.empty() && md < table.md_m.back())
            throw ParseError(name, lineNumber, fields[static_cast<std::size_t>(columns[kMd])].column,
                             "measured depths must not decrease");
        table.md_m.push_back(md);
        table.inc_deg.push_back(inc);
        table.azi_deg.push_back(azi);
        if (hasTvd) table.tvd_m.push_back(number(kTvd, "TVD", false) * scaleOf(kTvd));
        if (hasNorth) table.north_m.push_back(number(kNorth, "north", false) * scaleOf(kNorth));
        if (hasEast) table.east_m.push_back(number(kEast, "east", false) * scaleOf(kEast));
    }
    if (table.stationCount() < 2)
        throw ParseError(name, 0, 0, "a survey needs at least two stations, found " +
                                         std::to_string(table.stationCount()));
    return table;
}

SurveyTable readSurvey(const std::string& path, const SurveyReadOptions& options) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ParseError(path, 0, 0, "cannot open the survey file");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return parseSurvey(buffer.str(), path, options);
}

}  // namespace caliper3d::io
