#include "reconstruction/analysis/run_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <thread>

#include "reconstruction/analysis/section_angle_reference.h"
#include "reconstruction/analysis/section_profile.h"

namespace caliper3d::reconstruction {

double repeatabilityLimit_mm(int armCount) {
    return armCount >= 6 ? kImagerRepeatability95_mm : kFourArmRepeatability95_mm;
}

std::string_view notComparedText(NotCompared reason) {
    switch (reason) {
        case NotCompared::None:
            return "";
        case NotCompared::NoData1:
            return "run 1 no data";
        case NotCompared::ArmsNotOpen1:
            return "run 1 arms not open";
        case NotCompared::Cased1:
            return "run 1 cased";
        case NotCompared::NoData2:
            return "run 2 no data";
        case NotCompared::ArmsNotOpen2:
            return "run 2 arms not open";
        case NotCompared::Cased2:
            return "run 2 cased";
    }
    return "";
}

std::string_view zoneChangeName(ZoneChange::Kind kind) {
    switch (kind) {
        case ZoneChange::Kind::Appeared:
            return "appeared";
        case ZoneChange::Kind::Grew:
            return "grew";
        case ZoneChange::Kind::Shrank:
            return "shrank";
        case ZoneChange::Kind::Unchanged:
            return "unchanged";
        case ZoneChange::Kind::Closed:
            return "closed";
    }
    return "";
}

namespace {

// Why each row of a run cannot be compared (None where it can), as run 1's reasons; run 2's are
// these plus 3.
std::vector<NotCompared> rowReasons(const WellAnalysis& a) {
    std::vector<NotCompared> out(a.sections.size(), NotCompared::None);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const BoreholeClass cls = a.sections.measure(i).cls;
        if (cls == BoreholeClass::Cased) out[i] = NotCompared::Cased1;
        if (cls == BoreholeClass::NoData) out[i] = NotCompared::NoData1;
    }
    for (const NoDataInterval& closed : a.armsNotOpen)
        for (std::size_t i = closed.firstRow; i <= closed.lastRow && i < out.size(); ++i)
            out[i] = NotCompared::ArmsNotOpen1;
    return out;
}

NotCompared asRun2(NotCompared reason) {
    if (reason == NotCompared::None) return reason;
    return static_cast<NotCompared>(static_cast<int>(reason) + 3);
}

RunBias biasOf(const WellAnalysis& a) {
    RunBias bias;
    for (const CasingCheck& check : a.casing)
        if (std::isfinite(check.offset_mm) && check.sections > bias.sections) {
            bias.offset_mm = check.offset_mm;
            bias.casingId_mm = check.medianDiameter_mm - check.offset_mm;
            bias.sections = check.sections;
        }
    return bias;
}

double lerp(double a, double b, double w) {
    if (!std::isfinite(b)) return a;
    if (!std::isfinite(a)) return b;
    return a + (b - a) * w;
}

// A section's diameters and area with the run's offset removed (a diameter reads `offset` too
// wide; the area scales with the square of the equivalent diameter).
struct Measures {
    double deq = io::kNaN, dmin = io::kNaN, dmax = io::kNaN, area = io::kNaN;
};
Measures measures(const SectionMeasure& s, double offset_mm) {
    const double b = std::isfinite(offset_mm) ? offset_mm : 0.0;
    Measures m{s.equivalentDiameter_mm - b, s.dmin_mm - b, s.dmax_mm - b, s.area_mm2};
    if (b != 0.0 && s.equivalentDiameter_mm > 0.0)
        m.area *= (m.deq / s.equivalentDiameter_mm) * (m.deq / s.equivalentDiameter_mm);
    return m;
}

// Axial difference of two directions of [0, 180), in [0, 90]; NaN when either is (a round
// section has no axis).
double axisTurn_deg(double a, double b) {
    const double d = std::fmod(std::abs(b - a), 180.0);
    return std::min(d, 180.0 - d);
}

// Reads both runs section by section; owns the scratch the outlines need.
class SectionComparer {
public:
    SectionComparer(const ComparedRun& run1, const ComparedRun& run2,
                    const RunComparisonOptions& options, const RunBias& bias1, const RunBias& bias2,
                    const std::vector<NotCompared>& reasons1,
                    const std::vector<NotCompared>& reasons2)
        : m_run1(run1),
          m_run2(run2),
          m_options(options),
          m_offset1(options.removeBias ? bias1.offset_mm : io::kNaN),
          m_offset2(options.removeBias ? bias2.offset_mm : io::kNaN),
          m_reasons1(reasons1),
          m_reasons2(reasons2),
          m_gate_mm(options.outlineGate * options.repeatability95_mm),
          m_profiler1(*run1.geometry, options.azimuthBins),
          m_profiler2(*run2.geometry, options.azimuthBins),
          m_p1(static_cast<std::size_t>(options.azimuthBins)),
          m_p2(m_p1.size()) {}

