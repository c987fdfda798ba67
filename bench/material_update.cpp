// Stress updates per second of the constitutive models on one thread, with and without the
// consistent tangent, and through Material::update_points in blocks of 64 points as the SPH
// stress update calls it (no tangent); and where the returns end (elastic, failure surface, cap,
// corner, apex).
// The sand is the thesis's generalized cap (section 7.2, X0 = 0: every compressed point sits on the
// cap, as in the 3D column collapse) at the full stiffness and at K/1000, and the Drucker-Prager
// sand of the 2D collapse, the same sand with mu(I) (whose one-by-one calls are update(), its
// rest state; the blocks take each increment over kTimeStep, so they read the rate) and with the
// Mohr-Coulomb hexagon of its friction angle. Each point
// follows its own random strain path: a compressive volumetric drift plus random strain, scaled so
// that one increment changes the stress by about `stress_step` (a few per cent of the kPa stresses
// of a lab-scale column). "Compacting" paths have random parts as large as the drift; "shearing"
// paths ten times larger, which drives trials far above the envelope beyond the cap centre, the
// states of a flowing column (there the cap Newton from the trial heads out of its box).
//
// usage: material_update [points] [steps]   (default 20000 points, 50 steps)

#include "materials/cone_fit.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/generalized_cap.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/mu_i_material.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <span>
#include <vector>

