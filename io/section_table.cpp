#include "io/section_table.h"

#include <stdexcept>

namespace caliper3d::io {

namespace {
void appendCurve(std::vector<double>& to, const std::vector<double>& from) {
    to.insert(to.end(), from.begin(), from.end());
}
}  // namespace

void SectionTable::append(const SectionTable& other) {
    const bool empty = rowCount() == 0;
    if (empty && armCount == 0) armCount = other.armCount;
    if (other.armCount != armCount)
        throw std::invalid_argument("SectionTable::append: arm counts differ");
    appendCurve(depth_m, other.depth_m);
    appendCurve(radius_mm, other.radius_mm);
    appendCurve(p1az_deg, other.p1az_deg);
    appendCurve(devi_deg, other.devi_deg);
    appendCurve(hazi_deg, other.hazi_deg);
    appendCurve(rb_deg, other.rb_deg);
    appendCurve(bitSize_mm, other.bitSize_mm);
    if (empty && extraCurves.empty()) extraCurves = other.extraCurves;
    else if (extraCurves.size() == other.extraCurves.size())
        for (std::size_t i = 0; i < extraCurves.size(); ++i) appendCurve(extraCurves[i].values, other.extraCurves[i].values);
    else throw std::invalid_argument("SectionTable::append: extra curves differ");
}

void SectionTable::reserve(std::size_t rows) {
    depth_m.reserve(rows);
    radius_mm.reserve(rows * static_cast<std::size_t>(armCount));
    p1az_deg.reserve(rows);
    devi_deg.reserve(rows);
    hazi_deg.reserve(rows);
}

}  // namespace caliper3d::io
