#include "io/column_text_writer.h"

#include <charconv>
#include <fstream>
#include <stdexcept>

namespace caliper3d::io {

namespace {
// Shortest text that reads back to the same double.
void put(std::string& line, double value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    line.append(buffer, result.ptr);
}
double valueOr(const std::vector<double>& curve, std::size_t row) {
    return row < curve.size() ? curve[row] : 0.0;
}
}  // namespace

void writeColumnText(std::ostream& out, const SectionTable& table, LengthUnit radiusUnit) {
    const double radiusScale = 1.0 / toMillimetres(radiusUnit);
    out << "# depth_m";
    for (int k = 1; k <= table.armCount; ++k) out << " R" << k << "_" << unitName(radiusUnit);
    out << " P1AZ_deg DEVI_deg HAZI_deg\n";
    std::string line;
    for (std::size_t row = 0; row < table.rowCount(); ++row) {
        line.clear();
        put(line, table.depth_m[row]);
        const double* r = table.radii(row);
        for (int k = 0; k < table.armCount; ++k) {
            line.push_back(' ');
            put(line, r[k] * radiusScale);
        }
        for (const auto* curve : {&table.p1az_deg, &table.devi_deg, &table.hazi_deg}) {
            line.push_back(' ');
            put(line, valueOr(*curve, row));
        }
        line.push_back('\n');
        out.write(line.data(), static_cast<std::streamsize>(line.size()));
    }
}

void writeColumnTextFile(const std::string& path, const SectionTable& table, LengthUnit radiusUnit) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(path + ": cannot open file for writing");
    writeColumnText(out, table, radiusUnit);
    if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace caliper3d::io
