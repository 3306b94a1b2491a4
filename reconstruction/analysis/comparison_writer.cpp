#include "reconstruction/analysis/comparison_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string_view>
#include <thread>
#include <vector>

#include "io/atomic_output.h"
#include "io/number_format.h"

namespace caliper3d::reconstruction {

namespace {

std::string fixed(double v, int decimals) {
    std::string text;
    io::appendFixed(text, v, decimals);
    return text;
}

std::string signedFixed(double v, int decimals) {
    const std::string text = fixed(v, decimals);
    return text.front() == '-' ? text : "+" + text;
}

void field(std::string& line, double v, int decimals) {
    line += ',';
    if (std::isfinite(v)) io::appendFixed(line, v, decimals);
}

void field(std::string& line, std::string_view text) {
    line += ',';
    line += text;
}

// Axial difference of two directions of [0, 180): (-90, 90].
double axialDifference(double a, double b) {
    double d = std::fmod(b - a, 180.0);
    if (d > 90.0) d -= 180.0;
    if (d <= -90.0) d += 180.0;
    return d;
}

// The notes of a comparison's rows, made once.
struct RowNotes {
    explicit RowNotes(const RunComparison& r) {
        for (int k = 1; k < 7; ++k)
            notCompared[k] =
                "not compared: " + std::string(notComparedText(static_cast<NotCompared>(k)));
        unoriented = r.unoriented1 && r.unoriented2 ? "azimuth unknown: neither run oriented"
                     : r.unoriented1                ? "azimuth unknown: run 1 not oriented"
                     : r.unoriented2                ? "azimuth unknown: run 2 not oriented"
                                                    : "azimuth unknown here";
        skipped = "outline not compared: diameters within " + fixed(r.outlineGate_mm, 2) +
                  " mm and major axis within " + fixed(kOutlineAxisTurn_deg, 0) + " deg";
    }
    std::string_view of(const SectionChange& c) const {
        if (!c.compared()) return notCompared[static_cast<int>(c.notCompared)];
        if (c.oriented) return "";
        if (c.outlineSkipped) return skipped;
        return unoriented;
    }
    std::string notCompared[7], unoriented, skipped;
};

// A row's fields written into a buffer of the row's own (one append a row, not one a field).
class RowText {
public:
    void number(double v, int decimals) {
        *m_end++ = ',';
        if (std::isfinite(v)) m_end = io::writeFixed(m_end, v, decimals);
    }
    void first(double v, int decimals) { m_end = io::writeFixed(m_end, v, decimals); }
    void text(std::string_view t) {
        *m_end++ = ',';
        m_end = std::copy(t.begin(), t.end(), m_end);
    }
    void appendTo(std::string& out) {
        *m_end++ = '\n';
        out.append(m_buffer, static_cast<std::size_t>(m_end - m_buffer));
        m_end = m_buffer;
    }

private:
    // 24 numbers, the class names, the significance and the longest note.
    char m_buffer[24 * (io::kFixedMaxChars + 1) + 512];
    char* m_end = m_buffer;
};

void appendRow(std::string& line, RowText& row, const SectionChange& c, const RowNotes& notes) {
    row.first(c.md1_m, 4);
    row.number(c.md2_m, 4);
    const auto triple = [&row](double a, double b) {
        row.number(a, 2);
        row.number(b, 2);
        row.number(b - a, 2);
    };
    triple(c.deq1_mm, c.deq2_mm);
    triple(c.dmin1_mm, c.dmin2_mm);
    triple(c.dmax1_mm, c.dmax2_mm);
    row.text(className(c.class1));
    row.text(className(c.class2));
    row.number(c.majorAzimuth1_deg, 2);
    row.number(c.majorAzimuth2_deg, 2);
    row.number(axialDifference(c.majorAzimuth1_deg, c.majorAzimuth2_deg), 2);
    row.number(c.area1_mm2, 1);
    row.number(c.area2_mm2, 1);
    row.number(c.area2_mm2 - c.area1_mm2, 1);
    row.number(100.0 * (c.area2_mm2 - c.area1_mm2) / c.area1_mm2, 2);
    row.number(100.0 * (c.deq2_mm - c.deq1_mm) / c.deq1_mm, 2);
    row.number(c.maxGrowth_mm, 2);
    row.number(c.maxGrowthAzimuth_deg, 1);
    row.text(c.compared() ? (c.significant ? "yes" : "no") : "");
    row.text(notes.of(c));
    row.appendTo(line);
}

// The rows in blocks, `threads` blocks formatted at once and written in order.
void writeRows(std::ostream& out, const RunComparison& r, int threads) {
    constexpr std::size_t kBlockRows = 16384;
    const RowNotes notes(r);
    const std::size_t rows = r.sections.size();
    const std::size_t blocks = (rows + kBlockRows - 1) / kBlockRows;
    const std::size_t lanes = std::max<std::size_t>(
        1, std::min<std::size_t>(static_cast<std::size_t>(std::max(1, threads)), blocks));
    std::vector<std::string> text(lanes);
    for (std::size_t first = 0; first < blocks; first += lanes) {
        const std::size_t count = std::min(lanes, blocks - first);
        const auto format = [&](std::size_t k) {
            text[k].clear();
            text[k].reserve(kBlockRows * 192);
            const std::size_t from = (first + k) * kBlockRows,
                              to = std::min(rows, from + kBlockRows);
            auto row = std::make_unique<RowText>();
            for (std::size_t i = from; i < to; ++i) appendRow(text[k], *row, r.sections[i], notes);
        };
        std::vector<std::thread> workers;
        for (std::size_t k = 1; k < count; ++k) workers.emplace_back(format, k);
        format(0);
        for (std::thread& w : workers) w.join();
        for (std::size_t k = 0; k < count; ++k)
            out.write(text[k].data(), static_cast<std::streamsize>(text[k].size()));
    }
}

std::string range(double top, double bottom) {
    return fixed(top, 2) + "-" + fixed(bottom, 2) + " m";
}

// Below this the match is no evidence of a shift (the tie points' threshold, DepthMappingOptions).
constexpr double kWeakCorrelation = 0.5;

std::string matchLine(const DepthMapping& m) {
    std::string s = "depth match: run 2 depth = run 1 depth " + signedFixed(m.shift_m, 3) + " m";
    if (m.given) return s + " (given)\n";
    s += " (" + m.curve + ", correlation " + fixed(m.match.correlation, 3) + " over " +
         std::to_string(m.match.samples) + " samples)";
    if (!(m.match.correlation >= kWeakCorrelation))
        s += "; weak: the runs may not be of one well, or the shift lies beyond --max-shift "
             "(check it, or give --shift)";
    return s + "\n";
}

std::string stretchLine(const DepthMapping& m) {
    if (m.given) return "stretch: none (the shift was given)\n";
    if (m.ties.size() < 2) return "stretch: none (the overlap is too short to measure one)\n";
    std::string ties;
    for (const DepthTie& t : m.ties)
        ties += (ties.empty() ? "" : ", ") + signedFixed(t.match.shift_m, 3) + " m at " +
                fixed(t.md1_m, 1) + " m (correlation " + fixed(t.match.correlation, 3) + ")";
    if (m.stretch == 0.0) return "stretch: none (tie points " + ties + ")\n";
    return "stretch: " + signedFixed(m.stretch * 1000.0, 3) + " mm per m from " +
           fixed(m.reference_m, 2) + " m (tie points " + ties + ")\n";
}

std::string overlapLine(const RunComparison& r) {
    std::string s = "overlap: " + range(r.overlapTop1_m, r.overlapBottom1_m) + " of run 1 (" +
                    std::to_string(r.sections.size()) +
                    " sections): " + std::to_string(r.compared) + " compared, " +
                    std::to_string(r.oriented) + " of them with azimuths";
    if (r.outlinesSkipped > 0)
        s += " (" + std::to_string(r.outlinesSkipped) +
             " more oriented, their outlines not compared: diameters within " +
             fixed(r.outlineGate_mm, 2) + " mm, major axis within " +
             fixed(kOutlineAxisTurn_deg, 0) + " deg)";
    std::string left;
    for (int k = 1; k < 7; ++k)
        if (r.notCompared[k] > 0)
            left += (left.empty() ? "" : ", ") + std::to_string(r.notCompared[k]) + " " +
                    std::string(notComparedText(static_cast<NotCompared>(k)));
    if (!left.empty()) s += "; not compared: " + left;
    return s + "\n";
}

std::string biasText(const RunBias& b) {
    if (std::isnan(b.offset_mm))
        return "none removed (no reading in casing of known inner diameter)";
    return signedFixed(b.offset_mm, 2) + " mm removed (reading in casing of " +
           fixed(b.casingId_mm, 2) + " mm, " + std::to_string(b.sections) + " sections)";
}

std::string largestLine(const RunComparison& r) {
    const auto one = [](const char* name, const LargestChange& c) {
        if (std::isnan(c.change)) return std::string(name) + " not compared";
        return std::string(name) + " " + signedFixed(c.change, 2) + " mm at " + fixed(c.md1_m, 2) +
               " m";
    };
    std::string s = "largest changes: " + one("equivalent diameter", r.deq) + "; " +
                    one("dmin", r.dmin) + "; " + one("dmax", r.dmax) + "; ";
    if (std::isnan(r.growth.change) && r.outlinesSkipped > 0)
        s += "wall growth by azimuth not compared (the outlines of " +
             std::to_string(r.outlinesSkipped) + " oriented sections skipped: diameters within " +
             fixed(r.outlineGate_mm, 2) + " mm and major axis within " +
             fixed(kOutlineAxisTurn_deg, 0) + " deg)";
    else if (std::isnan(r.growth.change))
        s += "wall growth by azimuth not compared (azimuth unknown)";
    else
        s += "wall " + signedFixed(r.growth.change, 2) + " mm from the centre " +
             (std::isfinite(r.growth.azimuth_deg) ? "at azimuth " + fixed(r.growth.azimuth_deg, 1)
                                                  : std::string("all round")) +
             " at " + fixed(r.growth.md1_m, 2) + " m" +
             (r.outlinesSkipped > 0
                  ? " (of the " + std::to_string(r.oriented) + " outlines compared)"
                  : std::string());
    return s + "\n";
}

std::string zonesLine(const RunComparison& r) {
    if (r.zones.empty()) return "zones: none in either run over the overlap\n";
    std::string s = "zones:";
    for (const ZoneChange& z : r.zones) {
        s += "\n  " + std::string(className(z.cls)) + " " + range(z.top1_m, z.bottom1_m) + " " +
             std::string(zoneChangeName(z.kind)) + " (run 2 " + range(z.top2_m, z.bottom2_m);
        if (std::isfinite(z.maxDmaxChange_mm))
            s += "; dmax " + signedFixed(z.maxDmaxChange_mm, 1) + " mm at " +
                 fixed(z.maxDmaxChangeAt_m, 2) + " m, mean equivalent diameter " +
                 signedFixed(z.meanDeqChange_mm, 1) + " mm";
        s += ")";
    }
    return s + "\n";
}

std::string changedLine(const RunComparison& r) {
    std::string s = "changed beyond " + fixed(r.repeatability95_mm, 1) +
                    " mm: " + std::to_string(r.significant) + " of " + std::to_string(r.compared) +
                    " sections (" + fixed(r.significant_m, 2) + " m) in " +
                    std::to_string(r.changed.size()) + " intervals";
    const std::size_t shown = std::min<std::size_t>(r.changed.size(), 10);
    for (std::size_t k = 0; k < shown; ++k) {
        const ChangedInterval& c = r.changed[k];
        s += (k == 0 ? ": " : ", ") + range(c.top1_m, c.bottom1_m) + " (equivalent diameter " +
             signedFixed(c.maxDeqChange_mm, 1) + " mm at " + fixed(c.maxDeqChangeAt_m, 2) + " m)";
    }
    if (shown < r.changed.size()) s += ", ...";
    return s + "\n";
}

std::string volumeLine(const RunComparison& r) {
    if (!(r.volumeLength_m > 0.0)) return "hole volume: no compared interval\n";
    const double d = r.volume2_m3 - r.volume1_m3;
    return "hole volume over the " + fixed(r.volumeLength_m, 2) + " m compared: run 1 " +
           fixed(r.volume1_m3, 4) + " m3, run 2 " + fixed(r.volume2_m3, 4) + " m3 (" +
           signedFixed(d, 4) + " m3, " + signedFixed(100.0 * d / r.volume1_m3, 2) + " %)\n";
}

}  // namespace

void writeComparisonCsv(std::ostream& out, const RunComparison& r, int threads) {
    out << "md_m,md2_m,deq1_mm,deq2_mm,d_deq_mm,dmin1_mm,dmin2_mm,d_dmin_mm,dmax1_mm,dmax2_mm,"
           "d_dmax_mm,class1,class2,major_azimuth1_deg,major_azimuth2_deg,d_major_azimuth_deg,"
           "area1_mm2,area2_mm2,d_area_mm2,d_area_pct,d_deq_pct,max_growth_mm,"
           "max_growth_azimuth_deg,significant,note\n";
    writeRows(out, r, threads);
}

void writeComparisonCsv(const std::string& path, const RunComparison& r, int threads) {
    io::AtomicOutput file(path);
    writeComparisonCsv(file.stream(), r, threads);
    file.commit();
}

void writeZoneChanges(std::ostream& out, const RunComparison& r) {
    out << "change,class,top1_m,bottom1_m,top2_m,bottom2_m,length1_m,length2_m,mean_d_deq_mm,"
           "max_d_dmax_mm,max_d_dmax_md_m\n";
    for (const ZoneChange& z : r.zones) {
        std::string line(zoneChangeName(z.kind));
        field(line, className(z.cls));
        for (double v : {z.top1_m, z.bottom1_m, z.top2_m, z.bottom2_m, z.length1_m, z.length2_m})
            field(line, v, 3);
        field(line, z.meanDeqChange_mm, 2);
        field(line, z.maxDmaxChange_mm, 2);
        field(line, z.maxDmaxChangeAt_m, 3);
        out << line << '\n';
    }
    for (const ChangedInterval& c : r.changed) {
        std::string line = "changed,";
        for (double v :
             {c.top1_m, c.bottom1_m, r.mapping.toRun2(c.top1_m), r.mapping.toRun2(c.bottom1_m),
              c.bottom1_m - c.top1_m, c.bottom1_m - c.top1_m})
            field(line, v, 3);
        field(line, c.maxDeqChange_mm, 2);
        line += ",,";
        out << line << '\n';
    }
}

void writeZoneChanges(const std::string& path, const RunComparison& r) {
    io::AtomicOutput file(path);
    writeZoneChanges(file.stream(), r);
    file.commit();
}

std::string formatComparisonSummary(const RunComparison& r) {
    std::string s = matchLine(r.mapping) + stretchLine(r.mapping) + overlapLine(r);
    s += "bias: run 1 " + biasText(r.bias1) + "; run 2 " + biasText(r.bias2) + "\n";
    s += "repeatability: a diameter change beyond " + fixed(r.repeatability95_mm, 1) +
         " mm is significant (95 % of repeat-pass differences; docs/analysis.md)\n";
    if (r.unoriented1 || r.unoriented2)
        s += std::string("azimuths: unknown (") +
             (r.unoriented1 && r.unoriented2 ? "neither run"
              : r.unoriented1                ? "run 1"
                                             : "run 2") +
             " oriented): compared orientation-free quantities only (dmin, dmax, equivalent "
             "diameter, area)\n";
    s += largestLine(r) + zonesLine(r) + changedLine(r);
    s += "class changed on " + std::to_string(r.classChanges) + " of " +
         std::to_string(r.compared) + " compared sections\n";
    s += volumeLine(r);
    if (r.compared == 0)
        s += "agreement: nothing compared\n";
    else if (r.agree())
        s += "agreement: the runs agree within the tool's repeatability (" +
             fixed(r.repeatability95_mm, 1) + " mm) over every compared section\n";
    else
        s += "agreement: the runs differ beyond the tool's repeatability on " +
             std::to_string(r.significant) + " sections (" + fixed(r.significant_m, 2) + " m)\n";
    return s;
}

}  // namespace caliper3d::reconstruction
