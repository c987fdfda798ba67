#pragma once
// The particles of an SPH body read from the *ELEMENT_SPH cards of an LS-DYNA deck.

#include "io/key_spec.hpp"
#include "io/types.hpp"

#include <array>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// Default of [sph.body.shape] `mass_tolerance`: the largest relative difference allowed between
/// a deck's particle mass and density * spacing^d. 1 %: a deck written for the same material
/// and spacing agrees to its printed digits (1e-6 and better), while a deck for another spacing
/// (a factor 1.25^3 = 1.95 in mass for 4 mm instead of 5 mm) or another density (dry sand
/// 1500-1700 kg/m^3 against saturated 2000) is off by far more.
inline constexpr double kDefaultMassTolerance = 0.01;

/// The keys of [sph.body.shape] type = "lsdyna" besides `file` (io::kSurfaceMeshKeys).
inline constexpr std::array<io::KeySpec, 3> kKeywordBodyKeys{{
    {"units", "string", "required for a deck",
     "the deck's unit system `LENGTH-MASS-TIME` (or LENGTH-FORCE-TIME), e.g. `mm-t-s`"},
    {"parts", "string, integer or a list of them", "every part with `*ELEMENT_SPH`",
     "the particles' parts, by *PART title or id"},
    {"mass_tolerance", "number", "0.01",
     "largest relative difference between a particle's deck mass and `density x spacing^d`",
     kDefaultMassTolerance},
}};

/// generate_body_points for [sph.body.shape] type = "lsdyna": the positions of the
/// *ELEMENT_SPH particles of the table's `parts` (titles or ids; default every part with
/// particles) in the deck `file`, whose units the table's `units` states (see
/// io::parse_keyword_units). The body keeps its own spacing and mass density * spacing^d per
/// particle; a deck mass (or volume, with _VOLUME or a negative MASS) that differs from that
/// (or from spacing^d) by more than `mass_tolerance` is refused, naming the first particle and
/// how many disagree; zero masses are not checked. In 2D the particles must lie in z = 0.
std::vector<Vec3> read_keyword_particles(const io::CaseTable& shape, double spacing, int dimension,
                                         double density);

} // namespace grainload::sph
