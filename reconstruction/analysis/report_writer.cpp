#include "reconstruction/analysis/report_writer.h"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/atomic_output.h"
#include "io/casing_program.h"
#include "io/las_writer.h"

namespace caliper3d::reconstruction {

namespace {

// Every number goes through std::to_chars, which writes a decimal point whatever the locale:
// printf follows LC_NUMERIC, and a Qt application sets it from the environment on Unix (a
// German desktop would get "215,90" in a comma-separated file). The digits are printf's "%.*f".
std::string fixed(double v, int decimals) {
    char buf[400];  // the longest double in fixed notation, 309 digits, plus decimals
    return std::string(
        buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals).ptr);
}

// A field of the CSV: empty when undefined, never "-0.000".
void number(std::string& line, double v, int decimals) {
    if (!std::isfinite(v)) return;
    line += fixed(v == 0.0 ? 0.0 : v, decimals);
}

// printf's "%+.1f".
std::string signedFixed(double v, int decimals) {
    return (std::signbit(v) ? "" : "+") + fixed(v, decimals);
}

std::string breakoutSummary(const WellAnalysis& a) {
    const BreakoutSummary& b = a.breakouts;
    // "none" would read as a finding: one diameter per section cannot show a breakout.
    if (a.twoPads)
        return "breakouts: not seen by a two-pad tool (one diameter per section), WSM quality E\n";
    if (b.zoneCount == 0) return "breakouts: none, WSM quality E\n";
    return "breakouts: " + std::to_string(b.zoneCount) + " zone" + (b.zoneCount == 1 ? "" : "s") +
           ", " + fixed(b.combinedLength_m, 2) + " m, mean azimuth " + fixed(b.meanAzimuth_deg, 1) +
           " deg, circular SD " + fixed(b.circularSd_deg, 1) + " deg, SHmax " +
           fixed(b.shmaxAzimuth_deg, 1) + " deg, WSM quality " + b.quality + "\n";
}

std::string volumeSummary(const HoleVolume& v) {
    const double excessPercent =
        v.gaugeHole_m3 > 0.0 ? 100.0 * (v.hole_m3 - v.gaugeHole_m3) / v.gaugeHole_m3 : 0.0;
    std::string s = "hole volume " + fixed(v.top_m, 2) + "-" + fixed(v.bottom_m, 2) +
                    " m: " + fixed(v.hole_m3, 4) + " m3 (bit size " + fixed(v.gaugeHole_m3, 4) +
                    " m3, " + signedFixed(excessPercent, 1) + " %)\n";
    if (!v.uncovered.empty()) {
        // The volumes above leave these out: say where, so no one reads them as the whole hole.
        s += "hole volume not covered (no caliper data):";
        for (std::size_t k = 0; k < v.uncovered.size(); ++k)
            s += (k ? ", " : " ") + fixed(v.uncovered[k].first, 2) + "-" +
                 fixed(v.uncovered[k].second, 2) + " m";
        s += " (" + fixed(v.uncovered_m, 2) + " m in all; no volume figure includes it)\n";
    }
    if (!v.cased.empty()) {
        s += "hole volume of open hole only; cased hole left out:";
        for (std::size_t k = 0; k < v.cased.size(); ++k)
            s += (k ? ", " : " ") + fixed(v.cased[k].first, 2) + "-" + fixed(v.cased[k].second, 2) +
                 " m";
        s += " (" + fixed(v.cased_m, 2) + " m in all)\n";
    }
    if (v.casingOd_mm > 0.0 || v.excess > 0.0)
        s += "annulus outside " + fixed(v.casingOd_mm, 1) + " mm casing " + fixed(v.annulus_m3, 4) +
             " m3 (bit size " + fixed(v.gaugeAnnulus_m3, 4) + " m3), cement with " +
             fixed(100.0 * v.excess, 0) + " % excess " + fixed(v.cement_m3, 4) + " m3 (bit size " +
             fixed(v.gaugeCement_m3, 4) + " m3)\n";
    return s;
}

// Each casing string and the tool's reading inside it against its nominal inner diameter.
std::string casingSummary(const WellAnalysis& a) {
    std::string s;
    for (const CasingCheck& c : a.casing) {
        s += "casing " + io::describeCasing(c.casing) + "\n";
        s += "  reading in casing: ";
        if (a.sections.empty() || c.casing.bottom_m < a.sections[0].md_m) {
            s += "none (the log starts below its shoe)\n";
            continue;
        }
        if (c.sections == 0) {
            s += "none (no measured section inside it)\n";
            continue;
        }
        s += "median " + fixed(c.medianDiameter_mm, 1) + " mm over " + fixed(c.top_m, 2) + "-" +
             fixed(c.bottom_m, 2) + " m (" + std::to_string(c.sections) + " sections)";
        if (std::isfinite(c.offset_mm))
            s += ", nominal ID " + fixed(c.casing.innerDiameter_mm, 1) + " mm, offset " +
                 signedFixed(c.offset_mm, 1) + " mm\n";
        else
            s += "; nominal ID unknown: no calibration check\n";
    }
    return s;
}

}  // namespace

