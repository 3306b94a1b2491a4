#include "reconstruction/section/section_batch.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <boost/math/constants/constants.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/section/periodic_spline.h"

namespace caliper3d::reconstruction {

namespace {

constexpr int kL = SectionBatchAnalyzer::kLanes;
constexpr double kTwoPi = boost::math::constants::two_pi<double>();

// Sections side by side, one per element. GCC and Clang vector extensions do
// element-wise IEEE arithmetic, so each element gets exactly the value the
// scalar code computes, and they lower the type to whatever SIMD the function
// is compiled for; auto-vectorisation of per-lane loops did not do that well.
typedef double Lanes4 __attribute__((vector_size(4 * sizeof(double))));
typedef double Lanes8 __attribute__((vector_size(8 * sizeof(double))));

template <class V>
constexpr int kWidth = static_cast<int>(sizeof(V) / sizeof(double));
// The comparison result of V: integers of the same width.
template <class V>
using MaskOf = decltype(V{} < V{});

template <class V>
inline V load(const double* p) {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
template <class V>
inline void store(double* p, V v) {
    std::memcpy(p, &v, sizeof v);
}
template <class V>
inline V splat(double x) {
    return V{} + x;
}
// std::abs of each element: the sign bit cleared.
template <class V>
inline V absolute(V x) {
    return reinterpret_cast<V>(reinterpret_cast<MaskOf<V>>(x) & 0x7fffffffffffffffLL);
}
template <class V>
inline V squareRoot(V x) {
    for (int l = 0; l < kWidth<V>; ++l) x[l] = std::sqrt(x[l]);
    return x;
}

// What the vectorised part leaves for each lane: the shoelace sums and the
// least-squares conic a x^2 + b xy + c y^2 + d x + e y = 1 about the points'
// mean, with `fitted` false where fitEllipse gives up before its eigenvalues
// (singular normal equations, not an ellipse).
struct LaneSums {
    double twiceArea[kL], cu[kL], cv[kL];
    double a[kL], b[kL], c[kL], d[kL], e[kL];
    double k[kL], scale[kL];
    bool fitted[kL];
};

// The kernel's parts below are always inlined into laneSums, itself always
// inlined into the clones, so each is compiled for the clone's vector width.

// Row j of a lane-interleaved array (kL values per row) from the first lane.
template <class V>
__attribute__((always_inline)) inline V row(const double* p, int j) {
    return load<V>(p + j * kL);
}

// PeriodicSplineSampler::sample: the m outline points into u and v, and the
// first again as row m.
template <class V>
__attribute__((always_inline)) inline void sampleOutline(int knots, int m, const double* weights,
                                                         const double* cosines, const double* sines,
                                                         const double* pads, double* u, double* v) {
    for (int j = 0; j < m; ++j) {
        const double* w = weights + j * knots;
        V s = splat<V>(0.0);
        for (int k = 0; k < knots; ++k) s += w[k] * load<V>(pads + k * kL);
        store(u + j * kL, s * cosines[j]);
        store(v + j * kL, s * sines[j]);
    }
    store(u + m * kL, load<V>(u));
    store(v + m * kL, load<V>(v));
}

// Shoelace area and centroid (SectionAnalyzer::analyse).
template <class V>
__attribute__((always_inline)) inline void shoelaceSums(int m, const double* u, const double* v,
                                                        int offset, LaneSums& out) {
    V twiceArea = splat<V>(0.0), cu = splat<V>(0.0), cv = splat<V>(0.0);
    for (int j = 0; j < m; ++j) {
        const V uj = row<V>(u, j), uk = row<V>(u, j + 1), vj = row<V>(v, j), vk = row<V>(v, j + 1);
        const V cross = uj * vk - uk * vj;
        twiceArea += cross;
        cu += (uj + uk) * cross;
        cv += (vj + vk) * cross;
    }
    store(out.twiceArea + offset, twiceArea);
    store(out.cu + offset, cu);
    store(out.cv + offset, cv);
}

// fitEllipse's normal equations, of the points about their mean divided by
// `scale`: the mean of |u - mean u| + |v - mean v|, or 1 where that is 0.
template <class V>
struct NormalEquations {
    V mat[5][5];
    V rhs[5];
    V scale;
};

template <class V>
__attribute__((always_inline)) inline NormalEquations<V> normalEquations(int m, const double* u,
                                                                         const double* v) {
    V mx = splat<V>(0.0), my = splat<V>(0.0), scale = splat<V>(0.0);
    for (int i = 0; i < m; ++i) {
        mx += row<V>(u, i);
        my += row<V>(v, i);
    }
    mx /= static_cast<double>(m);
    my /= static_cast<double>(m);
    for (int i = 0; i < m; ++i) scale += absolute(row<V>(u, i) - mx) + absolute(row<V>(v, i) - my);
    scale = scale > 0.0 ? scale / static_cast<double>(m) : splat<V>(1.0);
    const V inv = 1.0 / scale;
    V sxxxx = splat<V>(0.0), sxxxy = sxxxx, sxxyy = sxxxx, sxyyy = sxxxx, syyyy = sxxxx,
      sxxx = sxxxx, sxxy = sxxxx, sxyy = sxxxx, syyy = sxxxx, sxx = sxxxx, sxy = sxxxx, syy = sxxxx,
      sx = sxxxx, sy = sxxxx;
    for (int i = 0; i < m; ++i) {
        const V x = (row<V>(u, i) - mx) * inv, y = (row<V>(v, i) - my) * inv;
        const V xx = x * x, xy = x * y, yy = y * y;
        sxxxx += xx * xx;
        sxxxy += xx * xy;
        sxxyy += xx * yy;
        sxyyy += xy * yy;
        syyyy += yy * yy;
        sxxx += xx * x;
        sxxy += xx * y;
        sxyy += x * yy;
        syyy += yy * y;
        sxx += xx;
        sxy += xy;
        syy += yy;
        sx += x;
        sy += y;
    }
    return {{{sxxxx, sxxxy, sxxyy, sxxx, sxxy},
             {sxxxy, sxxyy, sxyyy, sxxy, sxyy},
             {sxxyy, sxyyy, syyyy, sxyy, syyy},
             {sxxx, sxxy, sxyy, sxx, sxy},
             {sxxy, sxyy, syyy, sxy, syy}},
            {sxx, sxy, syy, sx, sy},
            scale};
}

// The 5x5 Cholesky solve of fitEllipse, in place: rhs becomes the solution.
// A lane whose pivot fails goes on with NaNs and is false in the mask.
template <class V>
__attribute__((always_inline)) inline MaskOf<V> choleskySolve(V (&mat)[5][5], V (&rhs)[5]) {
    MaskOf<V> ok = MaskOf<V>{} - 1;
    for (int j = 0; j < 5; ++j) {
        V d = mat[j][j];
        for (int k = 0; k < j; ++k) d -= mat[j][k] * mat[j][k];
        ok &= d > 1e-300;
        d = squareRoot(d);
        mat[j][j] = d;
        for (int i = j + 1; i < 5; ++i) {
            V s = mat[i][j];
            for (int k = 0; k < j; ++k) s -= mat[i][k] * mat[j][k];
            mat[i][j] = s / d;
        }
    }
    for (int i = 0; i < 5; ++i) {
        V s = rhs[i];
        for (int k = 0; k < i; ++k) s -= mat[i][k] * rhs[k];
        rhs[i] = s / mat[i][i];
    }
    for (int i = 4; i >= 0; --i) {
        V s = rhs[i];
        for (int k = i + 1; k < 5; ++k) s -= mat[k][i] * rhs[k];
        rhs[i] = s / mat[i][i];
    }
    return ok;
}

// Per lane, the operations of PeriodicSplineSampler::sample,
// SectionAnalyzer::analyse and fitEllipse in their order: no sum is reordered
// and no product fused (the library is built with -ffp-contract=off), so each
// lane's result is bit-identical to the one-section code whatever the vector
// width. Lanes [offset, offset + width) of the batch; pads, u and v hold kL
// values per row (u and v: m + 1 rows, the last repeating the first).
template <class V>
__attribute__((always_inline)) inline void laneSums(int knots, int m, const double* weights,
                                                    const double* cosines, const double* sines,
                                                    const double* pads, double* u, double* v,
                                                    int offset, LaneSums& out) {
    pads += offset;
    u += offset;
    v += offset;
    sampleOutline<V>(knots, m, weights, cosines, sines, pads, u, v);
    shoelaceSums<V>(m, u, v, offset, out);
    if (m < 5) {
        for (int l = 0; l < kWidth<V>; ++l) out.fitted[offset + l] = false;
        return;
    }

    // fitEllipse: the conic, its centre and its constant.
    NormalEquations<V> eq = normalEquations<V>(m, u, v);
    MaskOf<V> ok = choleskySolve(eq.mat, eq.rhs);
    const V A = eq.rhs[0], B = eq.rhs[1], C = eq.rhs[2], D = eq.rhs[3], E = eq.rhs[4];
    const V det = 4.0 * A * C - B * B;
    const V x0 = (B * E - 2.0 * C * D) / det;
    const V y0 = (B * D - 2.0 * A * E) / det;
    const V k = 1.0 - (A * x0 * x0 + B * x0 * y0 + C * y0 * y0 + D * x0 + E * y0);
    store(out.a + offset, A);
    store(out.b + offset, B);
    store(out.c + offset, C);
    store(out.d + offset, D);
    store(out.e + offset, E);
    store(out.k + offset, k);
    store(out.scale + offset, eq.scale);
    ok &= (det > 0.0) & (k > 0.0);
    for (int l = 0; l < kWidth<V>; ++l) out.fitted[offset + l] = ok[l] != 0;
}

// ThreadSanitizer instruments the clones' resolver, which the dynamic loader
// runs before the sanitizer's runtime is up: no clones in such a build.
#if defined(__SANITIZE_THREAD__)
#define CALIPER3D_SIMD_CLONES
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define CALIPER3D_SIMD_CLONES
#endif
#endif
#ifndef CALIPER3D_SIMD_CLONES
#define CALIPER3D_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#endif

// The batch as two halves of four lanes: one AVX2 register per vector in the
// AVX2 clone (picked by the dynamic loader), two SSE2 registers otherwise.
CALIPER3D_SIMD_CLONES void batchSums4(int knots, int m, const double* weights,
                                      const double* cosines, const double* sines,
                                      const double* pads, double* u, double* v, LaneSums& out) {
    laneSums<Lanes4>(knots, m, weights, cosines, sines, pads, u, v, 0, out);
    laneSums<Lanes4>(knots, m, weights, cosines, sines, pads, u, v, 4, out);
}

// The batch as one AVX-512 vector: twice the lanes per instruction where the
// processor has them (the machines we measure on do).
#if defined(__x86_64__) || defined(__i386__)
#define CALIPER3D_HAS_AVX512_PATH 1
__attribute__((target("avx512f"))) void batchSums8(int knots, int m, const double* weights,
                                                   const double* cosines, const double* sines,
                                                   const double* pads, double* u, double* v,
                                                   LaneSums& out) {
    laneSums<Lanes8>(knots, m, weights, cosines, sines, pads, u, v, 0, out);
}
#endif

bool haveAvx512() {
#if defined(CALIPER3D_HAS_AVX512_PATH)
    return __builtin_cpu_supports("avx512f");
#else
    return false;
#endif
}

// SectionAnalyzer::analyse's fallback when no ellipse fits: the ellipse of
// the same second moments, from the sums it would have accumulated beside the
// area (Steger 1996), and its angle the way analyse computes it.
void momentEllipse(const double* u, const double* v, int m, int lane, double area, BatchShape& s,
                   double& majorAngle_deg) {
    double suu = 0.0, svv = 0.0, suv = 0.0;
    for (int j = 0; j < m; ++j) {
        const double uj = u[j * kL + lane], uk = u[(j + 1) * kL + lane];
        const double vj = v[j * kL + lane], vk = v[(j + 1) * kL + lane];
        const double cross = uj * vk - uk * vj;
        suu += (uj * uj + uj * uk + uk * uk) * cross;
        svv += (vj * vj + vj * vk + vk * vk) * cross;
        suv += (uj * vk + 2.0 * uj * vj + 2.0 * uk * vk + uk * vj) * cross;
    }
    const double iuu = suu / (12.0 * area) - s.centroidU_mm * s.centroidU_mm;
    const double ivv = svv / (12.0 * area) - s.centroidV_mm * s.centroidV_mm;
    const double iuv = suv / (24.0 * area) - s.centroidU_mm * s.centroidV_mm;
    const double mean = (iuu + ivv) / 2.0, diff = std::hypot((iuu - ivv) / 2.0, iuv);
    s.dmax_mm = 4.0 * std::sqrt(std::max(mean + diff, 0.0));
    s.dmin_mm = 4.0 * std::sqrt(std::max(mean - diff, 0.0));
    const double angle = glm::degrees(0.5 * std::atan2(2.0 * iuv, iuu - ivv));
    majorAngle_deg = angle < 0.0 ? angle + 180.0 : angle;
}

}  // namespace

double majorAngle_deg(const BatchShape& s) {
    if (!s.ellipseFitted) return s.unfittedAngle_deg;
    // fitEllipse's angle, then analyse's degrees and fold.
    const double pi = boost::math::constants::pi<double>();
    double angle = 0.5 * std::atan2(s.conicB, s.conicAMinusC) + pi / 2.0;
    angle = std::fmod(angle, pi);
    if (angle < 0.0) angle += pi;
    double deg = glm::degrees(angle);
    if (deg >= 180.0) deg -= 180.0;
    return deg;
}

SectionBatchAnalyzer::SectionBatchAnalyzer(int knots, int samples, Width width)
    : m_knots(knots), m_samples(samples), m_wide(width == Width::Widest && haveAvx512()) {
    const PeriodicSplineSampler sampler(knots, samples);
    m_weights.assign(sampler.weights(),
                     sampler.weights() + static_cast<std::size_t>(knots) * samples);
    m_cos.resize(static_cast<std::size_t>(samples));
    m_sin.resize(static_cast<std::size_t>(samples));
    for (int j = 0; j < samples; ++j) {
        const double phi = kTwoPi * j / samples;
        m_cos[static_cast<std::size_t>(j)] = std::cos(phi);
        m_sin[static_cast<std::size_t>(j)] = std::sin(phi);
    }
}

void SectionBatchAnalyzer::analyse(const double* pads, BatchShape* out,
                                   Workspace& workspace) const {
    const int m = m_samples;
    LaneSums sums;
    double* u = workspace.data();
    double* v = u + (m + 1) * kL;
    if (m_wide)
        batchSums8(m_knots, m, m_weights.data(), m_cos.data(), m_sin.data(), pads, u, v, sums);
    else
        batchSums4(m_knots, m, m_weights.data(), m_cos.data(), m_sin.data(), pads, u, v, sums);
    for (int l = 0; l < kL; ++l) {
        BatchShape& s = out[l];
        s = BatchShape{};
        const double area = sums.twiceArea[l] / 2.0;
        s.area_mm2 = std::abs(area);
        s.equivalentDiameter_mm =
            2.0 * std::sqrt(s.area_mm2 / boost::math::constants::pi<double>());
        if (area != 0.0) {
            s.centroidU_mm = sums.cu[l] / (6.0 * area);
            s.centroidV_mm = sums.cv[l] / (6.0 * area);
        }
        s.centreOffset_mm = std::hypot(s.centroidU_mm, s.centroidV_mm);

        // fitEllipse's eigenvalues of [[A, B/2], [B/2, C]] and axes.
        bool fitted = sums.fitted[l];
        const double A = sums.a[l], B = sums.b[l], C = sums.c[l];
        double halfDiff = 0.0, diff = 0.0;
        if (fitted) {
            const double mean = (A + C) / 2.0;
            halfDiff = (A - C) / 2.0;
            diff = std::hypot(halfDiff, B / 2.0);
            const double lambdaMin = mean - diff, lambdaMax = mean + diff;
            fitted = lambdaMin > 0.0;
            if (fitted) {
                s.dmax_mm = 2.0 * std::sqrt(sums.k[l] / lambdaMin) * sums.scale[l];
                s.dmin_mm = 2.0 * std::sqrt(sums.k[l] / lambdaMax) * sums.scale[l];
            }
        }
        if (fitted) {
            s.ellipseFitted = true;
            s.conicAMinusC = A - C;
            s.conicB = B;
            // The major axis is the eigenvector of the smaller eigenvalue, at
            // phi + 90 deg with 2 phi = atan2(B, A - C) (fitEllipse); its cosine
            // and sine by the half-angle formulas, each branch free of cancellation.
            double cosPhi = 1.0, sinPhi = 0.0;  // atan2(+-0, +0) = +-0
            if (diff > 0.0) {
                const double cos2 = halfDiff / diff, sin2 = (B / 2.0) / diff;
                if (cos2 >= 0.0) {
                    cosPhi = std::sqrt((1.0 + cos2) / 2.0);
                    sinPhi = sin2 / (2.0 * cosPhi);
                } else {
                    sinPhi = std::copysign(std::sqrt((1.0 - cos2) / 2.0), sin2);
                    cosPhi = sin2 / (2.0 * sinPhi);
                }
            }
            s.majorU = -sinPhi;
            s.majorV = cosPhi;
            if (s.majorV == 0.0) {  // 180 deg, which fitEllipse folds to 0
                s.majorU = 1.0;
                s.majorV = 0.0;
            }
        } else {
            double majorAngle_deg = 0.0;
            if (area != 0.0) momentEllipse(u, v, m, l, area, s, majorAngle_deg);
            if (majorAngle_deg >= 180.0) majorAngle_deg -= 180.0;
            s.unfittedAngle_deg = majorAngle_deg;
            // The direction exactly as SectionFrame::direction takes it.
            const double angle = glm::radians(majorAngle_deg);
            s.majorU = std::cos(angle);
            s.majorV = std::sin(angle);
        }
        s.ellipticity = s.dmin_mm > 0.0 ? s.dmax_mm / s.dmin_mm : 0.0;
    }
}

}  // namespace caliper3d::reconstruction
