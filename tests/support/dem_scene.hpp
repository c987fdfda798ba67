#pragma once
// A DEM scene from case-file text, stepped as the driver steps it, for the DEM's tests.

#include "dem/dem_model.hpp"
#include "io/case_table.hpp"
#include "io/scene_settings.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_library.hpp"

#include <algorithm>
#include <memory>
#include <string>

namespace grainload::testing {

/// The DemModel of a case given as text (its [case], [[material]] and [dem] tables).
inline std::unique_ptr<dem::DemModel> dem_model(const std::string& text) {
    auto document = io::CaseDocument::from_string(text, "dem.toml");
    const io::SceneSettings settings = io::read_scene_settings(*document, "dem");
    const io::CaseTable root = document->root();
    const materials::MaterialLibrary library = materials::read_material_library(root);
    auto model = std::make_unique<dem::DemModel>(dem::read_dem_settings(root, library, settings),
                                                 settings, library);
    document->reject_unknown_keys();
    return model;
}

/// Advance `model` from `t` to `until` with its stable step, calling `each(t)` after every
/// step; returns the time reached.
template <class Each> double step_until(dem::DemModel& model, double t, double until, Each each) {
    while (t < until) {
        const double dt = std::min(model.stable_time_step(), until - t);
        model.advance(t, dt);
        t += dt;
        each(t);
    }
    return t;
}

/// A glass-like grain material for the DEM tests: the solid density and stiffness of soda-lime
/// glass beads are 2500 kg/m^3 and about 60 GPa; E is lowered as DEM practice lowers it for a
/// longer step, which changes no figure the tests compare with its own analytic reference.
inline std::string glass(const std::string& young = "10 MPa") {
    return "[[material]]\nname = \"glass\"\nmodel = \"linear_elastic\"\n"
           "density = \"2500 kg/m^3\"\nyoungs_modulus = \"" +
           young + "\"\npoisson_ratio = 0.3\n";
}

} // namespace grainload::testing
