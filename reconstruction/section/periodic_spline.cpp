#include "reconstruction/section/periodic_spline.h"

#include <cmath>
#include <stdexcept>

namespace caliper3d::reconstruction {

namespace {

std::vector<double> solveTridiagonal(std::vector<double> a, std::vector<double> b,
                                     std::vector<double> c, std::vector<double> r) {
    const std::size_t n = b.size();
    for (std::size_t i = 1; i < n; ++i) {
        const double m = a[i] / b[i - 1];
        b[i] -= m * c[i - 1];
        r[i] -= m * r[i - 1];
    }
    std::vector<double> x(n);
    x[n - 1] = r[n - 1] / b[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) x[i] = (r[i] - c[i] * x[i + 1]) / b[i];
    return x;
}

}  // namespace

std::vector<double> solveCyclicTridiagonal(const std::vector<double>& sub,
                                           const std::vector<double>& diag,
                                           const std::vector<double>& super,
                                           const std::vector<double>& rhs) {
    const std::size_t n = diag.size();
    if (n < 3 || sub.size() != n || super.size() != n || rhs.size() != n)
        throw std::invalid_argument("solveCyclicTridiagonal: need n >= 3 equal-sized arrays");
    // Corner elements: alpha = A[n-1][0] (sub[0] wraps), beta = A[0][n-1].
    const double alpha = super[n - 1];
    const double beta = sub[0];
    const double gamma = -diag[0];
    std::vector<double> bb(diag);
    bb[0] = diag[0] - gamma;
    bb[n - 1] = diag[n - 1] - alpha * beta / gamma;
    std::vector<double> a(sub), c(super);
    a[0] = 0.0;
    c[n - 1] = 0.0;
    std::vector<double> x = solveTridiagonal(a, bb, c, rhs);
    std::vector<double> u(n, 0.0);
    u[0] = gamma;
    u[n - 1] = alpha;
    std::vector<double> z = solveTridiagonal(a, bb, c, u);
    const double fact = (x[0] + beta * x[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
    for (std::size_t i = 0; i < n; ++i) x[i] -= fact * z[i];
    return x;
}

PeriodicSpline::PeriodicSpline(std::vector<double> values) : m_values(std::move(values)) {
    const std::size_t n = m_values.size();
    if (n < 3) throw std::invalid_argument("PeriodicSpline: need at least 3 values");
    // Uniform knots, h = 1: M[i-1] + 4 M[i] + M[i+1] = 6 (y[i+1] - 2 y[i] + y[i-1]).
    std::vector<double> sub(n, 1.0), diag(n, 4.0), super(n, 1.0), rhs(n);
    for (std::size_t i = 0; i < n; ++i) {
        rhs[i] = 6.0 * (m_values[(i + 1) % n] - 2.0 * m_values[i] + m_values[(i + n - 1) % n]);
    }
    m_second = solveCyclicTridiagonal(sub, diag, super, rhs);
}

namespace {
struct Span {
    std::size_t i0, i1;
    double u;
};
Span locate(double t, std::size_t n) {
    const double period = static_cast<double>(n);
    double w = std::fmod(t, period);
    if (w < 0) w += period;
    std::size_t i0 = static_cast<std::size_t>(w);
    if (i0 >= n) i0 = n - 1;
    return {i0, (i0 + 1) % n, w - static_cast<double>(i0)};
}
}  // namespace

double PeriodicSpline::operator()(double t) const {
    const Span s = locate(t, m_values.size());
    const double u = s.u, a = 1.0 - u;
    return a * m_values[s.i0] + u * m_values[s.i1] +
           ((a * a * a - a) * m_second[s.i0] + (u * u * u - u) * m_second[s.i1]) / 6.0;
}

double PeriodicSpline::derivative(double t) const {
    const Span s = locate(t, m_values.size());
    const double u = s.u, a = 1.0 - u;
    return m_values[s.i1] - m_values[s.i0] - (3.0 * a * a - 1.0) / 6.0 * m_second[s.i0] +
           (3.0 * u * u - 1.0) / 6.0 * m_second[s.i1];
}

double PeriodicSpline::secondDerivative(double t) const {
    const Span s = locate(t, m_values.size());
    return (1.0 - s.u) * m_second[s.i0] + s.u * m_second[s.i1];
}

PeriodicSplineSampler::PeriodicSplineSampler(int knots, int samples)
    : m_knots(knots), m_samples(samples) {
    if (knots < 3 || samples < 1)
        throw std::invalid_argument("PeriodicSplineSampler: need >= 3 knots and >= 1 sample");
    m_weights.assign(static_cast<std::size_t>(knots) * samples, 0.0);
    for (int k = 0; k < knots; ++k) {
        std::vector<double> unit(static_cast<std::size_t>(knots), 0.0);
        unit[static_cast<std::size_t>(k)] = 1.0;
        PeriodicSpline spline(std::move(unit));
        for (int j = 0; j < samples; ++j) {
            const double t = static_cast<double>(j) * knots / samples;
            m_weights[static_cast<std::size_t>(j) * knots + k] = spline(t);
        }
    }
}

void PeriodicSplineSampler::sample(const double* values, double* out) const {
    for (int j = 0; j < m_samples; ++j) {
        const double* w = m_weights.data() + static_cast<std::size_t>(j) * m_knots;
        double s = 0.0;
        for (int k = 0; k < m_knots; ++k) s += w[k] * values[k];
        out[j] = s;
    }
}

}  // namespace caliper3d::reconstruction
