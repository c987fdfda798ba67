#include "sph/kernels.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace grainload::sph {

KernelType kernel_type_from_name(std::string_view name) {
    if (name == "cubic_spline") {
        return KernelType::cubic_spline;
    }
    if (name == "quintic_spline") {
        return KernelType::quintic_spline;
    }
    if (name == "wendland_c2") {
        return KernelType::wendland_c2;
    }
    throw std::invalid_argument("unknown kernel \"" + std::string(name) +
                                "\" (expected cubic_spline, quintic_spline or wendland_c2)");
}

std::string_view kernel_name(KernelType type) {
    switch (type) {
    case KernelType::cubic_spline:
        return "cubic_spline";
    case KernelType::quintic_spline:
        return "quintic_spline";
    case KernelType::wendland_c2:
        break;
    }
    return "wendland_c2";
}

SmoothingKernel::SmoothingKernel(KernelType type, double smoothing_length, int dimension)
    : type_(type), dimension_(dimension), h_(smoothing_length), inverse_h_(1.0 / smoothing_length),
      support_(0.0), alpha_(0.0) {
    if (dimension != 2 && dimension != 3) {
        throw std::invalid_argument("kernel dimension must be 2 or 3");
    }
    if (!(smoothing_length > 0.0)) {
        throw std::invalid_argument("smoothing length must be positive");
    }
    double norm = 0.0;
    switch (type) {
    case KernelType::cubic_spline:
        support_ = CubicSplineKernel::support;
        norm = CubicSplineKernel::normalisation(dimension);
        break;
    case KernelType::quintic_spline:
        support_ = QuinticSplineKernel::support;
        norm = QuinticSplineKernel::normalisation(dimension);
        break;
    case KernelType::wendland_c2:
        support_ = WendlandC2Kernel::support;
        norm = WendlandC2Kernel::normalisation(dimension);
        break;
    }
    alpha_ = norm / std::pow(smoothing_length, dimension);
}

} // namespace grainload::sph
