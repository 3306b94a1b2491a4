#include "io/column_text_reader.h"

#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "io/number_parsing.h"
#include "io/parse_error.h"

namespace caliper3d::io {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string columnName(int column, int armCount) {
    if (column == 0) return "depth";
    if (column <= armCount) return "R" + std::to_string(column);
    static const char* const kAngles[] = {"P1AZ", "DEVI", "HAZI"};
    return kAngles[column - armCount - 1];
}

std::string expectedLayout(int armCount) {
    return std::to_string(armCount + 4) + " columns (depth R1..R" + std::to_string(armCount) +
           " P1AZ DEVI HAZI)";
}

}  // namespace

SectionTable parseColumnText(const std::string& text, const std::string& name,
                             const ColumnTextOptions& options, Diagnostics* diagnostics) {
    (void)diagnostics;
    if (options.armCount < 2 || options.armCount > 256)
        throw ParseError(name, 0, 0, "arm count must be between 2 and 256");
    const int arms = options.armCount;
    const int columns = arms + 4;
    const double depthScale = toMetres(options.depthUnit);
    const double radiusScale = toMillimetres(options.radiusUnit);

    SectionTable table;
    table.source = name;
    table.armCount = arms;

    std::vector<double> fields(static_cast<std::size_t>(columns));
    std::size_t lineNumber = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + pos, end - pos);
        const std::size_t lineStart = pos;
        pos = end + 1;
        ++lineNumber;

        std::size_t i = 0;
        while (i < line.size() && isBlank(line[i])) ++i;
        if (i == line.size() || line[i] == '#') continue;

        int column = 0;
        while (i < line.size()) {
            std::size_t start = i;
            while (i < line.size() && !isBlank(line[i])) ++i;
            std::string_view token = line.substr(start, i - start);
            if (column >= columns) {
                throw ParseError(name, lineNumber, start + 1,
                                 "expected " + expectedLayout(arms) + ", found more");
            }
            double value = 0.0;
            if (!parseNumber(token, value)) {
                throw ParseError(name, lineNumber, start + 1,
                                 "expected a number for " + columnName(column, arms) +
                                     ", found '" + std::string(token) + "'");
            }
            fields[static_cast<std::size_t>(column++)] = value;
            while (i < line.size() && isBlank(line[i])) ++i;
        }
        if (column != columns) {
            throw ParseError(name, lineNumber, 0,
                             "expected " + expectedLayout(arms) + ", found " +
                                 std::to_string(column));
        }
        (void)lineStart;
        table.depth_m.push_back(fields[0] * depthScale);
        for (int k = 0; k < arms; ++k) table.radius_mm.push_back(fields[1 + k] * radiusScale);
        table.p1az_deg.push_back(fields[arms + 1]);
        table.devi_deg.push_back(fields[arms + 2]);
        table.hazi_deg.push_back(fields[arms + 3]);
    }
    return table;
}

SectionTable readColumnText(const std::string& path, const ColumnTextOptions& options,
                            Diagnostics* diagnostics) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ParseError(path, 0, 0, "cannot open file for reading");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return parseColumnText(buffer.str(), path, options, diagnostics);
}

}  // namespace caliper3d::io
