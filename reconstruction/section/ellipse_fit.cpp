#include "reconstruction/section/ellipse_fit.h"

#include <cmath>

#include <boost/math/constants/constants.hpp>

namespace caliper3d::reconstruction {

namespace {

// Solves the symmetric positive definite 5x5 system m z = r in place (Cholesky).
bool solveCholesky5(double m[5][5], double r[5]) {
    for (int j = 0; j < 5; ++j) {
        double d = m[j][j];
        for (int k = 0; k < j; ++k) d -= m[j][k] * m[j][k];
        if (!(d > 1e-300)) return false;
        d = std::sqrt(d);
        m[j][j] = d;
        for (int i = j + 1; i < 5; ++i) {
            double s = m[i][j];
            for (int k = 0; k < j; ++k) s -= m[i][k] * m[j][k];
            m[i][j] = s / d;
        }
    }
    for (int i = 0; i < 5; ++i) {
        double s = r[i];
        for (int k = 0; k < i; ++k) s -= m[i][k] * r[k];
        r[i] = s / m[i][i];
    }
    for (int i = 4; i >= 0; --i) {
        double s = r[i];
        for (int k = i + 1; k < 5; ++k) s -= m[k][i] * r[k];
        r[i] = s / m[i][i];
    }
    return true;
}

}  // namespace

Ellipse fitEllipse(const double* x, const double* y, int n) {
    Ellipse out;
    if (n < 5) return out;
    double mx = 0.0, my = 0.0;
    for (int i = 0; i < n; ++i) {
        mx += x[i];
        my += y[i];
    }
    mx /= n;
    my /= n;
    double scale = 0.0;
    for (int i = 0; i < n; ++i) scale += std::abs(x[i] - mx) + std::abs(y[i] - my);
    scale = scale > 0.0 ? scale / n : 1.0;
    const double inv = 1.0 / scale;

    // Normal equations of the rows (x^2, xy, y^2, x, y) . p = 1, accumulated as
    // 15 distinct sums so that the loop vectorises.
    double sxxxx = 0, sxxxy = 0, sxxyy = 0, sxyyy = 0, syyyy = 0, sxxx = 0, sxxy = 0, sxyy = 0,
           syyy = 0, sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0;
    for (int i = 0; i < n; ++i) {
        const double u = (x[i] - mx) * inv, v = (y[i] - my) * inv;
        const double uu = u * u, uv = u * v, vv = v * v;
        sxxxx += uu * uu;
        sxxxy += uu * uv;
        sxxyy += uu * vv;
        sxyyy += uv * vv;
        syyyy += vv * vv;
        sxxx += uu * u;
        sxxy += uu * v;
        sxyy += u * vv;
        syyy += vv * v;
        sxx += uu;
        sxy += uv;
        syy += vv;
        sx += u;
        sy += v;
    }
    double m[5][5] = {{sxxxx, sxxxy, sxxyy, sxxx, sxxy},
                      {sxxxy, sxxyy, sxyyy, sxxy, sxyy},
                      {sxxyy, sxyyy, syyyy, sxyy, syyy},
                      {sxxx, sxxy, sxyy, sxx, sxy},
                      {sxxy, sxyy, syyy, sxy, syy}};
    double p[5] = {sxx, sxy, syy, sx, sy};
    if (!solveCholesky5(m, p)) return out;
    const double A = p[0], B = p[1], C = p[2], D = p[3], E = p[4];
    // Centre: gradient zero. Then A x'^2 + B x'y' + C y'^2 = -F_c about it.
    const double det = 4.0 * A * C - B * B;
    if (!(det > 0.0)) return out;  // a hyperbola or parabola, not an ellipse
    const double x0 = (B * E - 2.0 * C * D) / det;
    const double y0 = (B * D - 2.0 * A * E) / det;
    const double k = 1.0 - (A * x0 * x0 + B * x0 * y0 + C * y0 * y0 + D * x0 + E * y0);  // = -F_c
    if (!(k > 0.0)) return out;
    const double mean = (A + C) / 2.0, diff = std::hypot((A - C) / 2.0, B / 2.0);
    const double lambdaMin = mean - diff, lambdaMax = mean + diff;
    if (!(lambdaMin > 0.0)) return out;
    out.major = 2.0 * std::sqrt(k / lambdaMin) * scale;
    out.minor = 2.0 * std::sqrt(k / lambdaMax) * scale;
    // Eigenvector of the smaller eigenvalue of [[A, B/2], [B/2, C]] is the major axis.
    const double pi = boost::math::constants::pi<double>();
    double angle = 0.5 * std::atan2(B, A - C) + pi / 2.0;
    angle = std::fmod(angle, pi);
    if (angle < 0.0) angle += pi;
    out.majorAngle_rad = angle;
    out.centreX = mx + x0 * scale;
    out.centreY = my + y0 * scale;
    out.valid = true;
    return out;
}

}  // namespace caliper3d::reconstruction