    // Row i of run 1 against run 2 at md2, between its rows j0 (nearest) and j1 (weight w of
    // j1; j1 == j0 when md2 is on a row).
    SectionChange compare(std::size_t i, double md2, std::size_t j0, std::size_t j1, double w);

private:
    void compareOutlines(std::size_t i, std::size_t j0, std::size_t j1, double w, SectionChange& c);

    const ComparedRun& m_run1;
    const ComparedRun& m_run2;
    const RunComparisonOptions& m_options;
    // Run 2's outline of `row` (computed once for the two depths of run 1 that share it);
    // null where it has none.
    const double* profile2(std::size_t row);

    // Whether the outlines of a compared section are worth comparing (outlineGate).
    bool outlineMayDiffer(const SectionChange& c) const;

    double m_offset1, m_offset2;
    const std::vector<NotCompared>& m_reasons1;
    const std::vector<NotCompared>& m_reasons2;
    double m_gate_mm;  // 0: every outline
    SectionProfiler m_profiler1, m_profiler2;
    std::vector<double> m_p1, m_p2;
    // The last two outlines of run 2 computed: their rows (none: SIZE_MAX), whether they have
    // one, and the values.
    std::size_t m_cachedRow[2] = {SIZE_MAX, SIZE_MAX};
    bool m_cachedOk[2] = {false, false};
    std::vector<double> m_cached[2];
    int m_next = 0;
};

const double* SectionComparer::profile2(std::size_t row) {
    for (int k = 0; k < 2; ++k)
        if (m_cachedRow[k] == row) return m_cachedOk[k] ? m_cached[k].data() : nullptr;
    const int k = m_next;
    m_next = 1 - m_next;
    m_cached[k].resize(m_p1.size());
    m_cachedRow[k] = row;
    m_cachedOk[k] = m_profiler2.profile(row, m_cached[k].data());
    return m_cachedOk[k] ? m_cached[k].data() : nullptr;
}

SectionChange SectionComparer::compare(std::size_t i, double md2, std::size_t j0, std::size_t j1,
                                       double w) {
    const SectionResults& sections1 = m_run1.analysis->sections;
    const SectionResults& sections2 = m_run2.analysis->sections;
    const SectionMeasure& s1 = sections1.measure(i);
    const SectionMeasure& n2 = sections2.measure(j0);
    SectionChange c;
    c.md1_m = sections1.md_m(i);
    c.md2_m = md2;
    c.class1 = s1.cls;
    c.class2 = n2.cls;
    c.notCompared = m_reasons1[i];
    if (c.notCompared == NotCompared::None) c.notCompared = asRun2(m_reasons2[j0]);
    if (!c.compared()) return c;
    const bool blend = j1 != j0 && m_reasons2[j1] == NotCompared::None;
    const Measures m1 = measures(s1, m_offset1);
    const Measures a = measures(n2, m_offset2);
    const Measures b = blend ? measures(sections2.measure(j1), m_offset2) : a;
    const double wj = blend ? w : 0.0;
    c.deq1_mm = m1.deq;
    c.dmin1_mm = m1.dmin;
    c.dmax1_mm = m1.dmax;
    c.area1_mm2 = m1.area;
    c.deq2_mm = lerp(a.deq, b.deq, wj);
    c.dmin2_mm = lerp(a.dmin, b.dmin, wj);
    c.dmax2_mm = lerp(a.dmax, b.dmax, wj);
    c.area2_mm2 = lerp(a.area, b.area, wj);
    const bool oriented1 = m_run1.geometry->orientation(i) != WellGeometry::Orientation::Unoriented;
    const bool oriented2 =
        m_run2.geometry->orientation(j0) != WellGeometry::Orientation::Unoriented;
    if (oriented1) c.majorAzimuth1_deg = s1.majorAzimuth_deg;
    if (oriented2) c.majorAzimuth2_deg = n2.majorAzimuth_deg;
    if (oriented1 && oriented2) {
        // Only an outline that could be compared is skipped: where either run has no north
        // (the profiler says so at once), the row says "azimuth unknown", gate or not.
        const bool northKnown = referenceKnown(*m_run1.geometry, i, AngleReference::North) &&
                                referenceKnown(*m_run2.geometry, j0, AngleReference::North);
        if (!northKnown || outlineMayDiffer(c))
            compareOutlines(i, j0, blend ? j1 : j0, wj, c);
        else
            c.outlineSkipped = true;
    }
    const double limit = m_options.repeatability95_mm;
    c.significant = std::abs(c.deq2_mm - c.deq1_mm) > limit ||
                    std::abs(c.dmin2_mm - c.dmin1_mm) > limit ||
                    std::abs(c.dmax2_mm - c.dmax1_mm) > limit;
    return c;
}

bool SectionComparer::outlineMayDiffer(const SectionChange& c) const {
    if (!(m_gate_mm > 0.0)) return true;
    const double largest =
        std::max({std::abs(c.deq2_mm - c.deq1_mm), std::abs(c.dmin2_mm - c.dmin1_mm),
                  std::abs(c.dmax2_mm - c.dmax1_mm)});
    // A diameter that is NaN in either run tells nothing: compare the outlines.
    if (!(largest <= m_gate_mm)) return true;
    return axisTurn_deg(c.majorAzimuth1_deg, c.majorAzimuth2_deg) > kOutlineAxisTurn_deg;
}

void SectionComparer::compareOutlines(std::size_t i, std::size_t j0, std::size_t j1, double w,
                                      SectionChange& c) {
    const double* near = profile2(j0);
    if (!near || !m_profiler1.profile(i, m_p1.data())) return;
    std::copy(near, near + m_p2.size(), m_p2.begin());
    if (const double* far = j1 != j0 ? profile2(j1) : nullptr)
        for (std::size_t k = 0; k < m_p2.size(); ++k) m_p2[k] += (far[k] - m_p2[k]) * w;
    // A radius reads half a diameter's offset too long.
    const double half1 = std::isfinite(m_offset1) ? m_offset1 / 2.0 : 0.0;
    const double half2 = std::isfinite(m_offset2) ? m_offset2 / 2.0 : 0.0;
    std::size_t best = 0;
    double growth = -1.0e300, least = 1.0e300;
    for (std::size_t k = 0; k < m_p1.size(); ++k) {
        const double g = (m_p2[k] - half2) - (m_p1[k] - half1);
        m_p2[k] = g;  // the outline is used up: the growth, for the sink
        least = std::min(least, g);
        if (g > growth) {
            growth = g;
            best = k;
        }
    }
    if (m_options.outlineSink) m_options.outlineSink(i, m_p2.data());
    c.oriented = true;
    c.maxGrowth_mm = growth;
    // A wall that moved alike all round (a gauge hole unchanged, a washout widened evenly) has
    // no azimuth of largest growth: below kUniformGrowth_mm of spread it is left empty.
    if (growth - least >= kUniformGrowth_mm)
        c.maxGrowthAzimuth_deg = profileAngleAzimuth_deg(
            m_run1.geometry->frame(i), 360.0 * static_cast<double>(best) / m_p1.size());
}

// The signed value of larger magnitude.
void keepLargest(LargestChange& largest, double change, double md, double azimuth = io::kNaN) {
    if (!std::isfinite(change)) return;
    if (std::isnan(largest.change) || std::abs(change) > std::abs(largest.change))
        largest = {change, md, azimuth};
}

// The sampling step about row k of a depth sequence (half the distance between its neighbours).
double stepAbout(const FillArray<SectionChange>& s, std::size_t k) {
    if (s.size() < 2) return 0.0;
    const std::size_t lo = k == 0 ? 0 : k - 1, hi = std::min(k + 1, s.size() - 1);
    return (s[hi].md1_m - s[lo].md1_m) / static_cast<double>(hi - lo);
}

void countSections(RunComparison& r) {
    bool any1 = false, any2 = false;
    for (std::size_t k = 0; k < r.sections.size(); ++k) {
        const SectionChange& c = r.sections[k];
        ++r.notCompared[static_cast<int>(c.notCompared)];
        if (!c.compared()) continue;
        ++r.compared;
        r.oriented += c.oriented;
        r.outlinesSkipped += c.outlineSkipped;
        any1 |= std::isfinite(c.majorAzimuth1_deg) || c.oriented || c.outlineSkipped;
        any2 |= std::isfinite(c.majorAzimuth2_deg) || c.oriented || c.outlineSkipped;
        r.classChanges += c.class1 != c.class2;
        if (c.significant) {
            ++r.significant;
            r.significant_m += stepAbout(r.sections, k);
        }
        keepLargest(r.deq, c.deq2_mm - c.deq1_mm, c.md1_m);
        keepLargest(r.dmin, c.dmin2_mm - c.dmin1_mm, c.md1_m);
        keepLargest(r.dmax, c.dmax2_mm - c.dmax1_mm, c.md1_m);
        if (c.oriented && (std::isnan(r.growth.change) || c.maxGrowth_mm > r.growth.change))
            r.growth = {c.maxGrowth_mm, c.md1_m, c.maxGrowthAzimuth_deg};
    }
    const bool anyBoth = r.oriented + r.outlinesSkipped > 0;
    r.unoriented1 = !anyBoth && !any1;
    r.unoriented2 = !anyBoth && !any2;
}

void integrateVolumes(RunComparison& r) {
    for (std::size_t k = 1; k < r.sections.size(); ++k) {
        const SectionChange& a = r.sections[k - 1];
        const SectionChange& b = r.sections[k];
        if (!a.compared() || !b.compared()) continue;
        const double dz = b.md1_m - a.md1_m;
        r.volume1_m3 += 0.5 * (a.area1_mm2 + b.area1_mm2) * dz * 1e-6;
        r.volume2_m3 += 0.5 * (a.area2_mm2 + b.area2_mm2) * dz * 1e-6;
        r.volumeLength_m += dz;
    }
}

void findChangedIntervals(RunComparison& r) {
    ChangedInterval* open = nullptr;
    for (std::size_t k = 0; k < r.sections.size(); ++k) {
        const SectionChange& c = r.sections[k];
        if (!c.significant) {
            open = nullptr;
            continue;
        }
        const double half = stepAbout(r.sections, k) / 2.0;
        const double change = c.deq2_mm - c.deq1_mm;
        if (!open) {
            r.changed.push_back({c.md1_m - half, c.md1_m + half, 0, change, c.md1_m});
            open = &r.changed.back();
        }
        open->bottom1_m = c.md1_m + half;
        ++open->sections;
        if (std::abs(change) > std::abs(open->maxDeqChange_mm)) {
            open->maxDeqChange_mm = change;
            open->maxDeqChangeAt_m = c.md1_m;
        }
    }
}

// One run's zone in run 1's depths.
struct ZoneItem {
    int run = 1;
    BoreholeClass cls = BoreholeClass::Breakout;
    double top1 = 0.0, bottom1 = 0.0, length = 0.0;
};

// The sections of [top, bottom] (run 1's depths): how many, how many compared, their mean deq
// change and largest dmax change. The sections are in run 1's depth order, so only the zone's
// own rows are visited (a long well has hundreds of zones).
void measureZone(const RunComparison& r, ZoneChange& z, double& comparedFraction) {
    std::size_t all = 0, compared = 0;
    double deqSum = 0.0;
    const auto first =
        std::lower_bound(r.sections.begin(), r.sections.end(), z.top1_m,
                         [](const SectionChange& c, double md) { return c.md1_m < md; });
    for (auto it = first; it != r.sections.end() && !(it->md1_m > z.bottom1_m); ++it) {
        const SectionChange& c = *it;
        ++all;
        if (!c.compared()) continue;
        ++compared;
        deqSum += c.deq2_mm - c.deq1_mm;
        const double d = c.dmax2_mm - c.dmax1_mm;
        if (std::isnan(z.maxDmaxChange_mm) || std::abs(d) > std::abs(z.maxDmaxChange_mm)) {
            z.maxDmaxChange_mm = d;
            z.maxDmaxChangeAt_m = c.md1_m;
        }
    }
    if (compared > 0) z.meanDeqChange_mm = deqSum / static_cast<double>(compared);
    comparedFraction = all > 0 ? static_cast<double>(compared) / static_cast<double>(all) : 0.0;
}

ZoneChange::Kind pairedKind(const ZoneChange& z, double limit) {
    const double longer = std::max(0.5, 0.1 * z.length1_m);
    if (z.maxDmaxChange_mm > limit || z.meanDeqChange_mm > limit) return ZoneChange::Kind::Grew;
    if (z.maxDmaxChange_mm < -limit || z.meanDeqChange_mm < -limit) return ZoneChange::Kind::Shrank;
    if (z.length2_m - z.length1_m > longer) return ZoneChange::Kind::Grew;
    if (z.length1_m - z.length2_m > longer) return ZoneChange::Kind::Shrank;
    return ZoneChange::Kind::Unchanged;
}

// Groups the zones of both runs that share a class and overlap in depth; each group is one
// ZoneChange: in run 2 only, appeared; in run 1 only, closed; in both, grew, shrank or
// unchanged. A group over depths mostly not compared (either run without data) is left out.
void pairZones(RunComparison& r, const WellAnalysis& a1, const WellAnalysis& a2) {
    std::vector<ZoneItem> items;
    const double lo = r.overlapTop1_m, hi = r.overlapBottom1_m;
    for (const Zone& z : a1.zones)
        if (z.bottom_m >= lo && z.top_m <= hi)
            items.push_back({1, z.kind, z.top_m, z.bottom_m, z.length_m});
    for (const Zone& z : a2.zones) {
        const double top = r.mapping.toRun1(z.top_m), bottom = r.mapping.toRun1(z.bottom_m);
        if (bottom >= lo && top <= hi) items.push_back({2, z.kind, top, bottom, z.length_m});
    }
    std::sort(items.begin(), items.end(), [](const ZoneItem& x, const ZoneItem& y) {
        return x.cls != y.cls ? x.cls < y.cls : x.top1 < y.top1;
    });
    for (std::size_t k = 0; k < items.size();) {
        ZoneChange z;
        z.cls = items[k].cls;
        z.top1_m = items[k].top1;
        z.bottom1_m = items[k].bottom1;
        for (; k < items.size() && items[k].cls == z.cls && items[k].top1 <= z.bottom1_m; ++k) {
            z.bottom1_m = std::max(z.bottom1_m, items[k].bottom1);
            (items[k].run == 1 ? z.length1_m : z.length2_m) += items[k].length;
        }
        z.top2_m = r.mapping.toRun2(z.top1_m);
        z.bottom2_m = r.mapping.toRun2(z.bottom1_m);
        double comparedFraction = 0.0;
        measureZone(r, z, comparedFraction);
        if (comparedFraction < 0.5) continue;
        if (z.length1_m == 0.0)
            z.kind = ZoneChange::Kind::Appeared;
        else if (z.length2_m == 0.0)
            z.kind = ZoneChange::Kind::Closed;
        else
            z.kind = pairedKind(z, r.repeatability95_mm);
        r.zones.push_back(z);
    }
    std::sort(r.zones.begin(), r.zones.end(),
              [](const ZoneChange& x, const ZoneChange& y) { return x.top1_m < y.top1_m; });
}

}  // namespace

