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
        const std::string_view raw =
            line.substr(start, end == std::string_view::npos ? line.npos : end - start);
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
        const std::string_view inside =
            trim(name.substr(open + 1, close == name.npos ? name.npos : close - open - 1));
        if (auto u = parseLengthUnit(inside)) return u;
    }
    const std::size_t underscore = name.rfind('_');
    if (underscore != std::string_view::npos)
        return parseLengthUnit(trim(name.substr(underscore + 1)));
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
        if (parseLengthUnit(suffix) || suffix == "deg" || suffix == "DEG")
            name = name.substr(0, underscore);
    }
    std::string out;
    for (char c : name)
        if (std::isalnum(static_cast<unsigned char>(c)))
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
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

namespace {

// parseSurvey's steps: the header line, an optional units line, the columns as
// info lists them, the stations, and the choice of well in a multi-well table.
class SurveyParser {
public:
    SurveyParser(const std::string& text, const std::string& name, const SurveyReadOptions& options,
                 Diagnostics* diagnostics)
        : m_name(name), m_options(options), m_diagnostics(diagnostics) {
        splitLines(text);
        m_table.source = name;
    }

    SurveyTable parse() {
        findHeader();
        readUnitsLine();
        describeColumns();
        readStations();
        if (m_wellColumn >= 0) chooseWell();
        if (m_table.stationCount() < 2)
            throw ParseError(
                m_name, 0, 0,
                "expected at least two stations, found " + std::to_string(m_table.stationCount()));
        return std::move(m_table);
    }

private:
    void warn(std::size_t line, std::string message) const {
        if (m_diagnostics) m_diagnostics->warn(m_name, line, std::move(message));
    }

    static bool isComment(std::string_view line) {
        const std::string_view t = trim(line);
        return t.empty() || t.front() == '#';
    }

    std::size_t column(int role) const {
        return static_cast<std::size_t>(m_columns[static_cast<std::size_t>(role)]);
    }

    // Lines, with a UTF-8 BOM and '\r' removed.
    void splitLines(const std::string& text) {
        std::size_t pos = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
        while (pos < text.size()) {
            std::size_t end = text.find('\n', pos);
            if (end == std::string::npos) end = text.size();
            std::string_view line(text.data() + pos, end - pos);
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            m_lines.push_back(line);
            pos = end + 1;
        }
    }

    // The first line naming MD, inclination and azimuth columns; its delimiter, units and well
    // column.
    void findHeader() {
        for (; m_i < m_lines.size(); ++m_i) {
            if (isComment(m_lines[m_i])) continue;
            const char d = detectDelimiter(m_lines[m_i]);
            const auto found = matchHeader(split(m_lines[m_i], d));
            if (found[kMd] >= 0 && found[kInc] >= 0 && found[kAzi] >= 0) {
                m_columns = found;
                m_delimiter = d;
                break;
            }
        }
        if (m_i == m_lines.size())
            throw ParseError(m_name, 0, 0,
                             "expected a survey header, a line naming measured depth, inclination "
                             "and azimuth columns (e.g. MD,INC,AZI), found none in " +
                                 std::to_string(m_lines.size()) + " lines");
        m_table.headerLine = m_i + 1;
        m_table.delimiter = m_delimiter;
        m_header = split(m_lines[m_i], m_delimiter);
        for (std::size_t c = 0; c < m_header.size(); ++c) {
            const std::string n = normalise(m_header[c].text);
            if (m_wellColumn < 0 && (n == "well" || n == "wellname" || n == "wellbore"))
                m_wellColumn = static_cast<int>(c);
        }
        const std::string azimuthName = normalise(m_header[column(kAzi)].text);
        if (azimuthName == "azimuthgrid" || azimuthName == "azimgn" || azimuthName == "azimuthgn")
            warn(m_table.headerLine,
                 "azimuth read from the grid-north column '" +
                     std::string(trim(m_header[column(kAzi)].text)) +
                     "' (no true-north column): grid convergence is not applied");
        for (int role : {kMd, kTvd, kNorth, kEast})
            if (m_columns[static_cast<std::size_t>(role)] >= 0)
                m_units[static_cast<std::size_t>(role)] = unitOfName(m_header[column(role)].text);
        ++m_i;
    }

    static std::string_view unbracketed(std::string_view t) {
        t = trim(t);
        if (!t.empty() && t.front() == '(')
            t = trim(t.substr(1, t.find(')') == t.npos ? t.npos : t.find(')') - 1));
        return t;
    }

