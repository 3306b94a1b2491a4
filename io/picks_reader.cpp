#include "io/picks_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <utility>

#include "io/curve_plan.h"
#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/text.h"
#include "io/units.h"

namespace caliper3d::io {

namespace {

// A column as the file names it.
struct Column {
    std::string name;  // upper case
    std::string unit;
};

enum class Field { Top, Bottom, Azimuth, Type, Other };

Field fieldOf(const std::string& name) {
    for (const char* n : {"DEPT", "DEPTH", "MD", "TOP", "MD_TOP", "TOP_MD", "DEPTH_TOP"})
        if (name == n) return Field::Top;
    for (const char* n : {"BOTTOM", "BASE", "BOT", "MD_BOTTOM", "BOTTOM_MD", "DEPTH_BOTTOM"})
        if (name == n) return Field::Bottom;
    for (const char* n : {"AZIMUTH", "AZIM", "AZI", "AZ", "BO_AZ", "BOAZ", "BO_AZIMUTH",
                          "BREAKOUT_AZIMUTH", "ORIENTATION", "DIRECTION"})
        if (name == n) return Field::Azimuth;
    for (const char* n : {"TYPE", "CLASS", "FEATURE", "PICK", "LABEL", "KIND", "NAME"})
        if (name == n) return Field::Type;
    return Field::Other;
}

// The fields of a data line: separated by `delimiter`, or by runs of blanks when it is 0.
std::vector<std::string> fieldsOf(std::string_view line, char delimiter) {
    std::vector<std::string> out;
    if (delimiter == 0) {
        for (std::string_view f : splitBlank(line)) out.emplace_back(f);
        return out;
    }
    std::size_t start = 0;
    while (true) {
        const std::size_t end = line.find(delimiter, start);
        out.emplace_back(
            trim(line.substr(start, end == std::string_view::npos ? end : end - start)));
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    return out;
}

class PickParser {
public:
    explicit PickParser(const std::string& path) : m_path(path) { m_out.path = path; }

    PickFile parse() {
        std::ifstream in(m_path, std::ios::binary);
        if (!in) throw ParseError(m_path, 0, 0, "cannot open the picks file");
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
        bool las = false;
        forEachTrimmedLine(text, 1, [&](std::string_view line, std::size_t) {
            if (line.empty() || line.front() == '#') return true;
            las = line.front() == '~';
            return false;
        });
        if (las)
            parseLas(text);
        else
            parseDelimited(text);
        return std::move(m_out);
    }

private:
    // ~C lines name the columns ("AZIM.DEG : breakout azimuth"); ~A rows hold them, blank
    // separated; the ~W NULL value is a missing reading.
    void parseLas(const std::string& text) {
        char section = 0;
        std::optional<double> null;
        bool columnsDone = false;
        forEachTrimmedLine(text, 1, [&](std::string_view line, std::size_t number) {
            if (line.empty() || line.front() == '#') return true;
            if (line.front() == '~') {
                section = static_cast<char>(
                    std::toupper(static_cast<unsigned char>(line.size() > 1 ? line[1] : ' ')));
                if (section == 'A') {
                    columnsDone = true;
                    setUp(number);
                }
                return true;
            }
            const std::size_t dot = line.find('.');
            if ((section == 'W' || section == 'C') && dot != std::string_view::npos) {
                const std::string mnemonic = upper(trim(line.substr(0, dot)));
                std::string_view rest = line.substr(dot + 1);
                const std::size_t blank = rest.find_first_of(" \t");
                const std::string unit(rest.substr(0, blank));
                if (section == 'C') m_columns.push_back({mnemonic, unit});
                if (section == 'W' && mnemonic == "NULL") {
                    const std::size_t colon = rest.rfind(':');
                    double v = 0.0;
                    std::string_view value =
                        blank == std::string_view::npos ? std::string_view() : rest.substr(blank);
                    if (colon != std::string_view::npos && colon > blank)
                        value = rest.substr(blank, colon - blank);
                    if (parseNumber(trim(value), v)) null = v;
                }
                return true;
            }
            if (section == 'A' && columnsDone) row(fieldsOf(line, 0), number, null);
            return true;
        });
        if (!columnsDone) throw ParseError(m_path, 0, 0, "expected a ~A section with the picks");
    }

    // The first line names the columns; the delimiter is the first of comma, tab it holds.
    void parseDelimited(const std::string& text) {
        char delimiter = 0;
        bool header = false;
        forEachTrimmedLine(text, 1, [&](std::string_view line, std::size_t number) {
            if (line.empty() || line.front() == '#') return true;
            if (!header) {
                delimiter = line.find(',') != std::string_view::npos    ? ','
                            : line.find('\t') != std::string_view::npos ? '\t'
                            : line.find(';') != std::string_view::npos  ? ';'
                                                                        : 0;
                for (const std::string& f : fieldsOf(line, delimiter)) {
                    const auto [name, unit] = splitColumnName(f);
                    m_columns.push_back({upper(name), std::string(unit)});
                }
                header = true;
                setUp(number);
                return true;
            }
            row(fieldsOf(line, delimiter), number, std::nullopt);
            return true;
        });
        if (!header) throw ParseError(m_path, 0, 0, "expected a line naming the picks' columns");
    }

    // Which column is which, and their units.
    void setUp(std::size_t line) {
        for (std::size_t c = 0; c < m_columns.size(); ++c) {
            int* slot = nullptr;
            switch (fieldOf(m_columns[c].name)) {
                case Field::Top:
                    slot = &m_top;
                    break;
                case Field::Bottom:
                    slot = &m_bottom;
                    break;
                case Field::Azimuth:
                    slot = &m_azimuth;
                    break;
                case Field::Type:
                    slot = &m_type;
                    break;
                case Field::Other:
                    break;
            }
            if (slot && *slot < 0) *slot = static_cast<int>(c);
        }
        if (m_top < 0)
            throw ParseError(m_path, line, 0,
                             "expected a depth column (DEPTH, MD or TOP) among the picks' columns");
        if (m_azimuth < 0)
            throw ParseError(m_path, line, 0,
                             "expected an azimuth column (AZIMUTH, AZIM, AZI or AZ) among the "
                             "picks' columns");
        const std::string& depthUnit = m_columns[static_cast<std::size_t>(m_top)].unit;
        if (const auto unit = parseLengthUnit(depthUnit)) {
            m_depthScale = toMetres(*unit);
        } else {
            if (!depthUnit.empty())
                throw ParseError(
                    m_path, line, 0,
                    "expected a depth unit M or FT for the picks, found '" + depthUnit + "'");
            m_out.diagnostics.warn(m_path, line, "picks' depths have no unit: read as metres");
        }
        m_angleScale = angleScaleOf(m_columns[static_cast<std::size_t>(m_azimuth)].unit);
        if (!std::isfinite(m_angleScale))
            throw ParseError(m_path, line, 0,
                             "expected an azimuth unit DEG or RAD for the picks, found '" +
                                 m_columns[static_cast<std::size_t>(m_azimuth)].unit + "'");
    }

    void row(const std::vector<std::string>& fields, std::size_t line, std::optional<double> null) {
        auto number = [&](int column, double& value) {
            if (column < 0 || static_cast<std::size_t>(column) >= fields.size()) return false;
            if (!parseNumber(fields[static_cast<std::size_t>(column)], value)) return false;
            return !(null && value == *null) && std::isfinite(value);
        };
        Pick p;
        p.line = line;
        double top = 0.0, azimuth = 0.0, bottom = 0.0;
        if (!number(m_top, top)) {
            m_out.diagnostics.warn(m_path, line, "pick skipped: its depth is not a number");
            return;
        }
        if (!number(m_azimuth, azimuth) || azimuth * m_angleScale < 0.0 ||
            azimuth * m_angleScale > 360.0) {
            m_out.diagnostics.warn(m_path, line,
                                   "pick skipped: expected an azimuth from 0 to 360 degrees");
            return;
        }
        p.top_m = top * m_depthScale;
        p.bottom_m = number(m_bottom, bottom) ? bottom * m_depthScale : p.top_m;
        if (p.bottom_m < p.top_m) std::swap(p.top_m, p.bottom_m);
        p.azimuth_deg = std::fmod(azimuth * m_angleScale, 360.0);
        if (m_type >= 0 && static_cast<std::size_t>(m_type) < fields.size())
            p.type = fields[static_cast<std::size_t>(m_type)];
        m_out.picks.push_back(std::move(p));
    }

    const std::string& m_path;
    PickFile m_out;
    std::vector<Column> m_columns;
    int m_top = -1, m_bottom = -1, m_azimuth = -1, m_type = -1;
    double m_depthScale = 1.0, m_angleScale = 1.0;
};

}  // namespace

PickFile readPicks(const std::string& path) {
    return PickParser(path).parse();
}

double axialDifference_deg(double a_deg, double b_deg) {
    const double d = std::fmod(std::abs(a_deg - b_deg), 180.0);
    return std::min(d, 180.0 - d);
}

}  // namespace caliper3d::io
