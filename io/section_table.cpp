#include "io/section_table.h"

#include <algorithm>
#include <stdexcept>

namespace caliper3d::io {

namespace {
void appendCurve(std::vector<double>& to, const std::vector<double>& from) {
    to.insert(to.end(), from.begin(), from.end());
}

void appendRange(const std::vector<double>& from, std::vector<double>& to, std::size_t first,
                 std::size_t last, std::size_t width) {
    if (from.empty()) return;
    to.insert(to.end(), from.begin() + static_cast<std::ptrdiff_t>(first * width),
              from.begin() + static_cast<std::ptrdiff_t>(last * width));
}

void keep(std::vector<double>& v, const std::vector<std::size_t>& rows, std::size_t width) {
    if (v.empty()) return;
    std::vector<double> out;
    out.reserve(rows.size() * width);
    for (std::size_t r : rows)
        out.insert(out.end(), v.begin() + static_cast<std::ptrdiff_t>(r * width),
                   v.begin() + static_cast<std::ptrdiff_t>((r + 1) * width));
    v.swap(out);
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
    if (empty && extraCurves.empty())
        extraCurves = other.extraCurves;
    else if (extraCurves.size() == other.extraCurves.size())
        for (std::size_t i = 0; i < extraCurves.size(); ++i)
            appendCurve(extraCurves[i].values, other.extraCurves[i].values);
    else
        throw std::invalid_argument("SectionTable::append: extra curves differ");
}

void SectionTable::appendRows(const SectionTable& other, std::size_t first, std::size_t last) {
    if (first >= last) return;
    const std::size_t arms = static_cast<std::size_t>(other.armCount);
    appendRange(other.depth_m, depth_m, first, last, 1);
    appendRange(other.radius_mm, radius_mm, first, last, arms);
    appendRange(other.p1az_deg, p1az_deg, first, last, 1);
    appendRange(other.devi_deg, devi_deg, first, last, 1);
    appendRange(other.hazi_deg, hazi_deg, first, last, 1);
    appendRange(other.rb_deg, rb_deg, first, last, 1);
    appendRange(other.bitSize_mm, bitSize_mm, first, last, 1);
    for (std::size_t e = 0; e < other.extraCurves.size(); ++e)
        appendRange(other.extraCurves[e].values, extraCurves[e].values, first, last, 1);
}

SectionTable SectionTable::rows(std::size_t first, std::size_t last) const {
    SectionTable out;
    out.source = source;
    out.wellName = wellName;
    out.fileDepthUnit = fileDepthUnit;
    out.fileCaliperUnit = fileCaliperUnit;
    out.armCount = armCount;
    out.holeAzimuth = holeAzimuth;
    out.north = north;
    out.casing = casing;
    for (const ExtraCurve& e : extraCurves)
        out.extraCurves.push_back({e.mnemonic, e.unit, e.description, {}});
    out.appendRows(*this, first, std::min(last, rowCount()));
    return out;
}

void SectionTable::clearRows() {
    depth_m.clear();
    radius_mm.clear();
    p1az_deg.clear();
    devi_deg.clear();
    hazi_deg.clear();
    rb_deg.clear();
    bitSize_mm.clear();
    for (ExtraCurve& e : extraCurves) e.values.clear();
}

void SectionTable::keepRows(const std::vector<std::size_t>& rows) {
    keep(depth_m, rows, 1);
    keep(radius_mm, rows, static_cast<std::size_t>(armCount));
    keep(p1az_deg, rows, 1);
    keep(devi_deg, rows, 1);
    keep(hazi_deg, rows, 1);
    keep(rb_deg, rows, 1);
    keep(bitSize_mm, rows, 1);
    for (ExtraCurve& c : extraCurves) keep(c.values, rows, 1);
}

void SectionTable::reserve(std::size_t rows) {
    depth_m.reserve(rows);
    radius_mm.reserve(rows * static_cast<std::size_t>(armCount));
    p1az_deg.reserve(rows);
    devi_deg.reserve(rows);
    hazi_deg.reserve(rows);
}

}  // namespace caliper3d::io
