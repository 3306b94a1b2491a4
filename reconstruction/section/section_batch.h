#pragma once

#include <cstddef>
#include <vector>

namespace caliper3d::reconstruction {

// SectionShape of one section as SectionBatchAnalyzer gives it: the same
// values, bit for bit, with the major axis as a unit direction in the section
// plane instead of an angle (what the world azimuths need, without the
// atan2/cos/sin round trip).
struct BatchShape {
    double area_mm2 = 0.0;
    double equivalentDiameter_mm = 0.0;
    double centroidU_mm = 0.0;
    double centroidV_mm = 0.0;
    double centreOffset_mm = 0.0;
    double dmax_mm = 0.0;
    double dmin_mm = 0.0;
    double ellipticity = 1.0;
    // Major axis at majorAngle_deg clockwise from arm 1: (cos, sin) of that
    // angle, so majorV >= 0.
    double majorU = 1.0;
    double majorV = 0.0;
    bool ellipseFitted = false;
    // What SectionAnalyzer::analyse's majorAngle_deg comes from, for the rare
    // caller that needs the angle itself (majorAngle_deg below): A - C and B of
    // the fitted conic, or the angle when no ellipse was fitted.
    double conicAMinusC = 0.0;
    double conicB = 0.0;
    double unfittedAngle_deg = 0.0;
};

// SectionAnalyzer::analyse's majorAngle_deg of a batch shape, bit for bit
// (one atan2).
double majorAngle_deg(const BatchShape& shape);

// Analyses kLanes sections at once (docs/analysis.md, "Sections": spline samples, area,
// centroid, least-squares ellipse). Each lane performs exactly the operations
// of SectionAnalyzer::analyse, in the same order, so its results are
// bit-identical; one section per SIMD lane is what lets the compiler
// vectorise the sums, which within one section it could only do by
// reordering them. Immutable; share it between threads, each with its own
// Workspace.
class SectionBatchAnalyzer {
public:
    static constexpr int kLanes = 8;

    // How the kLanes sections go through the vector units: the widest the
    // processor has (one AVX-512 vector), or two halves of four lanes (AVX2 or
    // SSE2). The results are the same; tests run both.
    enum class Width { Widest, FourLanes };

    SectionBatchAnalyzer(int knots, int samples, Width width = Width::Widest);

    int knots() const { return m_knots; }
    int samples() const { return m_samples; }

    // One worker's scratch: the samples' in-plane coordinates, lane by lane.
    class Workspace {
    public:
        explicit Workspace(const SectionBatchAnalyzer& analyzer)
            : m_buffer(static_cast<std::size_t>(2 * analyzer.samples() + 2) * kLanes) {}
        double* data() { return m_buffer.data(); }

    private:
        std::vector<double> m_buffer;
    };

    // pads[k * kLanes + lane]: radius of pad k of section `lane`, mm (repaired,
    // as WellGeometry::repairRadii gives them). Writes kLanes shapes.
    void analyse(const double* pads, BatchShape* out, Workspace& workspace) const;

private:
    int m_knots;
    int m_samples;
    bool m_wide;                       // one AVX-512 vector per batch, else two halves of four
    std::vector<double> m_weights;     // spline weights, samples x knots
    std::vector<double> m_cos, m_sin;  // of the sample angles
};

}  // namespace caliper3d::reconstruction
