#include "reconstruction/analysis/section_results.h"

#include "io/section_table.h"

namespace caliper3d::reconstruction {

SectionResults::SectionResults(std::shared_ptr<const std::vector<PathPoint>> path,
                               bool azimuthKnown)
    : m_path(std::move(path)), m_measures(m_path->size()), m_azimuthKnown(azimuthKnown) {}

SectionResult SectionResults::operator[](std::size_t i) const {
    const PathPoint& p = (*m_path)[i];
    const SectionMeasure& m = m_measures[i];
    SectionResult r;
    r.md_m = p.md;
    r.tvd_m = p.tvd;
    r.north_m = p.north;
    r.east_m = p.east;
    r.inc_deg = p.inc_deg;
    r.azi_deg = p.azi_deg;
    if (!m_azimuthKnown) {
        // No data, not north: the azimuth, and the departure wherever the path above has
        // leaned at all, its TVD short of its MD (docs/conventions.md). The path is drawn
        // without a departure, so north and east are 0 there only as drawn.
        r.azi_deg = io::kNaN;
        if (p.md - p.tvd > 1e-9) r.north_m = r.east_m = io::kNaN;
    }
    r.dls_degPer30m = p.dls_degPer30m;
    r.bit_mm = m.bit_mm;
    r.area_mm2 = m.area_mm2;
    r.equivalentDiameter_mm = m.equivalentDiameter_mm;
    r.dmin_mm = m.dmin_mm;
    r.dmax_mm = m.dmax_mm;
    r.ellipticity = m.ellipticity;
    r.majorAzimuth_deg = m.majorAzimuth_deg;
    r.majorFromHighSide_deg = m.majorFromHighSide_deg;
    r.centreOffset_mm = m.centreOffset_mm;
    r.centreOffsetAzimuth_deg = m.centreOffsetAzimuth_deg;
    r.repairedArms = m.repairedArms;
    r.cls = m.cls;
    return r;
}

}  // namespace caliper3d::reconstruction