std::vector<std::size_t> reportedSections(const WellAnalysis& a, const ReportOptions& options) {
    const SectionResults& s = a.sections;
    const double step = options.step_m;
    std::vector<std::size_t> rows;
    if (s.empty()) return rows;
    if (!(step > 0.0)) {
        rows.resize(s.size());
        for (std::size_t i = 0; i < s.size(); ++i) rows[i] = i;
        return rows;
    }
    const double top = s.md_m(0), bottom = s.md_m(s.size() - 1);
    std::size_t j = 0;
    for (std::size_t k = 0;; ++k) {
        const double target = top + step * static_cast<double>(k);
        if (target > bottom + 1e-9) break;
        while (j + 1 < s.size() && std::abs(s.md_m(j + 1) - target) <= std::abs(s.md_m(j) - target))
            ++j;
        if (rows.empty() || rows.back() != j) rows.push_back(j);
    }
    return rows;
}

namespace {

constexpr const char* kSectionColumns =
    "md_m,tvd_m,north_m,east_m,inc_deg,azi_deg,dmin_mm,dmax_mm,ellipticity,major_azimuth_deg,"
    "area_mm2,centre_offset_mm,class,dls_deg_per_30m,bit_mm,equivalent_diameter_mm,"
    "major_from_high_side_deg,centre_offset_azimuth_deg,repaired_arms";
constexpr const char* kWellheadColumns = ",easting_m,northing_m,tvdss_m";

// One section's CSV fields, comma separated, no line end.
void appendSectionRow(std::string& line, const SectionResult& r, const ReportOptions& options) {
    const double fields[] = {
        r.md_m,    r.tvd_m,   r.north_m,     r.east_m,           r.inc_deg,  r.azi_deg,
        r.dmin_mm, r.dmax_mm, r.ellipticity, r.majorAzimuth_deg, r.area_mm2, r.centreOffset_mm};
    const int decimals[] = {4, 4, 4, 4, 3, 3, 2, 2, 4, 2, 1, 2};
    for (int k = 0; k < 12; ++k) {
        number(line, fields[k], decimals[k]);
        line += ',';
    }
    line += className(r.cls);
    const double extra[] = {r.dls_degPer30m, r.bit_mm, r.equivalentDiameter_mm,
                            r.majorFromHighSide_deg, r.centreOffsetAzimuth_deg};
    const int extraDecimals[] = {3, 2, 2, 2, 2};
    for (int k = 0; k < 5; ++k) {
        line += ',';
        number(line, extra[k], extraDecimals[k]);
    }
    line += ',';
    if (r.cls != BoreholeClass::NoData) line += std::to_string(r.repairedArms);
    if (const auto& w = options.wellhead) {
        const double map[] = {w->easting_m + r.east_m, w->northing_m + r.north_m,
                              r.tvd_m - w->elevation_m};
        for (double v : map) {
            line += ',';
            number(line, v, 4);
        }
    }
}

std::vector<std::string> splitFields(const std::string& line) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
        out.push_back(line.substr(start, comma - start));
    out.push_back(line.substr(start));
    return out;
}

}  // namespace

