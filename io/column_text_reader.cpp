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
    if (options.armCount < 2 || options.armCount > 256)
        throw ParseError(name, 0, 0, "arm count must be between 2 and 256");
    int arms = options.armCount;
    int columns = arms + 4;
    bool radiiOnly = false;
    bool firstContent = true;
    const double depthScale = toMetres(options.depthUnit);
    const double radiusScale = toMillimetres(options.radiusUnit);

    SectionTable table;
    table.source = name;
    table.armCount = arms;

    std::vector<std::string_view> tokens;
    std::vector<std::size_t> starts;
    std::vector<double> fields;
    std::size_t lineNumber = 0;
    std::size_t pos = 0;
    const std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // UTF-8 BOM
    pos = start;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + pos, end - pos);
        pos = end + 1;
        ++lineNumber;

        tokens.clear();
        starts.clear();
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && isBlank(line[i])) ++i;
            if (i == line.size()) break;
            std::size_t j = i;
            while (j < line.size() && !isBlank(line[j])) ++j;
            tokens.push_back(line.substr(i, j - i));
            starts.push_back(i + 1);
            i = j;
        }
        if (tokens.empty() || tokens.front().front() == '#') continue;

        if (firstContent) {
            firstContent = false;
            double v = 0.0;
            bool anyNumber = false;
            for (std::string_view t : tokens) anyNumber = anyNumber || parseNumber(t, v);
            if (!anyNumber) continue;  // a line of column names
            const int found = static_cast<int>(tokens.size());
            if (found != columns && options.allowRadiiOnly && found >= ColumnTextOptions::kMinRadiiOnlyColumns) {
                radiiOnly = true;
                arms = found;
                columns = found;
                table.armCount = arms;
                if (diagnostics)
                    diagnostics->warn(name, lineNumber,
                                      std::to_string(found) + " numbers per line and no depth column: read as " +
                                          std::to_string(found) + " radii per row, depth = row x " +
                                          std::to_string(options.rowStep_m) + " m");
            }
        }

        if (static_cast<int>(tokens.size()) != columns) {
            const std::size_t at = static_cast<int>(tokens.size()) > columns ? starts[static_cast<std::size_t>(columns)] : 0;
            const std::string layout = radiiOnly ? std::to_string(columns) + " radii" : expectedLayout(arms);
            throw ParseError(name, lineNumber, at,
                             "expected " + layout + ", found " + std::to_string(tokens.size()));
        }
        fields.resize(tokens.size());
        for (std::size_t c = 0; c < tokens.size(); ++c) {
            if (!parseNumber(tokens[c], fields[c])) {
                const std::string column = radiiOnly ? "radius " + std::to_string(c + 1)
                                                     : columnName(static_cast<int>(c), arms);
                throw ParseError(name, lineNumber, starts[c],
                                 "expected a number for " + column + ", found '" + std::string(tokens[c]) + "'");
            }
        }
        if (radiiOnly) {
            table.depth_m.push_back(static_cast<double>(table.depth_m.size()) * options.rowStep_m);
            for (int k = 0; k < arms; ++k) table.radius_mm.push_back(fields[static_cast<std::size_t>(k)] * radiusScale);
            continue;
        }
        table.depth_m.push_back(fields[0] * depthScale);
        for (int k = 0; k < arms; ++k) table.radius_mm.push_back(fields[1 + static_cast<std::size_t>(k)] * radiusScale);
        table.p1az_deg.push_back(fields[static_cast<std::size_t>(arms) + 1]);
        table.devi_deg.push_back(fields[static_cast<std::size_t>(arms) + 2]);
        table.hazi_deg.push_back(fields[static_cast<std::size_t>(arms) + 3]);
    }
    if (table.rowCount() == 0) throw ParseError(name, 0, 0, "expected rows of numbers (" + expectedLayout(arms) + "), found none");
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
