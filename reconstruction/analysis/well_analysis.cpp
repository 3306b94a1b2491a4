#include "reconstruction/analysis/well_analysis.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "io/casing_program.h"
#include "io/median.h"
#include "reconstruction/parallel/ordered_blocks.h"
#include "reconstruction/parallel/prefault.h"
#include "reconstruction/section/section_analysis.h"
#include "reconstruction/section/section_batch.h"

namespace caliper3d::reconstruction {

namespace {

// Rows per block: the P1AZ check's blocks, so that the sums it adds in block
// order are padAzimuthOffset's, bit for bit.
constexpr std::size_t kBlockRows = kPadAzimuthBlockRows;
constexpr int kLanes = SectionBatchAnalyzer::kLanes;

double valueAt(const std::vector<double>& curve, std::size_t row) {
    return row < curve.size() ? curve[row] : io::kNaN;
}

// wrap360(degrees(atan2(y, x))): fmod is the identity on atan2's range.
double azimuthOf(double y, double x) {
    double a = glm::degrees(std::atan2(y, x));
    if (a < 0.0) a += 360.0;
    if (a >= 360.0) a -= 360.0;
    return a;
}

// fmod(a, 180) for a in [0, 360): a - 180 is exact there (Sterbenz lemma).
double axial(double a) {
    return a >= 180.0 ? a - 180.0 : a;
}

struct WorldAngles {
    double majorAzimuth_deg = 0.0;
    double majorFromHighSide_deg = 0.0;
    double centreOffsetAzimuth_deg = 0.0;
};

// An angle this close to where [0, 180) or [0, 360) wraps may come out at the
// other end from a formula that rounds differently; there the original
// formulas decide, so that the report prints what they give.
constexpr double kSeam_deg = 1e-9;
constexpr double kCentredBelow_mm = 0.01;
bool nearSeam(double a, double period) {
    return a < kSeam_deg || a > period - kSeam_deg;
}

// The world angles (docs/conventions.md, "Azimuth of an in-plane direction") from dot products on
// the frame: what inPlaneAzimuth_deg and angleFromHighSide_deg give (to rounding) without their
// angle -> sin/cos -> atan2 round trips and the high side's own trigonometry; one atan2 per angle
// remains.
WorldAngles worldAngles(const SectionFrame& f, const PathPoint& p, const BatchShape& s,
                        double axisMinElongation_mm) {
    WorldAngles out;
    // A round section has no major axis (ClassificationRules::axisMinElongation_mm),
    // and a centred tool no offset direction: below a hundredth of a millimetre
    // (what the report prints) its direction is that of rounding noise.
    const bool round = !(s.dmax_mm - s.dmin_mm >= axisMinElongation_mm);
    const bool centred = !(s.centreOffset_mm >= kCentredBelow_mm);
    out.majorAzimuth_deg = out.majorFromHighSide_deg = out.centreOffsetAzimuth_deg = std::nan("");
    if (!round) {
        // Azimuth of the horizontal projection; none within 0.06 deg of vertical
        // (projection of the unit vector shorter than 1e-3).
        const Ned major = s.majorU * f.arm1 + s.majorV * f.side;
        const double az = major.x * major.x + major.y * major.y < 1e-6
                              ? std::nan("")
                              : azimuthOf(major.y, major.x);
        out.majorAzimuth_deg = std::isfinite(az) ? axial(az) : az;
        if (nearSeam(out.majorAzimuth_deg, 180.0)) {
            const double exact = inPlaneAzimuth_deg(f, majorAngle_deg(s));
            out.majorAzimuth_deg = std::isfinite(exact) ? std::fmod(exact, 180.0) : exact;
        }

        // The high side is (cos i cos a, cos i sin a, -sin i) = (t_z t_x, t_z t_y,
        // -(t_x^2 + t_y^2)) / sin i for the tangent t = (sin i cos a, sin i sin a,
        // cos i): atan2 needs no normalisation, and the sign of sin i can only turn
        // the angle by 180 deg, which an axis ignores. North in a vertical hole.
        const Ned& t = f.tangent;
        const double horizontal2 = t.x * t.x + t.y * t.y;
        const Ned highSide =
            horizontal2 < 1e-24 ? Ned(1.0, 0.0, 0.0) : Ned(t.z * t.x, t.z * t.y, -horizontal2);
        const Ned right = glm::cross(t, highSide);
        out.majorFromHighSide_deg =
            axial(azimuthOf(glm::dot(major, right), glm::dot(major, highSide)));
        if (nearSeam(out.majorFromHighSide_deg, 180.0))
            out.majorFromHighSide_deg =
                std::fmod(angleFromHighSide_deg(f, p.inc_deg, p.azi_deg, majorAngle_deg(s)), 180.0);
    }

    if (!centred) {
        const Ned c = s.centroidU_mm * f.arm1 + s.centroidV_mm * f.side;  // length centreOffset_mm
        out.centreOffsetAzimuth_deg =
            c.x * c.x + c.y * c.y < 1e-6 * s.centreOffset_mm * s.centreOffset_mm
                ? std::nan("")
                : azimuthOf(c.y, c.x);
        if (nearSeam(out.centreOffsetAzimuth_deg, 360.0))
            out.centreOffsetAzimuth_deg =
                inPlaneAzimuth_deg(f, glm::degrees(std::atan2(s.centroidV_mm, s.centroidU_mm)));
    }
    return out;
}

struct BlockCounts {
    std::size_t repairedSections = 0, repairedArms = 0, unorientedSections = 0;
};

// One worker's scratch: the batch's workspace and its pads, lane by lane.
struct Scratch {
    explicit Scratch(const SectionBatchAnalyzer& analyzer)
        : workspace(analyzer),
          pads(static_cast<std::size_t>(analyzer.knots()) * kLanes),
          row(static_cast<std::size_t>(analyzer.knots())) {}
    SectionBatchAnalyzer::Workspace workspace;
    std::vector<double> pads;
    std::vector<double> row;
};

// Whether any bit size is known (the option or the log's BS). Without one the median
// equivalent diameter stands in as gauge; it is known only once every section is analysed,
// and the classes and the gauge volumes wait for it.
bool anyBitSize(const io::SectionTable& t, double bitOverride) {
    bool anyBit = std::isfinite(bitOverride);
    for (std::size_t i = 0; !anyBit && i < std::min(t.rowCount(), t.bitSize_mm.size()); ++i)
        anyBit = std::isfinite(t.bitSize_mm[i]);
    return anyBit;
}

// Where the section is, whatever its shape: the bit size (the path holds the rest).
SectionMeasure positionOf(double bit_mm) {
    SectionMeasure m;
    m.bit_mm = bit_mm;
    return m;
}

// Where it is, but no shape: every measurement undefined.
void markNoData(SectionMeasure& m) {
    m.area_mm2 = m.equivalentDiameter_mm = m.dmin_mm = m.dmax_mm = io::kNaN;
    m.ellipticity = m.majorAzimuth_deg = m.majorFromHighSide_deg = io::kNaN;
    m.centreOffset_mm = m.centreOffsetAzimuth_deg = io::kNaN;
    m.cls = BoreholeClass::NoData;
}

BoreholeClass shapeClass(const SectionMeasure& m, const PathPoint& p,
                         const ClassificationRules& rules) {
    return classifyShape(
        {p.md, m.dmin_mm, m.dmax_mm, m.bit_mm, p.inc_deg, m.majorFromHighSide_deg, io::kNaN},
        rules);
}

// One diameter measured: the circle's own figures, not the fit's (which the spline leaves a
// few hundredths off). Knot 0 is pad 1 and the opposite knot pad 2, so the diameter is
// r1 + r2 and the centre (r1 - r2)/2 from the tool; area and centroid direction stay the
// samples'.
void useTwoPadCircle(const double* pads, int knots, BatchShape* shapes) {
    for (std::size_t l = 0; l < kLanes; ++l) {
        const double r1 = pads[l], r2 = pads[static_cast<std::size_t>(knots / 2) * kLanes + l];
        shapes[l].dmax_mm = shapes[l].dmin_mm = r1 + r2;
        shapes[l].ellipticity = 1.0;
        shapes[l].centreOffset_mm = std::abs(r1 - r2) / 2.0;
    }
}

// analyseWell's state and its steps. Blocks in parallel: spline, shape and world angles of
// kLanes sections at a time, their shape class, the P1AZ check's sums. In row order after
// them: the volume, whose sum runs along the hole. Then, along the whole hole: the gauge from
// the sections where the log has no bit size, the breakout zone rules, zones and summaries.
class WellAnalyser {
public:
    WellAnalyser(const WellGeometry& g, const AnalysisOptions& options, WellAnalysis& a)
        : m_g(g),
          m_t(g.table()),
          m_options(options),
          m_a(a),
          m_rows(m_t.rowCount()),
          m_threads(std::max(1, options.threads)),
          m_analyzer(g.knotCount(), g.options().splinePoints),
          m_azimuthKnown(g.holeAzimuthKnown()),
          m_anyBit(anyBitSize(m_t, options.bitSize_mm)),
          m_checkOrientation(hasPadAzimuthCurves(m_t)),
          m_blocks((m_rows + kBlockRows - 1) / kBlockRows),
          m_classes(m_rows),
          m_counts(m_blocks),
          m_orientationSums(m_blocks),
          m_volume(options.volume, g.path().front().md, g.path().back().md) {
        m_a.twoPads = m_t.armCount == 2;
        m_scratch.reserve(static_cast<std::size_t>(m_threads));
        for (int w = 0; w < m_threads; ++w) m_scratch.emplace_back(m_analyzer);
    }

