#pragma once
// The scalar measures of a particle's stress that frames and probes write.

#include "io/types.hpp"

#include <cmath>

namespace grainload::sph {

/// Pressure, compression positive: -tr(sigma)/3.
inline double pressure_of(const Voigt6& s) {
    return -(s[0] + s[1] + s[2]) / 3.0;
}

/// von Mises equivalent stress sqrt(3/2 s:s) of the deviator s (tensor shear in Voigt order).
inline double von_mises_of(const Voigt6& s) {
    const double p = (s[0] + s[1] + s[2]) / 3.0;
    const double dev = (s[0] - p) * (s[0] - p) + (s[1] - p) * (s[1] - p) + (s[2] - p) * (s[2] - p) +
                       2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    return std::sqrt(1.5 * dev);
}

} // namespace grainload::sph