RunComparison compareRuns(const ComparedRun& run1, const ComparedRun& run2,
                          const RunComparisonOptions& options) {
    RunComparison r;
    r.mapping = options.mapping;
    r.repeatability95_mm = options.repeatability95_mm;
    r.bias1 = biasOf(*run1.analysis);
    r.bias2 = biasOf(*run2.analysis);
    r.outlineGate_mm = options.outlineGate * options.repeatability95_mm;
    const SectionResults& s1 = run1.analysis->sections;
    const SectionResults& s2 = run2.analysis->sections;
    if (s1.size() == 0 || s2.size() == 0) throw std::runtime_error("a run has no sections");
    // Run 1's rows that map into run 2's logged interval: one run of rows, as both runs' depths
    // and the mapping increase with depth. They are compared in chunks, one comparer (and its
    // scratch) per chunk, each chunk constructing its own rows of r.sections (FillArray: the
    // 136 bytes a row are first touched by the workers, side by side, not zeroed first on one
    // thread).
    const double first2 = s2.md_m(0), last2 = s2.md_m(s2.size() - 1);
    const double tolerance = 1e-6;
    const auto md2Of = [&](std::size_t i) { return r.mapping.toRun2(s1.md_m(i)); };
    std::size_t begin = 0, end = s1.size();
    while (begin < end && md2Of(begin) < first2 - tolerance) ++begin;
    while (end > begin && md2Of(end - 1) > last2 + tolerance) --end;
    // The first row of run 2 at or below md2 (the last row when none is).
    const auto rowAtOrBelow = [&s2](double md2) {
        std::size_t lo = 0, hi = s2.size() - 1;
        while (lo < hi) {
            const std::size_t mid = lo + (hi - lo) / 2;
            if (s2.md_m(mid) < md2)
                lo = mid + 1;
            else
                hi = mid;
        }
        return lo;
    };
    const std::vector<NotCompared> reasons1 = rowReasons(*run1.analysis);
    const std::vector<NotCompared> reasons2 = rowReasons(*run2.analysis);
    const std::size_t count = end - begin;
    r.sections = FillArray<SectionChange>(count);
    const auto work = [&](std::size_t from, std::size_t to) {
        if (from >= to) return;
        SectionComparer comparer(run1, run2, options, r.bias1, r.bias2, reasons1, reasons2);
        std::size_t j = rowAtOrBelow(md2Of(begin + from));
        for (std::size_t k = from; k < to; ++k) {
            const std::size_t i = begin + k;
            const double md2 = md2Of(i);
            while (j + 1 < s2.size() && s2.md_m(j) < md2) ++j;
            // Rows j - 1 and j enclose md2 (j alone at the top, or on a row).
            const std::size_t above = j > 0 && s2.md_m(j) > md2 ? j - 1 : j;
            const double span = s2.md_m(j) - s2.md_m(above);
            const double w = span > 0.0 ? (md2 - s2.md_m(above)) / span : 0.0;
            const std::size_t nearest = w > 0.5 ? j : above;
            r.sections.set(k, comparer.compare(i, md2, nearest, nearest == j ? above : j,
                                               nearest == j ? 1.0 - w : w));
        }
    };
    const std::size_t chunks =
        std::min<std::size_t>(std::max(1, options.threads), count / 1024 + 1);
    std::vector<std::thread> workers;
    for (std::size_t c = 1; c < chunks; ++c)
        workers.emplace_back(work, count * c / chunks, count * (c + 1) / chunks);
    work(0, count / chunks);
    for (std::thread& w : workers) w.join();
    if (r.sections.empty())
        throw std::runtime_error(
            "the runs do not overlap: no depth of run 1 maps into run 2's logged interval");
    r.overlapTop1_m = r.sections.front().md1_m;
    r.overlapBottom1_m = r.sections.back().md1_m;
    countSections(r);
    integrateVolumes(r);
    findChangedIntervals(r);
    pairZones(r, *run1.analysis, *run2.analysis);
    return r;
}

}  // namespace caliper3d::reconstruction