namespace {

using namespace grainload;
using namespace grainload::materials;

struct Figures {
    double updates_per_second = 0.0;
    std::array<long, 5> regions{};
};

/// How the points are updated: one by one without or with the tangent, or in blocks.
enum class Calls { single, tangent, blocks };

/// Points a block of the SPH stress update holds (sph/stress_update.cpp).
constexpr int kBlock = 64;
/// The time step the increments are taken over: the order of the 2D collapse's SPH step. Only a
/// rate-dependent model (mu(I)) reads it.
constexpr double kTimeStep = 1e-5;

Figures run(const Material& material, int points, int steps, double stress_step, double shear,
            Calls calls) {
    const int n_state = material.state_size();
    std::vector<double> state(static_cast<std::size_t>(points * n_state));
    std::vector<Voigt6> stress(static_cast<std::size_t>(points), Voigt6::Zero());
    for (int i = 0; i < points; ++i) {
        material.initialise_state({state.data() + i * n_state, static_cast<std::size_t>(n_state)});
    }
    const double strain_step = stress_step / material.elastic().bulk_modulus;
    std::mt19937 random(1);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<Voigt6> increments(static_cast<std::size_t>(points * steps));
    for (Voigt6& d : increments) {
        for (int a = 0; a < 6; ++a) {
            d[a] = shear * strain_step * normal(random);
        }
        d.head<3>().array() -= strain_step; // compaction on average (tension positive)
    }
    std::vector<double*> states(static_cast<std::size_t>(points));
    for (int i = 0; i < points; ++i) {
        states[static_cast<std::size_t>(i)] = state.data() + i * n_state;
    }
    std::vector<PlasticRegion> regions(static_cast<std::size_t>(points));
    Figures figures;
    Matrix6 d_stress;
    const auto start = std::chrono::steady_clock::now();
    for (int step = 0; step < steps; ++step) {
        const auto step_increments =
            std::span(increments).subspan(static_cast<std::size_t>(step * points));
        for (int i = 0; i < points; i += calls == Calls::blocks ? kBlock : 1) {
            const auto u = static_cast<std::size_t>(i);
            if (calls == Calls::blocks) {
                const auto count = static_cast<std::size_t>(std::min(kBlock, points - i));
                material.update_points(step_increments.subspan(u, count), kTimeStep,
                                       std::span(stress).subspan(u, count),
                                       std::span(states).subspan(u, count),
                                       std::span(regions).subspan(u, count));
                continue;
            }
            regions[u] = material.update(step_increments[u], stress[u],
                                         {states[u], static_cast<std::size_t>(n_state)},
                                         calls == Calls::tangent ? &d_stress : nullptr);
        }
        for (const PlasticRegion region : regions) {
            ++figures.regions[static_cast<std::size_t>(region)];
        }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    figures.updates_per_second = static_cast<double>(points) * steps / seconds;
    return figures;
}

void report(const char* name, const Material& material, int points, int steps, double stress_step,
            double shear) {
    for (const Calls calls : {Calls::single, Calls::tangent, Calls::blocks}) {
        const Figures f = run(material, points, steps, stress_step, shear, calls);
        const double total = static_cast<double>(points) * steps;
        std::array<double, 5> percent{};
        for (std::size_t r = 0; r < percent.size(); ++r) {
            percent[r] = 100.0 * static_cast<double>(f.regions[r]) / total;
        }
        std::printf("%-34s %-8s %10.3e   %5.1f %5.1f %5.1f %5.1f %5.1f\n", name,
                    calls == Calls::tangent  ? "yes"
                    : calls == Calls::blocks ? "blocks"
                                             : "no",
                    f.updates_per_second, percent[0], percent[1], percent[2], percent[3],
                    percent[4]);
    }
}

} // namespace

int main(int argc, char** argv) {
    const int points = argc > 1 ? std::atoi(argv[1]) : 20000;
    const int steps = argc > 2 ? std::atoi(argv[2]) : 50;
    // Thesis section 7.2, stresses in MPa there: SI here.
    cap::Parameters thesis;
    thesis.k = 0.03858e6;
    thesis.theta = 0.03;
    thesis.gamma = 0.03858e6;
    thesis.beta = 9.0e-6;
    thesis.D = 7.25e-6;
    thesis.W = 0.18;
    thesis.X0 = 0.0;
    thesis.R = 2.0;
    const GeneralizedCap full(ElasticConstants::from_bulk_shear(2099.0, 30.62e9, 8.23e9), thesis);
    const GeneralizedCap scaled(ElasticConstants::from_bulk_shear(2099.0, 30.62e6, 8.23e6), thesis);
    const ConeConstants cone =
        fit_cone(ConeFit::plane_strain, 21.9 * std::numbers::pi / 180.0, 0.0, 0.0);
    const DruckerPrager sand(ElasticConstants::from_young(2040.0, 5.84e6, 0.3),
                             {cone.alpha, cone.k, cone.alpha_flow});
    // The same bars with mu(I) (cases/column_collapse_2d/column_collapse_2d_mu_i_small.toml):
    // mu_s = sin 21.9 deg is the cone above.
    const MuIMaterial bars(ElasticConstants::from_young(2040.0, 5.84e6, 0.3),
                           {3.0 * cone.alpha, 3.0 * cone.alpha + 0.2616, 0.279, 1.25e-3, 2700.0});
    std::printf("%d points x %d steps, one thread, stress change per increment ~100 Pa\n", points,
                steps);
    std::printf("%-34s %-8s %10s   %% elastic/failure/cap/corner/apex\n", "model", "tangent",
                "updates/s");
    report("cap, thesis K, compacting", full, points, steps, 100.0, 1.0);
    report("cap, thesis K, shearing", full, points, steps, 100.0, 10.0);
    report("cap, K/1000, compacting", scaled, points, steps, 100.0, 1.0);
    report("cap, K/1000, shearing", scaled, points, steps, 100.0, 10.0);
    report("Drucker-Prager, 2D collapse sand", sand, points, steps, 100.0, 1.0);
    report("mu(I), 2D collapse sand", bars, points, steps, 100.0, 1.0);
    // The same sand's Mohr-Coulomb hexagon, of which the cone above is the plane-strain fit.
    const MohrCoulomb hexagon(ElasticConstants::from_young(2040.0, 5.84e6, 0.3),
                              {21.9 * std::numbers::pi / 180.0, 0.0, 0.0});
    report("Mohr-Coulomb, 2D collapse sand", hexagon, points, steps, 100.0, 1.0);
    // Both shearing, where most trials leave the surface: the hexagon's spectral return against
    // the cone's closed form.
    report("Drucker-Prager, shearing", sand, points, steps, 100.0, 10.0);
    report("Mohr-Coulomb, shearing", hexagon, points, steps, 100.0, 10.0);
    return 0;
}
