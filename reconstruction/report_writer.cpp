#include "reconstruction/report_writer.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace caliper3d::reconstruction {

namespace {

// printf-style numbers are locale dependent only through LC_NUMERIC, which
// the program never sets, so "%.*f" writes a decimal point.
void number(std::string& line, double v, int decimals) {
    if (!std::isfinite(v)) return;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v == 0.0 ? 0.0 : v);  // no "-0.000"
    line += buf;
}

std::vector<std::size_t> reportedRows(const std::vector<SectionResult>& s, double step) {
    std::vector<std::size_t> rows;
    if (s.empty()) return rows;
    if (!(step > 0.0)) {
        rows.resize(s.size());
        for (std::size_t i = 0; i < s.size(); ++i) rows[i] = i;
        return rows;
    }
    const double top = s.front().md_m;
    std::size_t j = 0;
    for (std::size_t k = 0;; ++k) {
        const double target = top + step * static_cast<double>(k);
        if (target > s.back().md_m + 1e-9) break;
        while (j + 1 < s.size() && std::abs(s[j + 1].md_m - target) <= std::abs(s[j].md_m - target)) ++j;
        if (rows.empty() || rows.back() != j) rows.push_back(j);
    }
    return rows;
}

}  // namespace

void writeSectionReport(std::ostream& out, const WellAnalysis& a, const ReportOptions& options) {
    out << "md_m,tvd_m,north_m,east_m,inc_deg,azi_deg,dmin_mm,dmax_mm,ellipticity,major_azimuth_deg,"
           "area_mm2,centre_offset_mm,class,dls_deg_per_30m,bit_mm,equivalent_diameter_mm,"
           "major_from_high_side_deg,centre_offset_azimuth_deg,repaired_arms\n";
    std::string line;
    for (std::size_t i : reportedRows(a.sections, options.step_m)) {
        const SectionResult& r = a.sections[i];
        line.clear();
        const double fields[] = {r.md_m, r.tvd_m, r.north_m, r.east_m, r.inc_deg, r.azi_deg,
                                 r.dmin_mm, r.dmax_mm, r.ellipticity, r.majorAzimuth_deg, r.area_mm2,
                                 r.centreOffset_mm};
        const int decimals[] = {4, 4, 4, 4, 3, 3, 2, 2, 4, 2, 1, 2};
        for (int k = 0; k < 12; ++k) {
            number(line, fields[k], decimals[k]);
            line += ',';
        }
        line += className(r.cls);
        const double extra[] = {r.dls_degPer30m, r.bit_mm, r.equivalentDiameter_mm, r.majorFromHighSide_deg,
                                r.centreOffsetAzimuth_deg};
        const int extraDecimals[] = {3, 2, 2, 2, 2};
        for (int k = 0; k < 5; ++k) {
            line += ',';
            number(line, extra[k], extraDecimals[k]);
        }
        line += ',';
        line += std::to_string(r.repairedArms);
        line += '\n';
        out << line;
    }
}

void writeZoneReport(std::ostream& out, const WellAnalysis& a) {
    out << "kind,top_m,bottom_m,length_m,mean_azimuth_deg,circular_sd_deg,mean_dmax_mm,mean_dmin_mm,sections\n";
    std::string line;
    for (const Zone& z : a.zones) {
        line.assign(className(z.kind));
        const double fields[] = {z.top_m, z.bottom_m, z.length_m, z.meanAzimuth_deg, z.circularSd_deg,
                                 z.meanDmax_mm, z.meanDmin_mm};
        const int decimals[] = {4, 4, 4, 2, 2, 2, 2};
        for (int k = 0; k < 7; ++k) {
            line += ',';
            number(line, fields[k], decimals[k]);
        }
        line += ',' + std::to_string(z.lastSection - z.firstSection + 1) + '\n';
        out << line;
    }
}

std::string formatAnalysisSummary(const WellAnalysis& a) {
    char buf[512];
    std::string s;
    const BreakoutSummary& b = a.breakouts;
    std::snprintf(buf, sizeof buf,
                  "breakouts: %d zones, %.2f m, mean azimuth %.1f deg, circular SD %.1f deg, "
                  "SHmax %.1f deg, WSM quality %c\n",
                  b.zoneCount, b.combinedLength_m, b.meanAzimuth_deg, b.circularSd_deg, b.shmaxAzimuth_deg, b.quality);
    s += buf;
    const HoleVolume& v = a.volume;
    std::snprintf(buf, sizeof buf,
                  "volume %.2f-%.2f m: hole %.4f m3 (bit size %.4f m3), annulus %.4f m3 (bit size %.4f m3), "
                  "cement with excess %.4f m3 (bit size %.4f m3)\n",
                  v.top_m, v.bottom_m, v.hole_m3, v.gaugeHole_m3, v.annulus_m3, v.gaugeAnnulus_m3, v.cement_m3,
                  v.gaugeCement_m3);
    s += buf;
    if (a.padAzimuthOffset.samples > 0) {
        std::snprintf(buf, sizeof buf, "P1AZ - (HAZI+RB): mean %.2f deg, circular SD %.2f deg over %zu sections\n",
                      a.padAzimuthOffset.mean_deg, a.padAzimuthOffset.sd_deg, a.padAzimuthOffset.samples);
        s += buf;
    }
    if (a.repairedSections > 0) {
        std::snprintf(buf, sizeof buf, "warning: %zu arms interpolated on %zu sections (missing, closed or beyond reach)\n",
                      a.repairedArms, a.repairedSections);
        s += buf;
    }
    if (a.unorientedSections > 0) {
        std::snprintf(buf, sizeof buf, "warning: %zu sections without P1AZ or RB: arm 1 assumed north\n",
                      a.unorientedSections);
        s += buf;
    }
    if (a.bitSizeFromSections) s += "warning: no bit size given: the median equivalent diameter is used as gauge\n";
    return s;
}

void writeSectionReport(const std::string& path, const WellAnalysis& a, const ReportOptions& options) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    writeSectionReport(out, a, options);
    if (!out) throw std::runtime_error(path + ": write failed");
}

void writeZoneReport(const std::string& path, const WellAnalysis& a) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    writeZoneReport(out, a);
    if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace caliper3d::reconstruction
