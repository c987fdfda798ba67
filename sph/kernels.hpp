#pragma once
// The SPH smoothing kernels: cubic and quintic splines, Wendland C2.

#include "io/types.hpp"

#include <numbers>
#include <string_view>

namespace grainload::sph {

// Smoothing kernels W(r, h) = alpha_d f(q), q = r/h. Each shape gives f(q), f'(q), its support
// radius in units of h and the normalisation alpha_d h^d (so that the integral of W over the
// plane/space is 1). The normalisations are recomputed by integration in the unit tests.

/// Cubic B-spline, thesis eq. (4.3.1.18); support 2h.
struct CubicSplineKernel {
    static constexpr double support = 2.0;
    static double shape(double q) {
        if (q < 1.0) {
            return 2.0 / 3.0 - q * q + 0.5 * q * q * q;
        }
        if (q < 2.0) {
            const double t = 2.0 - q;
            return t * t * t / 6.0;
        }
        return 0.0;
    }
    static double shape_derivative(double q) { return q < 2.0 ? shape_derivative_inside(q) : 0.0; }
    /// shape_derivative(q) for q < 2, without a branch: both pieces evaluated, one selected.
    static double shape_derivative_inside(double q) {
        const double t = 2.0 - q;
        const double inner = -2.0 * q + 1.5 * q * q;
        const double outer = -0.5 * t * t;
        return q < 1.0 ? inner : outer;
    }
    /// Thesis: 2D 15/(7 pi), 3D 3/(2 pi).
    static double normalisation(int dimension) {
        return dimension == 2 ? 15.0 / (7.0 * std::numbers::pi) : 3.0 / (2.0 * std::numbers::pi);
    }
};

/// Quintic spline, thesis eq. (4.3.1.19); support 3h. The thesis gives 3/(359 pi) in 3D (the
/// value often quoted from Liu & Liu); integration gives 1/(120 pi), which is used here (the
/// thesis' 1D value 120/h is likewise 1/(120 h)).
struct QuinticSplineKernel {
    static constexpr double support = 3.0;
    static double shape(double q) {
        const double a = q < 3.0 ? pow5(3.0 - q) : 0.0;
        const double b = q < 2.0 ? pow5(2.0 - q) : 0.0;
        const double c = q < 1.0 ? pow5(1.0 - q) : 0.0;
        return a - 6.0 * b + 15.0 * c;
    }
    static double shape_derivative(double q) {
        const double a = q < 3.0 ? pow4(3.0 - q) : 0.0;
        const double b = q < 2.0 ? pow4(2.0 - q) : 0.0;
        const double c = q < 1.0 ? pow4(1.0 - q) : 0.0;
        return -5.0 * (a - 6.0 * b + 15.0 * c);
    }
    static double shape_derivative_inside(double q) { return shape_derivative(q); }
    static double normalisation(int dimension) {
        return dimension == 2 ? 7.0 / (478.0 * std::numbers::pi) : 1.0 / (120.0 * std::numbers::pi);
    }

  private:
    static double pow4(double t) { return (t * t) * (t * t); }
    static double pow5(double t) { return pow4(t) * t; }
};

/// Wendland C2 (Wendland 1995; Dehnen & Aly 2012 scaling to support 2h):
/// f(q) = (1 - q/2)^4 (2q + 1); free of the pairing instability, better behaved for solids.
struct WendlandC2Kernel {
    static constexpr double support = 2.0;
    static double shape(double q) {
        if (q >= 2.0) {
            return 0.0;
        }
        const double t = 1.0 - 0.5 * q;
        return (t * t) * (t * t) * (2.0 * q + 1.0);
    }
    static double shape_derivative(double q) {
        if (q >= 2.0) {
            return 0.0;
        }
        const double t = 1.0 - 0.5 * q;
        return -5.0 * q * t * t * t;
    }
    /// shape_derivative(q) for q < 2.
    static double shape_derivative_inside(double q) { return shape_derivative(q); }
    static double normalisation(int dimension) {
        return dimension == 2 ? 7.0 / (4.0 * std::numbers::pi) : 21.0 / (16.0 * std::numbers::pi);
    }
};

enum class KernelType { cubic_spline, quintic_spline, wendland_c2 };

/// "cubic_spline" | "quintic_spline" | "wendland_c2"; throws std::invalid_argument otherwise.
KernelType kernel_type_from_name(std::string_view name);
std::string_view kernel_name(KernelType type);

/// A kernel of fixed shape, smoothing length and dimension (2 = plane strain, 3). The shape is
/// picked by a switch that the branch predictor resolves once per loop; the hot loops call
/// value() and gradient() with no virtual dispatch.
class SmoothingKernel {
  public:
    SmoothingKernel(KernelType type, double smoothing_length, int dimension);

