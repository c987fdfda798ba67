// Time each pass of an SPH step on a case's particles (by default the 2D column collapse of
// the peer comparison): velocity gradient, force inputs, forces, stress update and
// neighbour-list rebuild, in microseconds per material particle, the best of --reps calls each
// (a shared machine slows single calls at random; the best is the code's own speed). A run's
// checkpoint gives a flowing state: `grainload run CASE --set 'case.end_time=0.2 s'` writes
// OUT/checkpoint.bin. The checksum line sums the computed rates, so that two builds meant to
// compute the same can be compared. When a wall of the case acts on some bodies only (`bodies`,
// e.g. --set 'sph.wall[0].bodies="column"'), the rebuild is also timed with the solver's drop
// of the other bodies' pairs (sph/wall_bodies.hpp), the one cost such a wall adds. The
// kinematic and force passes are timed again with their scalar rows (rates.hpp
// PairArithmetic), and the line says whether the vector lanes gave the same bits.
//
// usage: sph_passes [--threads N] [--reps R] [--restart CHECKPOINT] [--set KEY=VALUE]...
//                   [CASE.toml]

#include "app/checkpoint.hpp"
#include "app/resources/heap_trim.hpp"
#include "app/resources/openmp_wait.hpp"
#include "app/scene.hpp"
#include "sph/rates.hpp"
#include "sph/sph_model.hpp"
#include "sph/stress_update.hpp"
#include "sph/wall_bodies.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <omp.h>
#include <string>
#include <vector>

