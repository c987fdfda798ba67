// SPH throughput in 3D: particle-steps per second of the material's particles, neighbour pairs
// per second, bytes per particle and peak memory, for 1 and 2 threads.
//  - an elastic block with a smooth velocity field, for the two neighbour-search modes (cell
//    list every step, Verlet list with a skin of 0.1 h) and the total-Lagrangian formulation
//    (stress sums over stored reference pairs; the Verlet list still serves the viscosity);
//  - a granular block (Drucker-Prager, and the generalized cap) slumping under gravity on a
//    frictional floor of wall particles (contact, dashpot, Coulomb friction): the production
//    configuration of issue 20, built from a case file as `grainload run` builds it.
// Each row also prints the kinetic energy after the timed steps, so that a change meant to keep
// the physics can be checked against the figure of an earlier build (docs/performance.md).
//
// usage: sph_throughput [particles ...]   (default 1e4 1e5 1e6)

#include "app/openmp_wait.hpp"
#include "app/scene.hpp"
#include "materials/linear_elastic.hpp"
#include "sph/lattice_fill.hpp"
#include "sph/sph_model.hpp"
#include "sph/sph_solver.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <omp.h>
#include <sstream>
#include <string>
#include <unistd.h>
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
    double particle_steps_per_second = 0.0; ///< material particles only
    double pairs_per_second = 0.0;
    double bytes_per_particle = 0.0; ///< solver heap bytes / material particles
    double rebuilds_per_step = 0.0;
    double kinetic_energy = 0.0; ///< of the material after the timed steps, J
};

/// Timed steps of `solver` (after one untimed step: first list, first forces) at the stable
/// step; `advance` takes one step of length dt.
template <class Advance>
Measurement time_steps(const sph::SphSolver& solver, Index material, Advance&& advance) {
    const double dt = solver.stable_time_step();
    advance(dt);
    const int steps = std::max(2, static_cast<int>(2e6 / static_cast<double>(material)));
    const Index rebuilds_before = solver.neighbours().rebuild_count();
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) {
        advance(dt);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Index pairs = 0;
    const double support = solver.kernel().support_radius();
    const sph::ParticleSet& p = solver.particles();
    for (Index i = 0; i < p.size(); ++i) {
        for (const Index j : solver.neighbours().neighbours(i)) {
            pairs += (p.position[i] - p.position[j]).norm() < support;
        }
    }
    Measurement m;
    m.particle_steps_per_second = static_cast<double>(material) * steps / seconds;
    // Interacting pairs, each counted once, visited twice per step (kinematics and forces).
    m.pairs_per_second = 0.5 * static_cast<double>(pairs) * steps / seconds;
    m.bytes_per_particle = static_cast<double>(solver.bytes()) / static_cast<double>(material);
    m.rebuilds_per_step =
        static_cast<double>(solver.neighbours().rebuild_count() - rebuilds_before) / steps;
    m.kinetic_energy = solver.kinetic_energy();
    return m;
}

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
    return time_steps(solver, n, [&](double dt) { solver.step(dt); });
}

/// Case file of the granular block: a cube of about `target` particles at 10 mm on a floor of
/// two layers of wall particles at 5 mm with Coulomb friction, released under gravity.
std::string granular_case(Index target, const std::string& material) {
    const double spacing = 10.0; // mm
    const auto side = static_cast<double>(std::llround(std::cbrt(static_cast<double>(target))));
    const double edge = side * spacing;
    const double base = 1.85 * spacing; // as the 2D collapse: touching the floor, no force
    const double margin = 3.0 * spacing;
    std::ostringstream text;
    text << "[case]\nname = \"bench_granular\"\ndimension = 3\nend_time = \"1 s\"\n"
         << "gravity = \"0 0 -9.81 m/s^2\"\n\n"
         << "[[material]]\nname = \"sand\"\n"
         << material << "\n"
         << "[sph]\nkernel = \"cubic_spline\"\nsmoothing_length_ratio = 1.3\n"
         << "kernel_gradient_correction = false\n"
         << "[sph.artificial_viscosity]\nalpha = 0.1\nbeta = 0.1\n"
         << "[sph.contact]\nstiffness = \"10 MPa\"\nexponent = 1\ndamping_ratio = 0.5\n\n"
         << "[[sph.body]]\nname = \"block\"\nmaterial = \"sand\"\nspacing = \"" << spacing
         << " mm\"\n[sph.body.shape]\ntype = \"box\"\nmin = \"0 0 " << base << " mm\"\nmax = \""
         << edge << " " << edge << " " << base + edge << " mm\"\n\n"
         << "[[sph.wall]]\nname = \"floor\"\ntype = \"plane\"\nspacing = \"" << 0.5 * spacing
         << " mm\"\nlayers = 2\norigin = \"" << -margin << " " << -margin << " 0 mm\"\nedge_u = \""
         << edge + 2.0 * margin << " 0 0 mm\"\nedge_v = \"0 " << edge + 2.0 * margin
         << " 0 mm\"\nnormal = \"0 0 1\"\n\n"
         << "[[sph.friction]]\nbody = \"block\"\nwall = \"floor\"\nmu_static = 0.5\n"
         << "mu_kinetic = 0.5\n";
    return text.str();
}

