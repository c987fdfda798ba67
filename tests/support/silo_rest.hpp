#pragma once
// The slot silo at rest (cases/silo/silo_rest*.toml) against Janssen: weight carried, p_h per band.

#include "support/frame_reader.hpp"
#include "support/silo_janssen.hpp"

#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace grainload::testing {

/// The slot silo cases' physics: g, the walls' friction mu and the sand's phi = 30 deg; the
/// left wall is split into bands left0 .. left5 of 0.2 m from the floor up.
struct SiloRestCase {
    static constexpr double gravity = 9.81;
    static constexpr double wall_friction = 0.4;
    static constexpr double sin_phi = 0.5;
    static constexpr double band = 0.2; // m
};

/// One band of the left wall against Janssen's p_h with K = 1 - sin(phi) (low) and EN
/// 1991-4's 1.1 (1 - sin phi) (high), averaged over the band's depths.
struct SiloBand {
    double p_h = 0.0;          ///< Pa, the band's normal force over its height
    double janssen_low = 0.0;  ///< Pa
    double janssen_high = 0.0; ///< Pa
    double mobilised = 0.0;    ///< friction / (mu p_h), 1 where fully mobilised
};

/// A silo-at-rest run read from its frame `frame` (the fill) and wall_forces.csv (the walls'
/// final forces): the fraction of the fill's weight the floor and the walls' friction carry,
/// and the bands 1 to 4 (0.2-1.0 m, clear of floor and surface).
struct SiloRest {
    SlotFill fill;
    std::map<std::string, std::pair<double, double>> forces;
    double carried_fraction = 0.0;
    std::vector<SiloBand> bands;
};

inline SiloRest read_silo_rest(const std::string& out, const std::string& frame, double spacing,
                               double particle_mass) {
    using C = SiloRestCase;
    SiloRest rest;
    const auto sand = read_named_block(frame, "sand");
    EXPECT_TRUE(sand) << frame;
    if (!sand) {
        return rest;
    }
    rest.fill = measure_slot_fill(sand, spacing, particle_mass, C::gravity);
    rest.forces = final_wall_forces(out);
    double carried = -rest.forces.at("floor").second - rest.forces.at("right").second;
    for (const auto& [wall, force] : rest.forces) {
        carried -= wall.rfind("left", 0) == 0 ? force.second : 0.0;
    }
    rest.carried_fraction = carried / (rest.fill.mass * C::gravity);
    for (int band = 1; band <= 4; ++band) {
        const auto [fx, fy] = rest.forces.at("left" + std::to_string(band));
        SiloBand b;
        b.p_h = -fx / C::band;
        const double top = rest.fill.surface - C::band * (band + 1);
        const double bottom = rest.fill.surface - C::band * band;
        b.janssen_low = janssen_band(rest.fill, 1.0 - C::sin_phi, C::wall_friction, top, bottom);
        b.janssen_high =
            janssen_band(rest.fill, 1.1 * (1.0 - C::sin_phi), C::wall_friction, top, bottom);
        b.mobilised = -fy / (C::wall_friction * b.p_h * C::band);
        std::cout << "band " << band << ": p_h " << b.p_h << " Pa, Janssen K=0.5 " << b.janssen_low
                  << " Pa, K=0.55 " << b.janssen_high << " Pa, friction/(mu p_h) " << b.mobilised
                  << '\n';
        rest.bands.push_back(b);
    }
    return rest;
}

/// The bands against Janssen as both silo-at-rest tests assert them: p_h below Janssen with
/// K = 0.55 (the design bound stays conservative) and above `lowest_fraction` of Janssen with
/// K = 0.5; friction / (mu p_h) between `mobilised` and Coulomb's bound 1.
inline void expect_bands_against_janssen(const SiloRest& rest, double lowest_fraction,
                                         double mobilised) {
    for (std::size_t i = 0; i < rest.bands.size(); ++i) {
        const SiloBand& b = rest.bands[i];
        EXPECT_LT(b.p_h, b.janssen_high) << "band " << i + 1;
        EXPECT_GT(b.p_h, lowest_fraction * b.janssen_low) << "band " << i + 1;
        EXPECT_GT(b.mobilised, mobilised) << "band " << i + 1;
        EXPECT_LE(b.mobilised, 1.0 + 1e-9) << "band " << i + 1;
    }
}

} // namespace grainload::testing