    void analyseSections() {
        forEachBlockInOrder(
            m_blocks, m_threads,
            [this](std::size_t block, std::size_t worker) { analyseBlock(block, worker); },
            [](std::size_t) {});
        if (!m_anyBit) classifyAgainstMedianDiameter();
        markArmsNotOpen();
        if (m_anyBit)
            for (std::size_t i = 1; i < m_rows; ++i) addVolumeStep(i);
    }

    // The breakout zone rules run along the hole, over the shape classes.
    void applyZoneRules() {
        WellAnalysis& a = m_a;
        const std::vector<BoreholeClass> shapeClasses = m_classes;
        const BreakoutEvidence evidence = breakoutEvidenceFor(m_t.armCount);
        applyBreakoutZoneRules(
            m_classes, [&](std::size_t i) { return a.sections.md_m(i); },
            [&](std::size_t i) -> double {
                if (evidence == BreakoutEvidence::AxisFixedInEarth)
                    return a.sections.measure(i).majorAzimuth_deg;
                const double p1az = valueAt(m_t.p1az_deg, i);
                return std::isfinite(p1az) ? p1az : valueAt(m_t.rb_deg, i);
            },
            m_options.rules, evidence);
        for (std::size_t i = 0; i < m_rows; ++i)
            if (m_classes[i] != shapeClasses[i]) a.sections.measure(i).cls = m_classes[i];
    }

