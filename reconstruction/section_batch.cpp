#include "reconstruction/section_batch.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <boost/math/constants/constants.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/periodic_spline.h"

namespace caliper3d::reconstruction {

namespace {

constexpr int kL = SectionBatchAnalyzer::kLanes;
constexpr double kTwoPi = boost::math::constants::two_pi<double>();

// kL sections side by side, one per element. GCC and Clang vector extensions
// do element-wise IEEE arithmetic, so each element gets exactly the value the
// scalar code computes, and they lower the type to whatever SIMD the function
// is compiled for (two SSE2 registers by default, one AVX2 register in the
// AVX2 clone), which auto-vectorisation of per-lane loops did not do well.
// The lanes never cross a call that is not inlined by value, so GCC's note
// that passing them by value changes the ABI without AVX does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"
typedef double Lanes __attribute__((vector_size(kL * sizeof(double))));
typedef long long LaneMask __attribute__((vector_size(kL * sizeof(long long))));

inline Lanes load(const double* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline Lanes splat(double x) {
    return Lanes{} + x;
}
// std::abs of each element: the sign bit cleared.
inline Lanes absolute(Lanes x) {
    return reinterpret_cast<Lanes>(reinterpret_cast<LaneMask>(x) & 0x7fffffffffffffffLL);
}
inline Lanes squareRoot(Lanes x) {
    for (int l = 0; l < kL; ++l) x[l] = std::sqrt(x[l]);
    return x;
}

// What the vectorised part leaves for each lane: the shoelace sums and the
// least-squares conic a x^2 + b xy + c y^2 + d x + e y = 1 about the points'
// mean, with `fitted` false where fitEllipse gives up before its eigenvalues
// (singular normal equations, not an ellipse).
struct LaneSums {
    Lanes twiceArea, cu, cv;
    Lanes a, b, c, d, e;
    Lanes k, scale;
    LaneMask fitted;
};

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

// Per lane, the operations of PeriodicSplineSampler::sample,
// SectionAnalyzer::analyse and fitEllipse in their order: no sum is reordered
// and no product fused (the library is built with -ffp-contract=off), so each
// lane's result is bit-identical to the one-section code whichever clone runs.
// The clones only change how many lanes one instruction takes; the dynamic
// loader picks one once per process.
CALIPER3D_SIMD_CLONES void analyseLanes(int knots, int m, const double* weights,
                                        const double* cosines, const double* sines,
                                        const double* pads, Lanes* u, LaneSums& out) {
    Lanes* v = u + (m + 1);  // u and v: m + 1 rows each, the last repeating the first
    for (int j = 0; j < m; ++j) {
        const double* w = weights + j * knots;
        Lanes s = splat(0.0);
        for (int k = 0; k < knots; ++k) s += w[k] * load(pads + k * kL);
        u[j] = s * cosines[j];
        v[j] = s * sines[j];
    }
    u[m] = u[0];
    v[m] = v[0];

    // Shoelace area and centroid (SectionAnalyzer::analyse).
    Lanes twiceArea = splat(0.0), cu = splat(0.0), cv = splat(0.0);
    for (int j = 0; j < m; ++j) {
        const Lanes cross = u[j] * v[j + 1] - u[j + 1] * v[j];
        twiceArea += cross;
        cu += (u[j] + u[j + 1]) * cross;
        cv += (v[j] + v[j + 1]) * cross;
    }
    out.twiceArea = twiceArea;
    out.cu = cu;
    out.cv = cv;
    out.fitted = LaneMask{} + (m >= 5 ? -1LL : 0LL);
    if (m < 5) return;

    // fitEllipse: mean, scale, normal equations.
    Lanes mx = splat(0.0), my = splat(0.0), scale = splat(0.0);
    for (int i = 0; i < m; ++i) {
        mx += u[i];
        my += v[i];
    }
    mx /= static_cast<double>(m);
    my /= static_cast<double>(m);
    for (int i = 0; i < m; ++i) scale += absolute(u[i] - mx) + absolute(v[i] - my);
    scale = scale > 0.0 ? scale / static_cast<double>(m) : splat(1.0);
    const Lanes inv = 1.0 / scale;
    Lanes sxxxx = splat(0.0), sxxxy = sxxxx, sxxyy = sxxxx, sxyyy = sxxxx, syyyy = sxxxx,
          sxxx = sxxxx, sxxy = sxxxx, sxyy = sxxxx, syyy = sxxxx, sxx = sxxxx, sxy = sxxxx,
          syy = sxxxx, sx = sxxxx, sy = sxxxx;
    for (int i = 0; i < m; ++i) {
        const Lanes x = (u[i] - mx) * inv, y = (v[i] - my) * inv;
        const Lanes xx = x * x, xy = x * y, yy = y * y;
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

    // The 5x5 Cholesky solve of fitEllipse; a lane whose pivot fails goes on
    // with NaNs and is marked not fitted.
    Lanes mat[5][5] = {{sxxxx, sxxxy, sxxyy, sxxx, sxxy},
                       {sxxxy, sxxyy, sxyyy, sxxy, sxyy},
                       {sxxyy, sxyyy, syyyy, sxyy, syyy},
                       {sxxx, sxxy, sxyy, sxx, sxy},
                       {sxxy, sxyy, syyy, sxy, syy}};
    Lanes rhs[5] = {sxx, sxy, syy, sx, sy};
    LaneMask ok = LaneMask{} - 1;
    for (int j = 0; j < 5; ++j) {
        Lanes d = mat[j][j];
        for (int k = 0; k < j; ++k) d -= mat[j][k] * mat[j][k];
        ok &= d > 1e-300;
        d = squareRoot(d);
        mat[j][j] = d;
        for (int i = j + 1; i < 5; ++i) {
            Lanes s = mat[i][j];
            for (int k = 0; k < j; ++k) s -= mat[i][k] * mat[j][k];
            mat[i][j] = s / d;
        }
    }
    for (int i = 0; i < 5; ++i) {
        Lanes s = rhs[i];
        for (int k = 0; k < i; ++k) s -= mat[i][k] * rhs[k];
        rhs[i] = s / mat[i][i];
    }
    for (int i = 4; i >= 0; --i) {
        Lanes s = rhs[i];
        for (int k = i + 1; k < 5; ++k) s -= mat[k][i] * rhs[k];
        rhs[i] = s / mat[i][i];
    }
    const Lanes A = rhs[0], B = rhs[1], C = rhs[2], D = rhs[3], E = rhs[4];
    const Lanes det = 4.0 * A * C - B * B;
    const Lanes x0 = (B * E - 2.0 * C * D) / det;
    const Lanes y0 = (B * D - 2.0 * A * E) / det;
    const Lanes k = 1.0 - (A * x0 * x0 + B * x0 * y0 + C * y0 * y0 + D * x0 + E * y0);
    out.a = A;
    out.b = B;
    out.c = C;
    out.d = D;
    out.e = E;
    out.k = k;
    out.scale = scale;
    out.fitted = ok & (det > 0.0) & (k > 0.0);
}

// SectionAnalyzer::analyse's fallback when no ellipse fits: the ellipse of
// the same second moments, from the sums it would have accumulated beside the
// area (Steger 1996), and its angle the way analyse computes it.
void momentEllipse(const Lanes* u, const Lanes* v, int m, int lane, double area, BatchShape& s,
                   double& majorAngle_deg) {
    double suu = 0.0, svv = 0.0, suv = 0.0;
    for (int j = 0; j < m; ++j) {
        const double uj = u[j][lane], uk = u[j + 1][lane];
        const double vj = v[j][lane], vk = v[j + 1][lane];
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

SectionBatchAnalyzer::SectionBatchAnalyzer(int knots, int samples)
    : m_knots(knots), m_samples(samples) {
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
    Lanes* u = workspace.lanes<Lanes>();
    const Lanes* v = u + (m + 1);
    analyseLanes(m_knots, m, m_weights.data(), m_cos.data(), m_sin.data(), pads, u, sums);
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
