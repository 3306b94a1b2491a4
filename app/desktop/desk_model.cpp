#include "app/desktop/desk_model.h"

#include <algorithm>
#include <cmath>

namespace caliper3d::app {

double smallestBitSize_mm(const io::SectionTable& table) {
    double smallest = NAN;
    for (const double b : table.bitSize_mm)
        if (std::isfinite(b) && !(b >= smallest)) smallest = b;
    return smallest;
}

const DeskWell* DeskModel::current() const {
    return m_well >= 0 && m_well < wellCount() ? &m_wells[static_cast<std::size_t>(m_well)]
                                               : nullptr;
}

int DeskModel::addWell(DeskWell well) {
    m_wells.push_back(std::move(well));
    const int index = wellCount() - 1;
    emit wellsChanged();
    openOnFirstWell(index);
    return index;
}

void DeskModel::updateWell(int i, DeskWell well) {
    m_wells.at(static_cast<std::size_t>(i)) = std::move(well);
    const auto& held = m_wells[static_cast<std::size_t>(i)].geometry;
    // The current well held by other rows (read whole again, or restyled) keeps its depth.
    if (i == m_well && held && std::isfinite(m_depth_m)) m_row = nearestRow(*held, m_depth_m);
    emit wellChanged(i);
    openOnFirstWell(i);
}

void DeskModel::openOnFirstWell(int i) {
    const auto& geometry = m_wells[static_cast<std::size_t>(i)].geometry;
    if (!geometry || m_chosen || (m_well >= 0 && m_well <= i)) return;
    moveTo(i, firstMeasuredRow(*geometry));
}

void DeskModel::setRunOf(int i, int mainId) {
    m_wells.at(static_cast<std::size_t>(i)).runOf = mainId;
    emit wellsChanged();
}

std::vector<int> DeskModel::otherRuns(int i) const {
    std::vector<int> out;
    const int group = well(i).runOf;
    if (group < 0) return out;
    const int main = mainRun(i);
    if (main != i) out.push_back(main);
    for (int j = 0; j < wellCount(); ++j)
        if (j != i && j != main && well(j).runOf == group) out.push_back(j);
    return out;
}

int DeskModel::mainRun(int i) const {
    const int group = well(i).runOf;
    if (group < 0) return i;
    const int main = indexOf(group);
    return main >= 0 ? main : i;
}

double DeskModel::matchedDepth_m(int from, int to, double md_m) const {
    if (from == to) return md_m;
    if (from < 0 || to < 0 || from >= wellCount() || to >= wellCount()) return io::kNaN;
    const DeskWell& a = well(from);
    const DeskWell& b = well(to);
    if (a.runOf < 0 || a.runOf != b.runOf) return io::kNaN;
    const int main = mainRun(from);
    // Into the main run's depths, then out to the other's.
    double mainMd_m = md_m;
    if (from != main) {
        if (!a.mapping) return io::kNaN;
        mainMd_m = a.mapping->toRun1(md_m);
    }
    if (to == main) return mainMd_m;
    if (!b.mapping) return io::kNaN;
    return b.mapping->toRun2(mainMd_m);
}

int DeskModel::indexOf(int id) const {
    for (std::size_t i = 0; i < m_wells.size(); ++i)
        if (m_wells[i].id == id) return static_cast<int>(i);
    return -1;
}

void DeskModel::removeWell(int i) {
    m_wells.erase(m_wells.begin() + i);
    const bool wasCurrent = m_well == i;
    if (m_well > i) --m_well;
    if (wasCurrent) {
        m_chosen = false;
        m_well = -1;
        m_row = 0;
        m_depth_m = io::kNaN;
        m_azimuth_deg = io::kNaN;
    }
    emit wellsChanged();
    if (!wasCurrent) return;
    emit currentChanged(m_well, m_depth_m);
    for (int w = 0; w < wellCount() && m_well < 0; ++w) openOnFirstWell(w);
}

void DeskModel::clearWells() {
    m_wells.clear();
    m_chosen = false;
    m_well = -1;
    m_row = 0;
    m_depth_m = io::kNaN;
    m_azimuth_deg = io::kNaN;
    emit wellsChanged();
    emit currentChanged(m_well, m_depth_m);
}

void DeskModel::setVisible(int i, bool visible) {
    DeskWell& w = m_wells.at(static_cast<std::size_t>(i));
    if (w.visible == visible) return;
    w.visible = visible;
    emit wellChanged(i);
}

std::size_t DeskModel::nearestRow(const reconstruction::WellGeometry& geometry, double md_m) {
    const std::vector<double>& depth = geometry.table().depth_m;
    if (depth.empty() || !std::isfinite(md_m)) return 0;
    const auto above = std::lower_bound(depth.begin(), depth.end(), md_m);
    if (above == depth.begin()) return 0;
    if (above == depth.end()) return depth.size() - 1;
    const auto below = above - 1;
    return static_cast<std::size_t>((md_m - *below <= *above - md_m ? below : above) -
                                    depth.begin());
}

std::size_t DeskModel::firstMeasuredRow(const reconstruction::WellGeometry& geometry) {
    const std::size_t rows = geometry.table().rowCount();
    for (std::size_t row = 0; row < rows; ++row)
        if (geometry.measured(row)) return row;
    return 0;
}

void DeskModel::setCurrent(int well, double md_m) {
    if (well < 0 || well >= wellCount()) return;
    const DeskWell& w = m_wells[static_cast<std::size_t>(well)];
    if (!w.geometry || w.geometry->table().rowCount() == 0) return;
    setCurrentRow(well, nearestRow(*w.geometry, md_m));
}

void DeskModel::setCurrentRow(int well, std::size_t row) {
    if (well < 0 || well >= wellCount()) return;
    const auto& geometry = m_wells[static_cast<std::size_t>(well)].geometry;
    if (!geometry || row >= geometry->table().rowCount()) return;
    m_chosen = true;
    moveTo(well, row);
}

void DeskModel::moveTo(int well, std::size_t row) {
    const DeskWell& w = m_wells[static_cast<std::size_t>(well)];
    if (!w.geometry || row >= w.geometry->table().rowCount()) return;
    if (well == m_well && row == m_row && std::isfinite(m_depth_m)) return;
    m_well = well;
    m_row = row;
    m_depth_m = w.geometry->table().depth_m[row];
    emit currentChanged(m_well, m_depth_m);
}

void DeskModel::setCurrentAzimuth(double azimuth_deg) {
    const double a = std::isfinite(azimuth_deg)
                         ? std::fmod(std::fmod(azimuth_deg, 360.0) + 360.0, 360.0)
                         : io::kNaN;
    if (a == m_azimuth_deg || (std::isnan(a) && std::isnan(m_azimuth_deg))) return;
    m_azimuth_deg = a;
    emit azimuthChanged(m_azimuth_deg);
}

}  // namespace caliper3d::app