    // An optional units line: "(m),(Deg),..." or "m , , m, ...".
    void readUnitsLine() {
        while (m_i < m_lines.size() && isComment(m_lines[m_i])) ++m_i;
        if (m_i >= m_lines.size()) return;
        const std::vector<Field> fields = split(m_lines[m_i], m_delimiter);
        if (fields.size() <= column(kMd) || isNumber(fields[column(kMd)].text)) return;
        for (const Field& f : fields)
            if (unbracketed(f.text).size() > 12) return;
        for (int role : {kMd, kTvd, kNorth, kEast}) {
            const int c = m_columns[static_cast<std::size_t>(role)];
            if (c < 0 || static_cast<std::size_t>(c) >= fields.size()) continue;
            if (auto u = parseLengthUnit(unbracketed(fields[static_cast<std::size_t>(c)].text)))
                m_units[static_cast<std::size_t>(role)] = u;
        }
        ++m_i;
    }

    LengthUnit lengthUnitOf(int role) const {
        if (m_options.depthUnit) return *m_options.depthUnit;
        const auto& u = m_units[static_cast<std::size_t>(role)];
        return u ? *u : m_table.depthUnit;
    }

    double scaleOf(int role) const { return toMetres(lengthUnitOf(role)); }

    void describeColumns() {
        m_table.depthUnit = m_options.depthUnit ? *m_options.depthUnit
                            : m_units[kMd]      ? *m_units[kMd]
                                                : m_options.defaultDepthUnit;
        m_mdScale = scaleOf(kMd);
        const char* roleNames[kRoleCount] = {"measured depth",
                                             "inclination",
                                             "azimuth",
                                             "TVD (read for checking)",
                                             "north (read for checking)",
                                             "east (read for checking)"};
        for (std::size_t c = 0; c < m_header.size(); ++c) {
            SurveyColumn col{std::string(trim(m_header[c].text)), "", ""};
            for (int role = 0; role < kRoleCount; ++role)
                if (m_columns[static_cast<std::size_t>(role)] == static_cast<int>(c)) {
                    col.role = roleNames[role];
                    col.unit = role == kInc || role == kAzi
                                   ? "deg"
                                   : std::string(unitName(lengthUnitOf(role)));
                }
            if (static_cast<int>(c) == m_wellColumn) col.role = "well name";
            m_table.columns.push_back(std::move(col));
        }
    }

    // A data line is one whose MD field is a number.
    bool isDataLine(std::string_view line) const {
        const std::vector<Field> f = split(line, m_delimiter);
        return f.size() > column(kMd) && isNumber(f[column(kMd)].text);
    }

    void readStations() {
        // Free text after the last station is a footer; found once, from the end,
        // so that a long footer costs one pass, not one pass per line.
        std::size_t lastData = m_i;
        for (std::size_t j = m_lines.size(); j > m_i; --j)
            if (!isComment(m_lines[j - 1]) && isDataLine(m_lines[j - 1])) {
                lastData = j - 1;
                break;
            }
        for (; m_i < m_lines.size(); ++m_i) {
            if (isComment(m_lines[m_i])) continue;
            const std::size_t lineNumber = m_i + 1;
            const std::vector<Field> fields = split(m_lines[m_i], m_delimiter);
            if (!isDataLine(m_lines[m_i])) {
                // Free text after the table ends it; before more stations it is an error.
                if (m_i > lastData && (m_table.stationCount() > 0 || m_otherWellStations > 0)) {
                    std::size_t footer = 0;
                    for (std::size_t j = m_i; j < m_lines.size(); ++j)
                        footer += !isComment(m_lines[j]);
                    warn(lineNumber,
                         std::to_string(footer) + " lines of text after the last station skipped");
                    break;
                }
                const bool hasMd = fields.size() > column(kMd);
                const std::size_t col = hasMd ? fields[column(kMd)].column : 1;
                const std::string found = std::string(
                    (hasMd ? trim(fields[column(kMd)].text) : trim(m_lines[m_i])).substr(0, 40));
                throw ParseError(m_name, lineNumber, col,
                                 "expected a number (measured depth), found '" + found + "'");
            }
            if (m_wellColumn >= 0 && !isWellAsked(fields)) {
                ++m_otherWellStations;
                continue;
            }
            station(fields, lineNumber);
        }
    }

    // Several wells in one table: read one, the first or the one asked for.
    bool isWellAsked(const std::vector<Field>& fields) {
        const std::size_t at = static_cast<std::size_t>(m_wellColumn);
        const std::string well =
            at < fields.size() ? std::string(trim(fields[at].text)) : std::string();
        if (std::find(m_wells.begin(), m_wells.end(), well) == m_wells.end())
            m_wells.push_back(well);
        if (m_table.wellName.empty() && (m_options.well.empty() || well == m_options.well))
            m_table.wellName = well;
        return well == m_table.wellName && !m_table.wellName.empty();
    }