    void summarise() {
        WellAnalysis& a = m_a;
        a.zones = detectZones(
            m_classes, [&](std::size_t i) { return a.sections.md_m(i); },
            [&](std::size_t i) { return a.sections.measure(i).majorAzimuth_deg; },
            [&](std::size_t i) { return a.sections.measure(i).dmax_mm; },
            [&](std::size_t i) { return a.sections.measure(i).dmin_mm; });
        a.breakouts = summariseBreakouts(a.zones, m_options.wsm);
        a.volume = m_volume.result();
        PadAzimuthSums orientation;
        for (const PadAzimuthSums& s : m_orientationSums) orientation.add(s);
        // A HAZI derived from P1AZ - RB agrees with P1AZ and RB by construction.
        if (m_t.holeAzimuth != io::SectionTable::HoleAzimuth::Derived)
            a.padAzimuthOffset = padAzimuthOffset(orientation);
        a.holeAzimuthUnknown = !m_azimuthKnown;
        a.north = m_t.north;
        a.noData = m_g.noDataIntervals();
        for (const NoDataInterval& gap : a.noData) a.noDataSections += gap.sections();
        for (const NoDataInterval& gap : a.armsNotOpen) a.armsNotOpenSections += gap.sections();
        checkCasing();
        for (const BlockCounts& c : m_counts) {
            a.repairedSections += c.repairedSections;
            a.repairedArms += c.repairedArms;
            a.unorientedSections += c.unorientedSections;
        }
    }

private:
    void analyseBlock(std::size_t block, std::size_t worker) {
        const std::size_t first = block * kBlockRows, last = std::min(m_rows, first + kBlockRows);
        Scratch& s = m_scratch[worker];
        const int knots = m_analyzer.knots();
        for (std::size_t group = first; group < last; group += kLanes) {
            const std::size_t n = std::min<std::size_t>(kLanes, last - group);
            int repaired[kLanes] = {};
            for (std::size_t l = 0; l < kLanes; ++l) {
                // A short last group repeats its last section in the spare lanes.
                const std::size_t row = group + std::min(l, n - 1);
                repaired[l] = m_g.sectionKnots(row, s.row.data());
                for (int k = 0; k < knots; ++k)
                    s.pads[static_cast<std::size_t>(k) * kLanes + l] = s.row[k];
            }
            BatchShape shapes[kLanes];
            m_analyzer.analyse(s.pads.data(), shapes, s.workspace);
            if (m_a.twoPads) useTwoPadCircle(s.pads.data(), knots, shapes);
            for (std::size_t l = 0; l < n; ++l)
                storeSection(group + l, shapes[l], repaired[l], m_counts[block]);
        }
        if (m_checkOrientation) m_orientationSums[block] = padAzimuthSums(m_t, first, last);
    }

