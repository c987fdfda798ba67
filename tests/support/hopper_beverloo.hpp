#pragma once
// The plane-wedge hopper (cases/hopper_discharge/) against Beverloo's slot law.

#include "support/case_runner.hpp"

#include <cmath>
#include <string>

namespace grainload::testing {

/// The hopper of Markauskas' DEM study as the case files model it: spheres of 65 mm mean
/// diameter, 500 kg/m^3 at solid fraction 0.6, through a 0.4 m slot.
struct WedgeHopper {
    static constexpr double gravity = 9.81;
    static constexpr double bulk_density = 300.0; // kg/m^3
    static constexpr double orifice = 0.4;        // m, across the slot
    static constexpr double grain = 0.065;        // m
};

/// Beverloo's law for a slot (Beverloo, Leniger & van de Velde 1961), per metre of slot
/// length: W / L = C' rho_b sqrt(g) (B - k d)^(3/2) with C' = 1.03 (Myers & Sellers,
/// Nedderman). Plane strain has no slot ends, so the (L - k d) factor of the 3D slot is L.
inline double beverloo_slot(double k) {
    using H = WedgeHopper;
    constexpr double kSlotConstant = 1.03;
    return kSlotConstant * H::bulk_density * std::sqrt(H::gravity) *
           std::pow(H::orifice - k * H::grain, 1.5);
}

/// A discharge run's figures from its summary.json, once its books are checked: the mass audit
/// to the round-off of `masses` particle masses and the energy within 0.3 %
/// (expect_books_close).
struct HopperDischarge {
    double initial_mass = 0.0;    ///< kg/m
    double discharged_mass = 0.0; ///< kg/m
    double steady_rate = 0.0;     ///< kg/m/s, the sink's fitted steady rate
};

inline HopperDischarge read_hopper_discharge(const std::string& summary, int masses) {
    expect_books_close(summary, masses);
    return {result_value(summary, "initial_mass"), result_value(summary, "discharged_mass"),
            result_value(summary, "sink_below_steady_rate")};
}

} // namespace grainload::testing