    KernelType type() const { return type_; }
    int dimension() const { return dimension_; }
    double smoothing_length() const { return h_; }
    /// Support radius (2h or 3h): pairs further apart do not interact.
    double support_radius() const { return support_ * h_; }

    double value(double r) const { return alpha_ * shape(r * inverse_h_); }
    /// dW/dr at distance r.
    double radial_derivative(double r) const {
        return alpha_ * inverse_h_ * shape_derivative(r * inverse_h_);
    }
    /// grad_i W(x_i - x_j) for the separation x_ij = x_i - x_j at distance r > 0.
    Vec3 gradient(const Vec3& x_ij, double r) const { return (radial_derivative(r) / r) * x_ij; }

    /// Calls visit(shape) with the kernel's shape (CubicSplineKernel{}, ...), so that a pair
    /// loop is compiled once per shape with the shape inlined (ShapeTerms below).
    template <class Visit> decltype(auto) visit_shape(Visit&& visit) const {
        switch (type_) {
        case KernelType::cubic_spline:
            return visit(CubicSplineKernel{});
        case KernelType::quintic_spline:
            return visit(QuinticSplineKernel{});
        case KernelType::wendland_c2:
            break;
        }
        return visit(WendlandC2Kernel{});
    }
    double normalisation_over_h_d() const { return alpha_; }
    double inverse_smoothing_length() const { return inverse_h_; }

  private:
    double shape(double q) const {
        switch (type_) {
        case KernelType::cubic_spline:
            return CubicSplineKernel::shape(q);
        case KernelType::quintic_spline:
            return QuinticSplineKernel::shape(q);
        case KernelType::wendland_c2:
            break;
        }
        return WendlandC2Kernel::shape(q);
    }
    double shape_derivative(double q) const {
        switch (type_) {
        case KernelType::cubic_spline:
            return CubicSplineKernel::shape_derivative(q);
        case KernelType::quintic_spline:
            return QuinticSplineKernel::shape_derivative(q);
        case KernelType::wendland_c2:
            break;
        }
        return WendlandC2Kernel::shape_derivative(q);
    }

    KernelType type_;
    int dimension_;
    double h_;
    double inverse_h_;
    double support_;
    double alpha_; ///< normalisation / h^d
};

/// A kernel's value and gradient factor with the shape fixed at compile time, for pair loops:
/// the same operations, in the same order, as SmoothingKernel::value() and gradient(), so a
/// loop that uses it reproduces the generic path bit for bit.
template <class Shape> struct ShapeTerms {
    explicit ShapeTerms(const SmoothingKernel& kernel)
        : inverse_h(kernel.inverse_smoothing_length()), alpha(kernel.normalisation_over_h_d()),
          alpha_over_h(alpha * inverse_h) {}
    double value(double r) const { return alpha * Shape::shape(r * inverse_h); }
    /// W'(r) / r: grad_i W_ij = gradient_factor(r) x_ij.
    double gradient_factor(double r) const {
        return alpha_over_h * Shape::shape_derivative(r * inverse_h) / r;
    }
    /// gradient_factor(r) for r inside the support: the same value, without a branch.
    double gradient_factor_inside(double r) const {
        return alpha_over_h * Shape::shape_derivative_inside(r * inverse_h) / r;
    }
    double inverse_h;
    double alpha;
    double alpha_over_h;
};

} // namespace grainload::sph
