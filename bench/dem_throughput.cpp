// DEM throughput: grain-steps and contacts per second of a packing of spheres settling in a
// box, the scene bench/liggghts/run_peer.sh gives LIGGGHTS (same spheres, region, Hertz-Mindlin
// contacts with friction, walls, step), for the side-by-side figure of docs/performance.md.
// The spheres are placed at random (solid fraction 0.25) in a 0.1 m square box and
// fall for `settle` steps (not timed), then `steps` steps are timed: the packing then rests on
// the floor with most grains in contact, the regime whose contacts cost what a silo's do.
// Prints the wall time, grain-steps/s, the contacts per step and contacts/s, the machine's
// load during the timed steps, and the kinetic energy (the figure two builds are compared by).
//
// usage: dem_throughput [--threads T] [--grains N] [--settle S] [--steps S]
//        (default 2 threads, 5000 grains, 40 000 settle steps, 10 000 timed steps, step 5 us)

#include "app/resources/openmp_wait.hpp"
#include "dem/dem_model.hpp"
#include "io/case_table.hpp"
#include "io/scene_settings.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_library.hpp"
#include "support/machine_load.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <omp.h>
#include <string>

namespace {

using namespace grainload;

struct Options {
    int threads = 2;
    long grains = 5000;
    long settle = 40000;
    long steps = 10000;
};

Options parse(int argc, char** argv) {
    Options o;
    for (int k = 1; k + 1 < argc; k += 2) {
        const long value = std::strtol(argv[k + 1], nullptr, 10);
        if (std::strcmp(argv[k], "--threads") == 0) {
            o.threads = static_cast<int>(value);
        } else if (std::strcmp(argv[k], "--grains") == 0) {
            o.grains = value;
        } else if (std::strcmp(argv[k], "--settle") == 0) {
            o.settle = value;
        } else if (std::strcmp(argv[k], "--steps") == 0) {
            o.steps = value;
        } else {
            std::fprintf(stderr, "dem_throughput: unknown option %s\n", argv[k]);
            std::exit(2);
        }
    }
    return o;
}

/// The scene: glass-like spheres of radius 2.5 mm (E = 10 MPa, nu = 0.3, 2500 kg/m^3), Hertz-
/// Mindlin with friction 0.5 and damping, a closed-bottom box of plane walls; the height of the
/// fill region grows with the count to keep the solid fraction at 0.25.
std::string scene(long grains) {
    const double volume =
        static_cast<double>(grains) * 4.0 / 3.0 * std::numbers::pi * std::pow(0.0025, 3);
    const double height = volume / 0.25 / (0.1 * 0.1);
    return "[case]\nend_time = \"1 s\"\n[[material]]\nname = \"glass\"\nmodel = "
           "\"linear_elastic\"\ndensity = \"2500 kg/m^3\"\nyoungs_modulus = \"10 MPa\"\n"
           "poisson_ratio = 0.3\n[dem]\ntime_step = \"5e-6 s\"\n[dem.contact]\n"
           "law = \"hertz_mindlin\"\ngamma_n = \"200 1/s\"\ngamma_t = \"50 1/s\"\n"
           "friction = 0.5\n[[dem.body]]\nname = \"beads\"\nmaterial = \"glass\"\n"
           "radius = \"2.5 mm\"\ncount = " +
           std::to_string(grains) + "\nmin = \"0 0 0 m\"\nmax = \"0.1 0.1 " +
           std::to_string(height) +
           " m\"\n[[dem.wall]]\nname = \"box\"\ntype = \"box\"\nmin = \"0 0 0 m\"\n"
           "max = \"0.1 0.1 10 m\"\n";
}

} // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    app::default_openmp_wait(argv);
    omp_set_num_threads(o.threads);
    auto document = io::CaseDocument::from_string(scene(o.grains), "dem_throughput.toml");
    const io::SceneSettings settings = io::read_scene_settings(*document, "dem_throughput");
    const io::CaseTable root = document->root();
    const materials::MaterialLibrary library = materials::read_material_library(root);
    auto model = std::make_unique<dem::DemModel>(dem::read_dem_settings(root, library, settings),
                                                 settings, library);
    const double dt = model->stable_time_step();
    double t = 0.0;
    for (long k = 0; k < o.settle; ++k, t += dt) {
        model->advance(t, dt);
    }
    bench::LoadMeter load;
    double contacts = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (long k = 0; k < o.steps; ++k, t += dt) {
        model->advance(t, dt);
        contacts +=
            static_cast<double>(model->books().pair_contacts + model->books().wall_contacts);
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double grain_steps = static_cast<double>(o.grains) * static_cast<double>(o.steps);
    std::printf("dem_throughput: %ld grains, %d threads, %ld settle + %ld timed steps of %.3g s\n",
                o.grains, o.threads, o.settle, o.steps, dt);
    std::printf("  wall %.3f s  %.4g grain-steps/s  %.1f contacts per step  %.4g contacts/s  "
                "(other processes: %.2f cores)  kinetic energy %.6e J\n",
                wall, grain_steps / wall, contacts / static_cast<double>(o.steps), contacts / wall,
                load.others_cores(), model->energy().translational + model->energy().rotational);
    return 0;
}
