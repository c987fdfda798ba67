#pragma once
// Where the SPH scene's bodies, sources, sinks, walls and materials stand in the case file.

#include "io/key_places.hpp"

#include <string>
#include <vector>

namespace grainload::sph {

/// The keys the scene's start checks name in their messages, by table (sph/sph_case_reader.hpp
/// reads them): a body's shape is placed by its `min`, `base`, `centre`, `file` or `type`, a
/// source by its `min` or its shape, a sink by its `min`, `point` or `normal`, a gate by its
/// wall's `remove_at`, a material's stiffness by its `stiffness_scale`, `from_lsdyna`,
/// `youngs_modulus` or `bulk_modulus`, the contact potential by [sph.contact] `stiffness`.
struct ScenePlaces {
    std::vector<io::KeyPlaces> body_shapes;   ///< per [[sph.body]], its [sph.body.shape]
    std::vector<io::KeyPlaces> sources;       ///< per [[sph.source]]
    std::vector<io::KeyPlaces> source_shapes; ///< per [[sph.source]], its shape (if any)
    std::vector<io::KeyPlaces> sinks;         ///< per [[sph.sink]]
    std::vector<io::KeyPlaces> walls;         ///< per [[sph.wall]]
    std::vector<io::KeyPlaces> materials;     ///< per [[material]]
    std::vector<std::string> deck_units;      ///< per [[material]]: from_lsdyna.units, or ""
    io::KeyPlaces contact;                    ///< [sph.contact]
};

} // namespace grainload::sph