namespace {

using namespace grainload;

template <class Pass> double best_seconds(Pass&& pass, int reps) {
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
        const auto start = std::chrono::steady_clock::now();
        pass();
        best = std::min(
            best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

} // namespace

int main(int argc, char** argv) {
    app::default_openmp_wait(argv);
    app::keep_freed_heap();
    std::string kase =
        std::string(GRAINLOAD_SOURCE_DIR) + "/cases/column_collapse_2d/column_collapse_2d.toml";
    std::string checkpoint;
    int threads = 1;
    int reps = 20;
    std::vector<std::string> overrides;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--threads" && a + 1 < argc) {
            threads = std::atoi(argv[++a]);
        } else if (arg == "--reps" && a + 1 < argc) {
            reps = std::atoi(argv[++a]);
        } else if (arg == "--set" && a + 1 < argc) {
            overrides.emplace_back(argv[++a]);
        } else if (arg == "--restart" && a + 1 < argc) {
            checkpoint = argv[++a];
        } else {
            kase = arg;
        }
    }
    omp_set_num_threads(threads);
    const auto scene = app::Scene::load(kase, overrides);
    if (!checkpoint.empty()) {
        app::read_checkpoint(*scene, checkpoint);
    }
    const auto* model = dynamic_cast<const sph::SphModel*>(scene->steppers.front().get());
    if (model == nullptr || model->solver() == nullptr) {
        std::fprintf(stderr, "sph_passes: %s has no SPH solver\n", kase.c_str());
        return 2;
    }
    const sph::SphSolver& solver = *model->solver();
    const sph::SphOptions& options = solver.options();
    const sph::SmoothingKernel& kernel = solver.kernel();
    sph::ParticleSet p = solver.particles();
    std::vector<char> frozen(static_cast<std::size_t>(p.size()));
    Index material = 0;
    sph::ForceInputs inputs;
    inputs.sound_speed.assign(static_cast<std::size_t>(p.size()), 0.0);
    for (Index i = 0; i < p.size(); ++i) {
        frozen[i] = p.is_wall(i) ? 1 : 0;
        if (!frozen[i]) {
            ++material;
            inputs.sound_speed[i] = solver.materials()[static_cast<std::size_t>(p.material_id[i])]
                                        ->elastic()
                                        .p_wave_speed();
        }
    }
    particles::NeighbourList list(kernel.support_radius(),
                                  options.verlet_skin_factor * options.smoothing_length,
                                  options.dimension);
    // As SphSolver: each same-body pair in one row (the passes take it once).
    const std::vector<int> keys = sph::continuum_keys(p);
    auto build = [&] {
        list.update(p.position, frozen, true);
        list.halve_pairs(keys);
    };
    build();
    sph::PairScratch scratch;
    const std::vector<const materials::Material*> materials(solver.materials().begin(),
                                                            solver.materials().end());
    std::vector<Mat3> gradient;
    std::vector<double> heating;
    // As SphSolver: plane strain keeps the kinematic pass's kernel gradients for the forces
    // where the force pass's scalar rows run (the lanes evaluate them themselves).
    std::vector<double>* factors =
        options.dimension == 2 && !sph::force_pass_uses_lanes(kernel, options)
            ? &inputs.entry_factor
            : nullptr;
    auto kinematics = [&] {
        sph::compute_velocity_gradient(p, list, kernel, options.kernel_gradient_correction,
                                       gradient, inputs.gradient_correction, factors, &scratch,
                                       sph::PairArithmetic::lanes_where_available,
                                       &inputs.pair_records);
    };
    kinematics();
    const double t_gradient = best_seconds(kinematics, reps);
    // The kinematic pass again with the scalar row everywhere (rates.hpp PairArithmetic),
    // storing the kernel gradients in plane strain for the scalar force row below, as the
    // solver does where the lanes do not run.
    const std::vector<Mat3> lane_gradient = gradient;
    std::vector<double>* scalar_factors = options.dimension == 2 ? &inputs.entry_factor : nullptr;
    const double t_scalar_gradient = best_seconds(
        [&] {
            sph::compute_velocity_gradient(p, list, kernel, options.kernel_gradient_correction,
                                           gradient, inputs.gradient_correction, scalar_factors,
                                           &scratch, sph::PairArithmetic::scalar);
        },
        reps);
    const bool same_gradient = std::memcmp(lane_gradient.data(), gradient.data(),
                                           gradient.size() * sizeof(gradient[0])) == 0;
    const double t_inputs = best_seconds(
        [&] { sph::prepare_force_inputs(p, options.artificial_stress, inputs); }, reps);
    const double t_forces = best_seconds(
        [&] { sph::compute_accelerations(p, list, kernel, options, inputs, heating, &scratch); },
        reps);
    // The force pass again with the scalar row everywhere (rates.hpp PairArithmetic): its time,
    // and whether the vector lanes wrote the same bits.
    const auto lane_acceleration = p.acceleration;
    const std::vector<double> lane_heating = heating;
    const double t_scalar = best_seconds(
        [&] {
            sph::compute_accelerations(p, list, kernel, options, inputs, heating, &scratch,
                                       sph::PairArithmetic::scalar);
        },
        reps);
    const bool same_bits =
        std::memcmp(lane_acceleration.data(), p.acceleration.data(),
                    lane_acceleration.size() * sizeof(lane_acceleration[0])) == 0 &&
        std::memcmp(lane_heating.data(), heating.data(), heating.size() * sizeof(double)) == 0;
    sph::ParticleSet updated = p;
    const double t_stress = best_seconds(
        [&] {
            updated.stress = p.stress;
            updated.state = p.state;
            sph::update_stresses(updated, materials, 1e-5);
        },
        reps);
    const double t_rebuild = best_seconds(build, reps);
    const sph::WallBodyFilter filter = sph::wall_body_filter(solver.walls());
    const double t_filtered = filter.empty()
                                  ? 0.0
                                  : best_seconds(
                                        [&] {
                                            list.update(p.position, frozen, true);
                                            list.drop_pairs(p.body_id, filter.apart, filter.groups);
                                            list.halve_pairs(keys);
                                        },
                                        reps);
    double checksum = 0.0;
    for (Index i = 0; i < p.size(); ++i) {
        checksum += p.acceleration[i].norm() + heating[i] + p.density_rate[i];
    }
    const double us = 1e6 / static_cast<double>(material);
    std::printf("# %s%s%s: %lld points, %lld material, %lld list entries, %d thread(s), best "
                "of %d\n",
                kase.c_str(), checkpoint.empty() ? "" : " at ", checkpoint.c_str(),
                static_cast<long long>(p.size()), static_cast<long long>(material),
                static_cast<long long>(list.pair_entries()), threads, reps);
    std::printf("us per material particle: velocity gradient %.4f  force inputs %.4f  forces "
                "%.4f  stress update %.4f  (sum %.4f)  list rebuild %.4f\n",
                t_gradient * us, t_inputs * us, t_forces * us, t_stress * us,
                (t_gradient + t_inputs + t_forces + t_stress) * us, t_rebuild * us);
    if (!filter.empty()) {
        std::printf("list rebuild with the walls' body filter %.4f (%lld entries kept)\n",
                    t_filtered * us, static_cast<long long>(list.pair_entries()));
    }
    std::printf("scalar rows: velocity gradient %.4f (%s bits)  forces %.4f (%s bits)\n",
                t_scalar_gradient * us, same_gradient ? "same" : "DIFFERENT", t_scalar * us,
                same_bits ? "same" : "DIFFERENT");
    std::printf("checksum %.17g\n", checksum);
    return 0;
}
