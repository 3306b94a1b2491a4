#include "io/column_text_writer.h"

#include <charconv>
#include <vector>

#include "io/atomic_output.h"

namespace caliper3d::io {

namespace {

// Shortest text that reads back to the same double ("nan" for a null).
void put(std::string& line, double value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    line.append(buffer, result.ptr);
}

struct Column {
    std::string name;
    const double* values;
    std::size_t stride;
    double scale;
};

}  // namespace

void writeColumnText(std::ostream& out, const SectionTable& table, LengthUnit radiusUnit) {
    const std::size_t rows = table.rowCount();
    const std::string unit(unitName(radiusUnit));
    const double radiusScale = 1.0 / toMillimetres(radiusUnit);
    std::vector<Column> columns;
    columns.push_back({"depth_m", table.depth_m.data(), 1, 1.0});
    for (int k = 0; k < table.armCount; ++k)
        columns.push_back({"R" + std::to_string(k + 1) + "_" + unit, table.radius_mm.data() + k,
                           static_cast<std::size_t>(table.armCount), radiusScale});
    // Only the curves the table has: a missing curve is never written as zeros.
    const std::pair<const char*, const std::vector<double>*> optional[] = {
        {"P1AZ_deg", &table.p1az_deg},
        {"DEVI_deg", &table.devi_deg},
        {"HAZI_deg", &table.hazi_deg},
        {"RB_deg", &table.rb_deg}};
    for (const auto& [name, curve] : optional)
        if (curve->size() == rows && rows > 0) columns.push_back({name, curve->data(), 1, 1.0});
    if (table.bitSize_mm.size() == rows && rows > 0)
        columns.push_back({"BS_" + unit, table.bitSize_mm.data(), 1, radiusScale});
    for (const ExtraCurve& e : table.extraCurves)
        if (e.values.size() == rows && rows > 0)
            columns.push_back({e.unit.empty() ? e.mnemonic : e.mnemonic + "[" + e.unit + "]",
                               e.values.data(), 1, 1.0});

    std::string line;
    for (const Column& c : columns) {
        if (!line.empty()) line.push_back(' ');
        line += c.name;
    }
    line.push_back('\n');
    out.write(line.data(), static_cast<std::streamsize>(line.size()));
    for (std::size_t row = 0; row < rows; ++row) {
        line.clear();
        for (std::size_t c = 0; c < columns.size(); ++c) {
            if (c) line.push_back(' ');
            const Column& column = columns[c];
            put(line, column.values[row * column.stride] * column.scale);
        }
        line.push_back('\n');
        out.write(line.data(), static_cast<std::streamsize>(line.size()));
    }
}

void writeColumnTextFile(const std::string& path, const SectionTable& table,
                         LengthUnit radiusUnit) {
    AtomicOutput file(path);
    writeColumnText(file.stream(), table, radiusUnit);
    file.commit();
}

}  // namespace caliper3d::io
