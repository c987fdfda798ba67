#pragma once

#include "io/types.hpp"

namespace grainload::io {
class CaseTable;
}

namespace grainload::materials {

/// Isotropic elastic constants and density, SI. Every material carries one.
struct ElasticConstants {
    double density = 0.0;
    double bulk_modulus = 0.0;
    double shear_modulus = 0.0;

    static ElasticConstants from_young(double density, double young, double poisson);
    static ElasticConstants from_bulk_shear(double density, double bulk, double shear);
    /// Reads density and either (youngs_modulus, poisson_ratio) or (bulk_modulus,
    /// shear_modulus) from a [[material]] table; refuses both or neither.
    static ElasticConstants from_case(const io::CaseTable& table);

    double young() const;
    double poisson() const;
    double lame_lambda() const { return bulk_modulus - 2.0 * shear_modulus / 3.0; }
    /// P-wave speed sqrt((K + 4G/3)/rho), used for the CFL condition (thesis section 4.7).
    double p_wave_speed() const;
    /// Isotropic stiffness in the Voigt convention of io/types.hpp (engineering shear strains).
    Matrix6 stiffness() const;
};

} // namespace grainload::materials
