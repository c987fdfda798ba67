#pragma once
// The keys of a [[material]] table that every model shares.

#include "io/key_spec.hpp"

#include <array>

namespace grainload::materials {

/// The keys of each [[material]] table that every model shares (docs/user-guide.md); a model's
/// own keys are declared with the model.
inline constexpr std::array<io::KeySpec, 10> kMaterialKeys{{
    {"name", "string", "", "unique name; bodies and shells refer to it"},
    {"model", "string", "required unless `from_lsdyna`",
     "`linear_elastic`, `von_mises`, `drucker_prager`, `generalized_cap`, `mu_i` or "
     "`mohr_coulomb`"},
    {"density", "density", "required unless `from_lsdyna`", "the bulk density, > 0"},
    {"youngs_modulus", "pressure", "one pair required", "E, with `poisson_ratio`"},
    {"poisson_ratio", "number", "one pair required", "ν in (−1, 0.5), with `youngs_modulus`"},
    {"bulk_modulus", "pressure", "one pair required", "K, with `shear_modulus`"},
    {"shear_modulus", "pressure", "one pair required", "G, with `bulk_modulus`"},
    {"grain_size", "length", "none (a continuum)",
     "the mean grain diameter d of a granular material (Beverloo's k d, mu(I)'s inertial number)"},
    {"stiffness_scale", "number > 0", "1",
     "multiplies K and G (a softer material for a longer explicit step)", 1.0},
    {"from_lsdyna", "table", "none",
     "`{file, mid, units}`: the material is a deck's *MAT_GEOLOGIC_CAP_MODEL card"},
}};

} // namespace grainload::materials