void writeSectionReport(std::ostream& out, const WellAnalysis& a, const ReportOptions& options) {
    out << kSectionColumns << (options.wellhead ? kWellheadColumns : "") << '\n';
    std::string line;
    for (std::size_t i : reportedSections(a, options)) {
        line.clear();
        appendSectionRow(line, a.sections[i], options);
        line += '\n';
        out << line;
    }
}

std::vector<std::pair<std::string, std::string>> sectionReportFields(const SectionResult& r,
                                                                     const ReportOptions& options) {
    std::string header = kSectionColumns;
    if (options.wellhead) header += kWellheadColumns;
    std::string line;
    appendSectionRow(line, r, options);
    const std::vector<std::string> names = splitFields(header), values = splitFields(line);
    std::vector<std::pair<std::string, std::string>> out;
    out.reserve(names.size());
    for (std::size_t k = 0; k < names.size() && k < values.size(); ++k)
        out.emplace_back(names[k], values[k]);
    return out;
}

void writeZoneReport(std::ostream& out, const WellAnalysis& a) {
    out << "kind,top_m,bottom_m,length_m,mean_azimuth_deg,circular_sd_deg,mean_dmax_mm,mean_dmin_"
           "mm,sections\n";
    std::string line;
    for (const Zone& z : a.zones) {
        line.assign(className(z.kind));
        const double fields[] = {z.top_m,          z.bottom_m,    z.length_m,   z.meanAzimuth_deg,
                                 z.circularSd_deg, z.meanDmax_mm, z.meanDmin_mm};
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
    // Which north every azimuth below is from (docs/conventions.md, "North").
    std::string s = a.north.empty() ? std::string() : "north: " + a.north + "\n";
    s += breakoutSummary(a) + volumeSummary(a.volume);
    for (const NoDataInterval& gap : a.armsNotOpen)
        s += "arms not open over " + describeNoDataInterval(gap) + ": class no_data\n";
    s += casingSummary(a);
    if (a.padAzimuthOffset.samples > 0)
        s += "P1AZ - (HAZI+RB): mean " + fixed(a.padAzimuthOffset.mean_deg, 2) +
             " deg, circular SD " + fixed(a.padAzimuthOffset.sd_deg, 2) + " deg over " +
             std::to_string(a.padAzimuthOffset.samples) + " sections\n";
    return s;
}

void writeSectionReport(const std::string& path, const WellAnalysis& a,
                        const ReportOptions& options) {
    io::AtomicOutput file(path);
    writeSectionReport(file.stream(), a, options);
    file.commit();
}

void writeAnalysisLas(std::ostream& out, const WellAnalysis& a, const ReportOptions& options,
                      const std::string& wellName) {
    const std::vector<std::size_t> rows = reportedSections(a, options);
    struct Curve {
        const char* mnemonic;
        const char* unit;
        const char* description;
        int decimals;  // as the CSV report prints them
        double (*value)(const SectionResult&);
    };
    static const Curve kCurves[] = {
        {"DEPT", "M", "measured depth", 4, [](const SectionResult& r) { return r.md_m; }},
        {"TVD", "M", "true vertical depth below the wellhead", 4,
         [](const SectionResult& r) { return r.tvd_m; }},
        {"NORTH", "M", "north of the wellhead", 4,
         [](const SectionResult& r) { return r.north_m; }},
        {"EAST", "M", "east of the wellhead", 4, [](const SectionResult& r) { return r.east_m; }},
        {"INC", "DEG", "hole inclination", 3, [](const SectionResult& r) { return r.inc_deg; }},
        {"AZI", "DEG", "hole azimuth", 3, [](const SectionResult& r) { return r.azi_deg; }},
        {"DLS", "DEG/30M", "dogleg severity", 3,
         [](const SectionResult& r) { return r.dls_degPer30m; }},
        {"BS", "MM", "bit size used as gauge", 2, [](const SectionResult& r) { return r.bit_mm; }},
        {"DMIN", "MM", "minor axis of the fitted ellipse", 2,
         [](const SectionResult& r) { return r.dmin_mm; }},
        {"DMAX", "MM", "major axis of the fitted ellipse", 2,
         [](const SectionResult& r) { return r.dmax_mm; }},
        {"ELLIP", "", "ellipticity dmax/dmin", 4,
         [](const SectionResult& r) { return r.ellipticity; }},
        {"MAJAZ", "DEG", "azimuth of the major axis, 0-180", 2,
         [](const SectionResult& r) { return r.majorAzimuth_deg; }},
        {"MAJHS", "DEG", "major axis clockwise from the high side, 0-180", 2,
         [](const SectionResult& r) { return r.majorFromHighSide_deg; }},
        {"AREA", "MM2", "section area", 1, [](const SectionResult& r) { return r.area_mm2; }},
        {"DEQ", "MM", "diameter of the circle of equal area", 2,
         [](const SectionResult& r) { return r.equivalentDiameter_mm; }},
        {"CENOFF", "MM", "tool axis to hole centre", 2,
         [](const SectionResult& r) { return r.centreOffset_mm; }},
        {"CENAZ", "DEG", "azimuth from tool axis to hole centre", 2,
         [](const SectionResult& r) { return r.centreOffsetAzimuth_deg; }},
        {"CLASS", "",
         "0 in_gauge 1 undergauge 2 washout 3 breakout 4 keyseat 5 cased; null no_data", 0,
         [](const SectionResult& r) {
             return r.cls == BoreholeClass::NoData ? io::kNaN : static_cast<double>(r.cls);
         }},
        {"REPAIRED", "", "arms interpolated on this section", 0,
         [](const SectionResult& r) {
             return r.cls == BoreholeClass::NoData ? io::kNaN : static_cast<double>(r.repairedArms);
         }},
    };
    // The report's rows may be a subset (--step): gather each curve once.
    std::vector<std::vector<double>> values;
    std::vector<io::LasColumn> columns;
    values.reserve(std::size(kCurves));
    for (const Curve& c : kCurves) {
        std::vector<double>& v = values.emplace_back();
        v.reserve(rows.size());
        for (std::size_t i : rows) v.push_back(c.value(a.sections[i]));
        columns.push_back({c.mnemonic, c.unit, c.description, v.data(), 1, c.decimals});
    }
    io::LasWriteOptions las;
    las.wellName = wellName;
    std::string other = "Computed by caliper3d from the caliper log. CLASS codes:";
    for (int k = 0; k <= static_cast<int>(BoreholeClass::Cased); ++k)
        other +=
            " " + std::to_string(k) + " " + std::string(className(static_cast<BoreholeClass>(k)));
    other += "; a section without caliper data (no_data) has CLASS and every measured curve null.";
    las.other = other + "\n" + formatAnalysisSummary(a);
    io::writeLasColumns(out, rows.size(), columns, las);
}

void writeAnalysisLas(const std::string& path, const WellAnalysis& a, const ReportOptions& options,
                      const std::string& wellName) {
    io::AtomicOutput file(path);
    writeAnalysisLas(file.stream(), a, options, wellName);
    file.commit();
}

void writeZoneReport(const std::string& path, const WellAnalysis& a) {
    io::AtomicOutput file(path);
    writeZoneReport(file.stream(), a);
    file.commit();
}

}  // namespace caliper3d::reconstruction
