#pragma once
// The materials of a case: each [[material]] table checked, read and built by its model.

#include "io/key_spec.hpp"
#include "materials/material.hpp"
#include "materials/material_library.hpp"

#include <array>
#include <memory>
#include <string_view>

namespace grainload::io {
class CaseTable;
}

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

/// The keys of a [[material]] with model = "von_mises" besides density and the elastic pair.
inline constexpr std::array<io::KeySpec, 3> kVonMisesKeys{{
    {"yield_stress", "pressure", "", "σ_0, the initial uniaxial yield stress"},
    {"tangent_modulus", "pressure", "`\"0 Pa\"` (perfectly plastic)",
     "E_T, the uniaxial elasto-plastic slope, 0 ≤ E_T < E", 0.0},
    {"hardening_beta", "number", "1", "β: 1 isotropic, 0 kinematic, between: mixed", 1.0},
}};

/// The keys of a [[material]] with model = "drucker_prager" besides density and the elastic
/// pair: one of two forms, the Mohr-Coulomb angles with a cone fit, or the cone's own constants.
inline constexpr std::array<io::KeySpec, 8> kDruckerPragerKeys{{
    {"friction_angle", "angle", "required in form 1", "φ, 0 ≤ φ < 90°"},
    {"cohesion", "pressure", "required in form 1", "c ≥ 0"},
    {"dilatancy_angle", "angle", "required in form 1", "ψ, 0 ≤ ψ ≤ φ; ψ = φ is associated"},
    {"cone_fit", "string", "required in form 1",
     "`plane_strain`, `compression`, `extension` or `inner`: which Mohr-Coulomb angle the cone "
     "reproduces"},
    {"dp_k", "pressure", "required in form 2", "k of thesis 4.6.3.1"},
    {"dp_theta", "number", "required in form 2", "θ of thesis 4.6.3.1"},
    {"dp_theta_flow", "number", "`dp_theta`", "θ of the plastic potential, 0 ≤ θ_flow ≤ θ"},
    {"tension_cutoff", "pressure", "the apex k/α",
     "T: the limit on I1 = σ_xx + σ_yy + σ_zz (not on the mean stress)"},
}};

/// The keys of a [[material]] with model = "mohr_coulomb" besides density and the elastic pair
/// (docs/user-guide.md, "`mohr_coulomb`").
inline constexpr std::array<io::KeySpec, 3> kMohrCoulombKeys{{
    {"friction_angle", "angle", "", "φ, 0 < φ < 90°"},
    {"cohesion", "pressure", "", "c ≥ 0"},
    {"dilatancy_angle", "angle", "", "ψ, 0 ≤ ψ ≤ φ; ψ = φ is associated"},
}};

/// The keys of a [[material]] with model = "mu_i" besides density and the elastic pair
/// (docs/user-guide.md, "`mu_i`").
inline constexpr std::array<io::KeySpec, 8> kMuIKeys{{
    {"mu_s", "number", "required unless `angle_s`",
     "static friction mu_s = sqrt(J2)/p at rest (I = 0), > 0"},
    {"angle_s", "angle", "required unless `mu_s`", "the static friction as an angle: mu_s = tan"},
    {"mu_2", "number", "required unless `angle_2`",
     "limit friction mu_2 >= mu_s, reached as I grows without bound; below sqrt(3)"},
    {"angle_2", "angle", "required unless `mu_2`", "the limit friction as an angle: mu_2 = tan"},
    {"i0", "number", "", "I0 > 0: the inertial number at which mu is half-way from mu_s to mu_2"},
    {"grain_size", "length", "", "the grain diameter d of the inertial number (> 0)"},
    {"grain_density", "density", "",
     "rho_s, the density of the grains' solid (not the bulk density, which it must exceed)"},
    {"nonlocal_amplitude", "number", "none (local law)",
     "A > 0 turns on the non-local fluidity: cooperativity length xi = A d / sqrt|mu - mu_s|"},
}};

/// The keys of a [[material]]'s `from_lsdyna` table.
inline constexpr std::array<io::KeySpec, 3> kFromLsDynaKeys{{
    {"file", "string", "", "the deck, relative to the case file; `*INCLUDE`s are followed"},
    {"mid", "integer or string", "", "the material's MID (an integer id or a label)"},
    {"units", "string", "",
     "the deck's consistent unit system, `\"LENGTH-MASS-TIME\"` (`\"mm-t-s\"`, `\"m-kg-s\"`, "
     "...)"},
}};

/// The keys of a [[material]] with model = "generalized_cap" besides density and the elastic
/// pair (MAT_025's names in docs/user-guide.md).
inline constexpr std::array<io::KeySpec, 13> kGeneralizedCapKeys{{
    {"cap_k", "pressure", "required unless `cap_alpha`", "k (MAT_025's ALPHA)"},
    {"cap_alpha", "pressure", "required unless `cap_k`", "MAT_025's ALPHA: k by its LS-DYNA name"},
    {"cap_theta", "number", "", "θ, the envelope's slope in (I1, sqrt(J2))"},
    {"cap_gamma", "pressure", "", "γ (GAMMA)"},
    {"cap_beta", "1/pressure", "", "B1 (BETA)"},
    {"cap_R", "number", "", "R, the ellipse axis ratio (X − L)/B; 0 is a flat cap"},
    {"cap_D", "1/pressure", "", "D, the hardening law's exponent"},
    {"cap_W", "number", "", "W, the maximum plastic volumetric compaction"},
    {"cap_X0", "pressure", "", "X0, the initial intercept of the cap with the I1 axis"},
    {"tension_cutoff", "pressure", "0", "T ≥ 0 with I1 ≥ −T", 0.0},
    {"cap_toff", "pressure", "none", "MAT_025's TOFF ≤ 0 instead of `tension_cutoff`: T = −TOFF"},
    {"cap_semantics", "`mat025` or `lifted_x0`", "mat025",
     "`mat025`: X0 is the initial cap intercept as in LS-DYNA; `lifted_x0`: grainload's first "
     "cap semantics"},
    {"cap_ftype", "integer", "1", "FTYPE; 1 (soil/concrete) only", 1.0},
}};

/// Density and either (youngs_modulus, poisson_ratio) or (bulk_modulus, shear_modulus) of a
/// [[material]] table (refusing both or neither), K and G then multiplied by its
/// stiffness_scale.
ElasticConstants read_elastic_constants(const io::CaseTable& table);
/// The optional [[material]] key `stiffness_scale`, a number > 0.
double read_stiffness_scale(const io::CaseTable& table);

/// The material one [[material]] table describes: its `model` key picks the class and the
/// model's keys (above) its constants, or its `from_lsdyna` table names a deck's MAT_025 card
/// (materials/lsdyna_material.hpp; the keys the deck gives are refused beside it). The tables
/// of the other models it holds are read too, so that a mistake in a model the case can be
/// switched to is reported now.
std::unique_ptr<Material> read_material(const io::CaseTable& table);

/// Every [[material]] table of the case's root, by name (unique) with its grain size.
MaterialLibrary read_material_library(const io::CaseTable& root);
/// Index in `library` of the material called table[key]; a CaseError names the key if there is
/// none.
int read_material_index(const MaterialLibrary& library, const io::CaseTable& table,
                        std::string_view key);

} // namespace grainload::materials