    // The result of one analysed row, with its shape class.
    void storeSection(std::size_t row, const BatchShape& shape, int repaired, BlockCounts& count) {
        const PathPoint& p = m_g.path()[row];
        const double bitOverride = m_options.bitSize_mm;
        const io::CasingString* casing = io::casingAt(m_t.casing, p.md);
        SectionMeasure r = positionOf(
            casing ? casing->innerDiameter_mm
                   : (std::isfinite(bitOverride) ? bitOverride : 2.0 * m_g.bitRadius_mm(row)));
        if (!m_g.measured(row)) {
            markNoData(r);
            m_classes[row] = r.cls;
            m_a.sections.set(row, r);
            return;
        }
        r.area_mm2 = shape.area_mm2;
        r.equivalentDiameter_mm = shape.equivalentDiameter_mm;
        r.dmin_mm = shape.dmin_mm;
        r.dmax_mm = shape.dmax_mm;
        r.ellipticity = shape.ellipticity;
        const WorldAngles w =
            worldAngles(m_g.frame(row), p, shape, m_options.rules.axisMinElongation_mm);
        r.majorAzimuth_deg = w.majorAzimuth_deg;
        r.majorFromHighSide_deg = w.majorFromHighSide_deg;
        r.centreOffset_mm = shape.centreOffset_mm;
        r.centreOffsetAzimuth_deg = w.centreOffsetAzimuth_deg;
        r.repairedArms = static_cast<std::uint16_t>(repaired);
        const bool oriented = m_g.orientation(row) != WellGeometry::Orientation::Unoriented;
        if (!oriented) {
            // No pad-1 azimuth nor relative bearing: arm 1 points nowhere known, so neither
            // north nor the high side is (docs/conventions.md, "No orientation"). The shape is
            // still measured.
            r.majorAzimuth_deg = r.centreOffsetAzimuth_deg = io::kNaN;
            r.majorFromHighSide_deg = io::kNaN;
        }
        r.cls = casing     ? BoreholeClass::Cased
                : m_anyBit ? shapeClass(r, p, m_options.rules)
                           : BoreholeClass::InGauge;
        m_classes[row] = r.cls;
        if (!m_azimuthKnown && p.inc_deg > 0.0) {
            // Arm 1 placed from RB has no true azimuth; from P1AZ, no high side.
            if (m_g.orientation(row) == WellGeometry::Orientation::RelativeBearing)
                r.majorAzimuth_deg = r.centreOffsetAzimuth_deg = io::kNaN;
            else
                r.majorFromHighSide_deg = io::kNaN;
        }
        m_a.sections.set(row, r);
        if (r.repairedArms > 0) {
            ++count.repairedSections;
            count.repairedArms += static_cast<std::size_t>(r.repairedArms);
        }
        if (!oriented) ++count.unorientedSections;
    }

    // The step from section i - 1 to i: open hole only, unless either has no data.
    void addVolumeStep(std::size_t i) {
        const SectionMeasure &r0 = m_a.sections.measure(i - 1), &r1 = m_a.sections.measure(i);
        const double md0 = m_a.sections.md_m(i - 1), md1 = m_a.sections.md_m(i);
        if (io::casingAt(m_t.casing, md0) || io::casingAt(m_t.casing, md1))
            m_volume.addCasedStep(md0, md1);
        else if (m_classes[i - 1] != BoreholeClass::NoData && m_classes[i] != BoreholeClass::NoData)
            m_volume.addStep(md0, r0.area_mm2, r0.bit_mm, md1, r1.area_mm2, r1.bit_mm);
        else
            m_volume.addUncoveredStep(md0, md1);
    }

