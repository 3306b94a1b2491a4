#include "reconstruction/well_analysis.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/arm_geometry.h"
#include "reconstruction/section_analysis.h"

namespace caliper3d::reconstruction {

namespace {

void analyseRows(const WellGeometry& g, const SectionAnalyzer& analyzer, double bitOverride_mm,
                 std::size_t first, std::size_t last, std::vector<SectionResult>& out) {
    const io::SectionTable& t = g.table();
    std::vector<double> pads(static_cast<std::size_t>(t.armCount));
    std::vector<double> sampled(static_cast<std::size_t>(analyzer.samples()));
    for (std::size_t row = first; row < last; ++row) {
        SectionResult& r = out[row];
        const PathPoint& p = g.path()[row];
        r.md_m = p.md;
        r.tvd_m = p.tvd;
        r.north_m = p.north;
        r.east_m = p.east;
        r.inc_deg = p.inc_deg;
        r.azi_deg = p.azi_deg;
        r.dls_degPer30m = p.dls_degPer30m;
        r.bit_mm = std::isfinite(bitOverride_mm) ? bitOverride_mm : 2.0 * g.bitRadius_mm(row);
        r.repairedArms = g.repairRadii(row, pads.data());
        const SectionShape s = analyzer.analyse(pads.data(), sampled.data());
        r.area_mm2 = s.area_mm2;
        r.equivalentDiameter_mm = s.equivalentDiameter_mm;
        r.dmin_mm = s.dmin_mm;
        r.dmax_mm = s.dmax_mm;
        r.ellipticity = s.ellipticity;
        r.centreOffset_mm = s.centreOffset_mm;
        const SectionFrame& f = g.frame(row);
        const double az = inPlaneAzimuth_deg(f, s.majorAngle_deg);
        r.majorAzimuth_deg = std::isfinite(az) ? std::fmod(az, 180.0) : az;
        r.majorFromHighSide_deg = std::fmod(angleFromHighSide_deg(f, p.inc_deg, p.azi_deg, s.majorAngle_deg), 180.0);
        r.centreOffsetAzimuth_deg =
            s.centreOffset_mm > 0.0
                ? inPlaneAzimuth_deg(f, glm::degrees(std::atan2(s.centroidV_mm, s.centroidU_mm)))
                : 0.0;
    }
}

}  // namespace

WellAnalysis analyseWell(const WellGeometry& g, const AnalysisOptions& options) {
    const io::SectionTable& t = g.table();
    const std::size_t rows = t.rowCount();
    WellAnalysis a;
    a.sections.resize(rows);
    const SectionAnalyzer analyzer(t.armCount, g.options().splinePoints);

    const int threads = std::max(1, options.threads);
    if (threads == 1 || rows < 4096) {
        analyseRows(g, analyzer, options.bitSize_mm, 0, rows, a.sections);
    } else {
        std::vector<std::thread> workers;
        const std::size_t chunk = (rows + static_cast<std::size_t>(threads) - 1) / static_cast<std::size_t>(threads);
        for (int w = 0; w < threads; ++w) {
            const std::size_t first = std::min(rows, static_cast<std::size_t>(w) * chunk);
            const std::size_t last = std::min(rows, first + chunk);
            workers.emplace_back([&, first, last] { analyseRows(g, analyzer, options.bitSize_mm, first, last, a.sections); });
        }
        for (auto& w : workers) w.join();
    }

    // No bit size at all: the median equivalent diameter stands in as gauge.
    bool anyBit = false;
    for (const SectionResult& r : a.sections) anyBit = anyBit || std::isfinite(r.bit_mm);
    if (!anyBit && rows > 0) {
        std::vector<double> d(rows);
        for (std::size_t i = 0; i < rows; ++i) d[i] = a.sections[i].equivalentDiameter_mm;
        std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(rows / 2), d.end());
        for (SectionResult& r : a.sections) r.bit_mm = d[rows / 2];
        a.bitSizeFromSections = true;
    }

    std::vector<ClassifierInput> in(rows);
    std::vector<double> md(rows), azimuth(rows), dmax(rows), dmin(rows), area(rows), bit(rows);
    for (std::size_t i = 0; i < rows; ++i) {
        const SectionResult& r = a.sections[i];
        const double p1az = i < t.p1az_deg.size() ? t.p1az_deg[i] : io::kNaN;
        const double rb = i < t.rb_deg.size() ? t.rb_deg[i] : io::kNaN;
        in[i] = {r.md_m, r.dmin_mm, r.dmax_mm, r.bit_mm, r.inc_deg, r.majorFromHighSide_deg,
                 std::isfinite(p1az) ? p1az : rb};
        md[i] = r.md_m;
        azimuth[i] = r.majorAzimuth_deg;
        dmax[i] = r.dmax_mm;
        dmin[i] = r.dmin_mm;
        area[i] = r.area_mm2;
        bit[i] = r.bit_mm;
        if (r.repairedArms > 0) {
            ++a.repairedSections;
            a.repairedArms += static_cast<std::size_t>(r.repairedArms);
        }
        if (g.orientation(i) == WellGeometry::Orientation::Unoriented) ++a.unorientedSections;
    }
    const std::vector<BoreholeClass> classes = classifySections(in, options.rules);
    for (std::size_t i = 0; i < rows; ++i) a.sections[i].cls = classes[i];
    a.zones = detectZones(md, classes, azimuth, dmax, dmin);
    a.breakouts = summariseBreakouts(a.zones, options.wsm);
    a.volume = holeVolume(md, area, bit, options.volume);
    a.padAzimuthOffset = padAzimuthOffset(t);
    return a;
}

}  // namespace caliper3d::reconstruction
