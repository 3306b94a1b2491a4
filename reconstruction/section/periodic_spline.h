#pragma once

#include <vector>

namespace caliper3d::reconstruction {

// Solves the cyclic tridiagonal system
//   sub[i] x[i-1] + diag[i] x[i] + super[i] x[i+1] = rhs[i]   (indices mod n)
// by the Sherman-Morrison correction of the Thomas algorithm (Press et al.,
// Numerical Recipes, 2.7). Boost has no cyclic tridiagonal solver, hence this.
// Requires n >= 3 and a diagonally dominant matrix.
std::vector<double> solveCyclicTridiagonal(const std::vector<double>& sub,
                                           const std::vector<double>& diag,
                                           const std::vector<double>& super,
                                           const std::vector<double>& rhs);

// Closed (periodic) natural cubic spline through n values at uniformly spaced
// parameters t = 0, 1, ..., n-1 with period n. The spline is C2 everywhere,
// the seam included, and passes through every value.
class PeriodicSpline {
public:
    explicit PeriodicSpline(std::vector<double> values);

    // Value at parameter t (any real; wrapped into [0, n)).
    double operator()(double t) const;
    // Derivatives with respect to t.
    double derivative(double t) const;
    double secondDerivative(double t) const;

    int size() const { return static_cast<int>(m_values.size()); }

private:
    std::vector<double> m_values;
    std::vector<double> m_second;  // second derivatives at the knots
};

// The spline's M samples at t = j*n/M are linear in the n knot values, so for
// fixed n and M they are a precomputed M x n weight matrix (one solve per unit
// vector, done once); sampling a section is then a small matrix-vector product.
class PeriodicSplineSampler {
public:
    PeriodicSplineSampler(int knots, int samples);

    int knots() const { return m_knots; }
    int samples() const { return m_samples; }

    // out[j] = spline through values[0..knots) at t = j*knots/samples.
    void sample(const double* values, double* out) const;
    // The weights: out[j] = sum over k of weights()[j * knots + k] * values[k].
    const double* weights() const { return m_weights.data(); }

private:
    int m_knots;
    int m_samples;
    std::vector<double> m_weights;  // samples x knots, row-major
};

}  // namespace caliper3d::reconstruction