    // Arms that did not open (docs/analysis.md, "Arms not open"): runs of at least
    // armsClosedMinSections measured sections whose largest diameter stays more than
    // armsClosedFraction of their gauge below it become no_data, listed in armsNotOpen.
    void markArmsNotOpen() {
        const ClassificationRules& rules = m_options.rules;
        auto closed = [&](std::size_t i) {
            const SectionMeasure& r = m_a.sections.measure(i);
            return m_g.measured(i) && r.dmax_mm < r.bit_mm * (1.0 - rules.armsClosedFraction);
        };
        const auto minRun =
            static_cast<std::size_t>(std::max(1.0, std::ceil(rules.armsClosedMinSections)));
        std::size_t i = 0;
        while (i < m_rows) {
            if (!closed(i)) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j + 1 < m_rows && closed(j + 1)) ++j;
            if (j - i + 1 >= minRun) {
                for (std::size_t k = i; k <= j; ++k) {
                    markNoData(m_a.sections.measure(k));
                    m_classes[k] = BoreholeClass::NoData;
                }
                m_a.armsNotOpen.push_back({i, j, m_a.sections.md_m(i), m_a.sections.md_m(j)});
            }
            i = j + 1;
        }
    }

    // Each casing string's measured sections: their median equivalent diameter against the
    // casing's nominal inner diameter.
    void checkCasing() {
        for (const io::CasingString& c : m_t.casing) {
            CasingCheck check;
            check.casing = c;
            std::vector<double> d;
            for (std::size_t i = 0; i < m_rows; ++i) {
                const double md = m_a.sections.md_m(i);
                if (m_classes[i] != BoreholeClass::Cased || io::casingAt(m_t.casing, md) != &c)
                    continue;
                if (!std::isfinite(check.top_m)) check.top_m = md;
                check.bottom_m = md;
                d.push_back(m_a.sections.measure(i).equivalentDiameter_mm);
            }
            check.sections = d.size();
            if (!d.empty()) check.medianDiameter_mm = io::medianInPlace(d);
            check.offset_mm = check.medianDiameter_mm - c.innerDiameter_mm;
            m_a.casing.push_back(check);
        }
    }

    // No bit size anywhere: the median equivalent diameter of the measured sections (WellGeometry
    // guarantees one) is the gauge of every section, its classes and the volume.
    void classifyAgainstMedianDiameter() {
        std::vector<double> d;
        d.reserve(m_g.measuredRows());
        for (std::size_t i = 0; i < m_rows; ++i)
            if (m_g.measured(i) && m_classes[i] != BoreholeClass::Cased)
                d.push_back(m_a.sections.measure(i).equivalentDiameter_mm);
        if (d.empty()) return;  // cased throughout: no open hole to take a gauge from
        const double gauge_mm = io::medianInPlace(d);
        for (std::size_t i = 0; i < m_rows; ++i) {
            SectionMeasure& r = m_a.sections.measure(i);
            if (m_classes[i] == BoreholeClass::Cased) continue;
            if (io::casingAt(m_t.casing, m_a.sections.md_m(i))) continue;  // no data inside casing
            r.bit_mm = gauge_mm;
            if (m_g.measured(i)) {
                r.cls = shapeClass(r, m_g.path()[i], m_options.rules);
                m_classes[i] = r.cls;
            }
        }
        m_a.bitSizeFromSections = true;
        m_anyBit = true;
    }

    const WellGeometry& m_g;
    const io::SectionTable& m_t;
    const AnalysisOptions& m_options;
    WellAnalysis& m_a;
    const std::size_t m_rows;
    const int m_threads;
    const SectionBatchAnalyzer m_analyzer;
    const bool m_azimuthKnown;
    bool m_anyBit;  // a bit size known, or the median diameter taken for one
    const bool m_checkOrientation;
    const std::size_t m_blocks;
    std::vector<Scratch> m_scratch;
    std::vector<BoreholeClass> m_classes;
    std::vector<BlockCounts> m_counts;
    std::vector<PadAzimuthSums> m_orientationSums;
    HoleVolumeAccumulator m_volume;
};

}  // namespace

WellAnalysis analyseWell(const WellGeometry& g, const AnalysisOptions& options) {
    const std::size_t rows = g.table().rowCount();
    WellAnalysis a;
    // 88 bytes per row of fresh memory: its pages are faulted in on every
    // worker at once, and each measure is constructed once, by the worker that
    // computes it (no sequential value-initialisation first).
    a.sections = SectionResults(g.sharedPath(), g.holeAzimuthKnown());
    prefaultPages(a.sections.data(), rows * sizeof(SectionMeasure), std::max(1, options.threads));
    if (rows == 0) return a;
    WellAnalyser analyser(g, options, a);
    analyser.analyseSections();
    analyser.applyZoneRules();
    analyser.summarise();
    return a;
}

}  // namespace caliper3d::reconstruction
