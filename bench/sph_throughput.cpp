// SPH throughput on a 3D elastic block: particle-steps per second, neighbour pairs per second,
// bytes per particle and peak memory, for 1 and 2 threads, for the two neighbour-search modes
// (cell list every step, Verlet list with a skin of 0.1 h) and for the total-Lagrangian
// formulation (stress sums over stored reference pairs; the Verlet list still serves the
// artificial viscosity).
//
// usage: sph_throughput [particles ...]   (default 1e4 1e5 1e6)

#include "materials/linear_elastic.hpp"
#include "sph/lattice_fill.hpp"
#include "sph/sph_solver.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <omp.h>
#include <string>
#include <vector>

namespace {

using namespace grainload;

/// Peak resident memory of the process (VmHWM), in MiB.
double peak_memory_mib() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) == 0) {
            return std::stod(line.substr(6)) / 1024.0;
        }
    }
    return 0.0;
}

struct Measurement {
    double particle_steps_per_second = 0.0;
    double pairs_per_second = 0.0;
    double bytes_per_particle = 0.0;
    double rebuilds_per_step = 0.0;
};

struct Mode {
    const char* label;
    double skin_factor;
    sph::Formulation formulation;
};

Measurement measure(Index target, int threads, const Mode& mode,
                    const materials::LinearElastic& steel) {
    omp_set_num_threads(threads);
    const double spacing = 0.01;
    const auto side = static_cast<double>(std::llround(std::cbrt(static_cast<double>(target))));
    sph::ParticleSet particles;
    sph::LatticeBody block;
    block.upper = Vec3::Constant(side * spacing);
    block.spacing = spacing;
    block.density = steel.density();
    sph::fill_box_lattice(particles, block, 3);
    // A smooth velocity field so that stresses, rotations and neighbour changes are real.
    for (Index i = 0; i < particles.size(); ++i) {
        const Vec3& x = particles.position[i];
        particles.velocity[i] =
            Vec3(std::sin(20.0 * x.y()), std::sin(20.0 * x.z()), std::sin(20.0 * x.x()));
    }
    sph::SphOptions options;
    options.dimension = 3;
    options.kernel = sph::KernelType::cubic_spline;
    options.smoothing_length = 1.3 * spacing;
    options.particle_spacing = spacing;
    options.viscosity = {0.5, 1.0};
    options.kernel_gradient_correction = true; // the case-file default
    options.verlet_skin_factor = mode.skin_factor;
    options.formulation = mode.formulation;
    const Index n = particles.size();
    sph::SphSolver solver(std::move(particles), {&steel}, options);
    const double dt = solver.stable_time_step();
    solver.step(dt); // warm-up: first force evaluation, first list
    const int steps = std::max(2, static_cast<int>(2e6 / static_cast<double>(n)));
    const Index rebuilds_before = solver.neighbours().rebuild_count();
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) {
        solver.step(dt);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Index pairs = 0;
    const double support = solver.kernel().support_radius();
    for (Index i = 0; i < n; ++i) {
        for (const Index j : solver.neighbours().neighbours(i)) {
            pairs +=
                (solver.particles().position[i] - solver.particles().position[j]).norm() < support;
        }
    }
    Measurement m;
    m.particle_steps_per_second = static_cast<double>(n) * steps / seconds;
    // Interacting pairs, each counted once, visited twice per step (kinematics and forces).
    m.pairs_per_second = 0.5 * static_cast<double>(pairs) * steps / seconds;
    m.bytes_per_particle = static_cast<double>(solver.bytes()) / static_cast<double>(n);
    m.rebuilds_per_step =
        static_cast<double>(solver.neighbours().rebuild_count() - rebuilds_before) / steps;
    return m;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<Index> sizes;
    for (int a = 1; a < argc; ++a) {
        sizes.push_back(static_cast<Index>(std::atof(argv[a])));
    }
    if (sizes.empty()) {
        sizes = {10000, 100000, 1000000};
    }
    const materials::LinearElastic steel(
        materials::ElasticConstants::from_young(7850.0, 200e9, 0.3));
    std::printf("# 3D elastic block, cubic spline, h = 1.3 dx, artificial viscosity and "
                "kernel-gradient correction on\n");
    const Mode modes[] = {{"cell list", 0.0, sph::Formulation::updated_lagrangian},
                          {"Verlet 0.1h", 0.1, sph::Formulation::updated_lagrangian},
                          {"total Lagrangian", 0.1, sph::Formulation::total_lagrangian}};
    std::printf("%10s %7s %-20s %16s %14s %12s %12s %14s\n", "particles", "threads", "search",
                "particle-steps/s", "pairs/s", "bytes/part.", "rebuild/step", "peak RSS MiB");
    for (const Index n : sizes) {
        for (const int threads : {1, 2}) {
            for (const Mode& mode : modes) {
                const Measurement m = measure(n, threads, mode, steel);
                std::printf("%10lld %7d %-20s %16.3e %14.3e %12.0f %12.2f %14.0f\n",
                            static_cast<long long>(n), threads, mode.label,
                            m.particle_steps_per_second, m.pairs_per_second, m.bytes_per_particle,
                            m.rebuilds_per_step, peak_memory_mib());
                std::fflush(stdout);
            }
        }
    }
    return 0;
}
