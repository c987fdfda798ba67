#pragma once
// Principal stresses and directions of a symmetric tensor in Voigt form, and the derivative of
// an isotropic tensor function given by its principal values.

#include "io/types.hpp"

namespace grainload::materials {

/// The spectral form of a symmetric tensor: values in descending order, values(0) >=
/// values(1) >= values(2) (tension positive: values(2) is the most compressive), column i of
/// `directions` the unit eigenvector of values(i).
struct PrincipalStresses {
    Vec3 values;
    Mat3 directions;
};

/// The principal values and directions of a stress-like Voigt vector.
PrincipalStresses principal_stresses(const Voigt6& stress);

/// The stress-like Voigt vector sum_i values(i) n_i (x) n_i, n_i = directions.col(i).
Voigt6 from_principal(const Vec3& values, const Mat3& directions);

/// d sigma / d sigma_trial as a matrix on stress-like Voigt vectors, for an isotropic function
/// sigma(sigma_trial) that keeps the principal directions and maps the principal values
/// trial_values -> values with Jacobian d values_i / d trial_values_j = jacobian(i, j).
/// In the principal frame the normal components change by the Jacobian and a shear component
/// ij by (values_i - values_j) / (trial_i - trial_j) (the spin of the common directions; e.g.
/// de Souza Neto, Peric & Owen, "Computational Methods for Plasticity" (2008), appendix A);
/// where trial_i = trial_j that ratio is its limit jacobian(i, i) - jacobian(i, j).
Matrix6 isotropic_function_derivative(const Mat3& jacobian, const Vec3& values,
                                      const Vec3& trial_values, const Mat3& directions);

} // namespace grainload::materials
