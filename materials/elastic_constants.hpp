#pragma once
// Isotropic elastic constants and density of a material, with its stiffness scale.

#include "io/types.hpp"

namespace grainload::materials {

/// Isotropic elastic constants and density, SI. Every material carries one.
struct ElasticConstants {
    double density = 0.0;
    double bulk_modulus = 0.0;
    double shear_modulus = 0.0;
    /// s of the case key `stiffness_scale`: bulk_modulus and shear_modulus above are the
    /// material's times s (a softer material for a longer explicit time step).
    double stiffness_scale = 1.0;

    static ElasticConstants from_young(double density, double young, double poisson);
    static ElasticConstants from_bulk_shear(double density, double bulk, double shear);
    /// The same material with K and G multiplied by s (on top of any earlier scale).
    ElasticConstants scaled(double s) const;

    double young() const;
    double poisson() const;
    double lame_lambda() const { return bulk_modulus - 2.0 * shear_modulus / 3.0; }
    /// P-wave speed sqrt((K + 4G/3)/rho), used for the CFL condition (thesis section 4.7).
    double p_wave_speed() const;
    /// The P-wave speed of the material before stiffness_scale, p_wave_speed() / sqrt(s): the
    /// sound speed of SPH's artificial viscosity, so that alpha c stays the real material's
    /// when the stiffness is scaled (docs/validation/column_collapse.md, "alpha c, not K").
    double unscaled_p_wave_speed() const;
    /// Isotropic stiffness in the Voigt convention of io/types.hpp (engineering shear strains).
    Matrix6 stiffness() const;
    /// The engineering strain of a stress, stiffness()^-1 * stress in closed form: the
    /// deviator over 2G on the normal components (shears over G, engineering) plus the mean
    /// stress over 3K.
    Voigt6 strain_from_stress(const Voigt6& stress) const {
        const double mean = (stress[0] + stress[1] + stress[2]) / 3.0;
        Voigt6 strain;
        for (int i = 0; i < 3; ++i) {
            strain[i] = (stress[i] - mean) / (2.0 * shear_modulus) + mean / (3.0 * bulk_modulus);
            strain[i + 3] = stress[i + 3] / shear_modulus;
        }
        return strain;
    }
    /// stiffness() * strain without forming the matrix: the same products and sums, in the
    /// order Eigen evaluates the 6x6 product (its zero terms left out), for the stress updates
    /// of every particle and step.
    Voigt6 stress_from_strain(const Voigt6& strain) const {
        const double lambda = lame_lambda();
        double diagonal = lambda;
        diagonal += 2.0 * shear_modulus;
        Voigt6 stress;
        for (int i = 0; i < 3; ++i) {
            double sum = (i == 0 ? diagonal : lambda) * strain[0];
            sum += (i == 1 ? diagonal : lambda) * strain[1];
            sum += (i == 2 ? diagonal : lambda) * strain[2];
            stress[i] = sum;
            stress[i + 3] = shear_modulus * strain[i + 3];
        }
        return stress;
    }
};

} // namespace grainload::materials