/// Drucker-Prager sand (10 MPa, 30 deg, cohesionless) and the generalized cap of the 3D column
/// collapse cases (the thesis sand at 1/1000 of its stiffness).
constexpr const char* kDruckerPrager =
    "model = \"drucker_prager\"\ndensity = \"2000 kg/m^3\"\nyoungs_modulus = \"10 MPa\"\n"
    "poisson_ratio = 0.3\nfriction_angle = \"30 deg\"\ncohesion = \"0 Pa\"\n"
    "dilatancy_angle = \"0 deg\"\ncone_fit = \"compression\"\n";
constexpr const char* kCap =
    "model = \"generalized_cap\"\ndensity = \"2099 kg/m^3\"\nbulk_modulus = \"30.62 MPa\"\n"
    "shear_modulus = \"8.23 MPa\"\ncap_k = \"0.03858 MPa\"\ncap_theta = 0.03\n"
    "cap_gamma = \"0.03858 MPa\"\ncap_beta = \"9.0 1/MPa\"\ncap_D = \"7.25 1/MPa\"\n"
    "cap_W = 0.18\ncap_X0 = \"0 MPa\"\ncap_R = 2.0\n";

Measurement measure_granular(Index target, int threads, const char* material) {
    omp_set_num_threads(threads);
    const std::string file = (std::filesystem::temp_directory_path() /
                              ("grainload_bench_granular_" + std::to_string(getpid()) + ".toml"))
                                 .string();
    std::ofstream(file) << granular_case(target, material);
    const auto scene = app::Scene::load(file, {});
    std::filesystem::remove(file);
    io::Stepper& stepper = *scene->steppers.front();
    const auto& model = dynamic_cast<const sph::SphModel&>(stepper);
    double t = 0.0;
    return time_steps(*model.solver(), scene->material_point_count(), [&](double dt) {
        stepper.advance(t, dt);
        t += dt;
    });
}

void print(Index n, int threads, const char* label, const Measurement& m) {
    std::printf("%10lld %7d %-22s %16.3e %14.3e %12.0f %12.2f %14.0f %22.15e\n",
                static_cast<long long>(n), threads, label, m.particle_steps_per_second,
                m.pairs_per_second, m.bytes_per_particle, m.rebuilds_per_step, peak_memory_mib(),
                m.kinetic_energy);
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    grainload::app::default_openmp_wait(argv); // the product default, as grainload run
    std::vector<Index> sizes;
    for (int a = 1; a < argc; ++a) {
        sizes.push_back(static_cast<Index>(std::atof(argv[a])));
    }
    if (sizes.empty()) {
        sizes = {10000, 100000, 1000000};
    }
    const materials::LinearElastic steel(
        materials::ElasticConstants::from_young(7850.0, 200e9, 0.3));
    std::printf("# 3D, cubic spline, h = 1.3 dx. Elastic block: artificial viscosity and "
                "kernel-gradient correction on. Granular block: Drucker-Prager or cap, viscosity, "
                "floor contact with dashpot and friction, Verlet 0.1h.\n"
                "# particle-steps/s and bytes/particle per material particle (wall particles "
                "not counted); KE = the material's kinetic energy after the timed steps\n");
    const Mode modes[] = {{"cell list", 0.0, sph::Formulation::updated_lagrangian},
                          {"Verlet 0.1h", 0.1, sph::Formulation::updated_lagrangian},
                          {"total Lagrangian", 0.1, sph::Formulation::total_lagrangian}};
    std::printf("%10s %7s %-22s %16s %14s %12s %12s %14s %22s\n", "particles", "threads", "mode",
                "particle-steps/s", "pairs/s", "bytes/part.", "rebuild/step", "peak RSS MiB",
                "KE, J");
    for (const Index n : sizes) {
        for (const int threads : {1, 2}) {
            for (const Mode& mode : modes) {
                print(n, threads, mode.label, measure(n, threads, mode, steel));
            }
            print(n, threads, "granular Drucker-Prager",
                  measure_granular(n, threads, kDruckerPrager));
            print(n, threads, "granular cap", measure_granular(n, threads, kCap));
        }
    }
    return 0;
}