    double number(const std::vector<Field>& fields, std::size_t lineNumber, int role,
                  const char* what, bool required) const {
        const int c = m_columns[static_cast<std::size_t>(role)];
        if (c < 0 || static_cast<std::size_t>(c) >= fields.size()) {
            if (required)
                throw ParseError(m_name, lineNumber, m_lines[lineNumber - 1].size() + 1,
                                 std::string("missing ") + what);
            return kNaN;
        }
        const Field& f = fields[static_cast<std::size_t>(c)];
        double v = kNaN;
        if (trim(f.text).empty() && !required) return kNaN;
        if (!parseNumber(trim(f.text), v) || !std::isfinite(v))
            throw ParseError(m_name, lineNumber, f.column,
                             std::string("expected a number (") + what + "), found '" +
                                 std::string(f.text) + "'");
        return v;
    }

    void station(const std::vector<Field>& fields, std::size_t lineNumber) {
        const int needed = std::max({m_columns[kMd], m_columns[kInc], m_columns[kAzi]}) + 1;
        if (static_cast<int>(fields.size()) < needed)
            throw ParseError(m_name, lineNumber, m_lines[lineNumber - 1].size() + 1,
                             "expected " + std::to_string(needed) +
                                 " fields (MD, inclination, azimuth), found " +
                                 std::to_string(fields.size()));
        const double md = number(fields, lineNumber, kMd, "measured depth", true) * m_mdScale;
        const double inc = number(fields, lineNumber, kInc, "inclination", true);
        const double azi = number(fields, lineNumber, kAzi, "azimuth", true);
        if (inc < 0.0 || inc > 180.0)
            throw ParseError(m_name, lineNumber, fields[column(kInc)].column,
                             "expected an inclination between 0 and 180 degrees, found " +
                                 std::string(trim(fields[column(kInc)].text)));
        if (!m_table.md_m.empty() && md < m_table.md_m.back())
            throw ParseError(m_name, lineNumber, fields[column(kMd)].column,
                             "expected measured depths that do not decrease (at least the " +
                                 formatNumber(m_table.md_m.back() / m_mdScale) +
                                 " of the station before), found " +
                                 std::string(trim(fields[column(kMd)].text)));
        m_table.md_m.push_back(md);
        m_table.inc_deg.push_back(inc);
        m_table.azi_deg.push_back(azi);
        if (m_columns[kTvd] >= 0)
            m_table.tvd_m.push_back(number(fields, lineNumber, kTvd, "TVD", false) * scaleOf(kTvd));
        if (m_columns[kNorth] >= 0)
            m_table.north_m.push_back(number(fields, lineNumber, kNorth, "north", false) *
                                      scaleOf(kNorth));
        if (m_columns[kEast] >= 0)
            m_table.east_m.push_back(number(fields, lineNumber, kEast, "east", false) *
                                     scaleOf(kEast));
    }

    void chooseWell() {
        m_table.wellCount = m_wells.size();
        const Field& wellHeader = m_header[static_cast<std::size_t>(m_wellColumn)];
        if (!m_options.well.empty() && m_table.wellName.empty()) {
            std::string names;
            for (const std::string& w : m_wells) names += (names.empty() ? "'" : ", '") + w + "'";
            throw ParseError(m_name, m_table.headerLine, wellHeader.column,
                             "expected stations of well '" + m_options.well + "' in column '" +
                                 std::string(trim(wellHeader.text)) + "', found only " +
                                 (names.empty() ? std::string("none") : names));
        }
        if (m_wells.size() > 1)
            warn(m_table.headerLine,
                 "the table holds " + std::to_string(m_wells.size()) + " wells in column '" +
                     std::string(trim(wellHeader.text)) + "'; read '" + m_table.wellName + "' (" +
                     std::to_string(m_table.stationCount()) + " stations), " +
                     std::to_string(m_otherWellStations) + " stations of other wells skipped");
    }

    const std::string& m_name;
    const SurveyReadOptions& m_options;
    Diagnostics* m_diagnostics;
    std::vector<std::string_view> m_lines;
    std::size_t m_i = 0;  // the line being read
    SurveyTable m_table;
    std::array<int, kRoleCount> m_columns{};
    char m_delimiter = ',';
    std::vector<Field> m_header;
    int m_wellColumn = -1;
    std::array<std::optional<LengthUnit>, kRoleCount> m_units;
    double m_mdScale = 1.0;
    std::vector<std::string> m_wells;  // names in the well column, in order of first appearance
    std::size_t m_otherWellStations = 0;
};

}  // namespace

SurveyTable parseSurvey(const std::string& text, const std::string& name,
                        const SurveyReadOptions& options, Diagnostics* diagnostics) {
    return SurveyParser(text, name, options, diagnostics).parse();
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
            if (role == CurveRole::Radius || role == CurveRole::Finger ||
                role == CurveRole::Diameter || role == CurveRole::PadAzimuth)
                return false;
        }
        return true;
    }
    return false;
}

SurveyTable readSurvey(const std::string& path, const SurveyReadOptions& options,
                       Diagnostics* diagnostics) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ParseError(path, 0, 0, "cannot open the survey file");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return parseSurvey(buffer.str(), path, options, diagnostics);
}

}  // namespace caliper3d::io
