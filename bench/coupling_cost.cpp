// Cost split of the SPH-shell coupling: a sand layer on a plate (static shell, staggered) and
// a sand block landing on a plate (dynamic shell, iterated), at windows of 1, 10 and 100 SPH
// steps, with the wall time of the SPH sub-steps, of the interpolation and force mapping, and
// of the shell solve split into assembly, factorisation and forward/back substitution. The
// coupling's share is (mapping + shell) / SPH. An iterated window counts all its passes; the
// shell's "assembly" is the rest of its time: the internal forces (K u for this linear plate),
// the reactions, and the element stresses the extremes read.
// Usage: coupling_cost [plate elements per side, default 24] [sand spacing in mm, default 20]
//                      [windows per run, default 20]
#include "coupling/coupling_case_reader.hpp"
#include "fem/sparse_solver.hpp"
#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace grainload;

/// A plate of `n` x `n` elements, 0.4 m square, under a sand layer (static) or a falling
/// block (dynamic); the window is `subcycles` SPH steps.
std::string scene(int n, double spacing_mm, bool dynamic) {
    const std::string dp = std::to_string(spacing_mm) + " mm";
    // The plate's first wall layer is at t/2 - dp/2 = 2 mm - dp/2; the first centres 2h = 2.6 dp
    // above it, the box half a spacing below them.
    const double bottom = 2.0 + 1.6 * spacing_mm;
    std::string text = R"(
[case]
end_time = "10 s"
[[material]]
name = "sand"
model = "drucker_prager"
density = "1600 kg/m^3"
youngs_modulus = "10 MPa"
poisson_ratio = 0.3
friction_angle = "30 deg"
cohesion = "0 Pa"
dilatancy_angle = "0 deg"
cone_fit = "compression"
[[material]]
name = "steel"
model = "linear_elastic"
density = "7850 kg/m^3"
youngs_modulus = "210 GPa"
poisson_ratio = 0.3
[sph]
[sph.artificial_viscosity]
alpha = 0.5
[sph.contact]
stiffness = "10 MPa"
damping_ratio = 1.0
[[sph.body]]
name = "sand"
material = "sand"
spacing = ")" + dp + R"("
velocity = "0 0 )" + std::string(dynamic ? "-2" : "0") +
                       R"( m/s"
[sph.body.shape]
type = "box"
min = "0 0 )" + std::to_string(bottom) +
                       R"( mm"
max = "400 400 )" + std::to_string(bottom + 100.0) +
                       R"( mm"
[fem]
analysis = ")" + std::string(dynamic ? "dynamic" : "static") +
                       R"("
)" + std::string(dynamic ? "time_step = \"1 s\"\n" : "") +
                       R"([[fem.shell]]
name = "plate"
material = "steel"
thickness = "4 mm"
generator = "plate"
length_x = "400 mm"
length_y = "400 mm"
elements_x = )" + std::to_string(n) +
                       "\nelements_y = " + std::to_string(n) + R"(
[[fem.shell.boundary]]
node_set = "x0"
dofs = "all"
[[fem.shell.boundary]]
node_set = "x1"
dofs = "all"
[[fem.shell.boundary]]
node_set = "y0"
dofs = "all"
[[fem.shell.boundary]]
node_set = "y1"
dofs = "all"
[coupling]
window = "1 s"
)" + std::string(dynamic ? "max_iterations = 20\n" : "") +
                       R"([[coupling.interface]]
part = "plate"
side = "positive"
)";
    return text;
}

void run(int n, double spacing, bool dynamic, int ratio, int windows) {
    auto document = io::CaseDocument::from_string(scene(n, spacing, dynamic), "bench.toml");
    const io::SceneSettings settings = io::read_scene_settings(*document, "bench");
    const auto materials = materials::read_material_library(document->root());
    auto model = coupling::read_coupled_model(document->root(), settings, materials);
    for (const std::string& line : document->take_notices()) {
        std::fprintf(stderr, "%s\n", line.c_str());
    }
    const double window = ratio * model->sph().stable_time_step();
    const fem::SparseSolver::Totals before = fem::SparseSolver::totals();
    double t = 0.0;
    for (int w = 0; w < windows; ++w) {
        model->advance(t, window);
        t += window;
    }
    const fem::SparseSolver::Totals after = fem::SparseSolver::totals();
    const coupling::CouplingMonitor& m = model->monitor();
    const double factor =
        after.factorization - before.factorization + after.analysis - before.analysis;
    const double solve = after.solve - before.solve;
    const double assembly = m.fem_seconds() - factor - solve;
    const double share = (m.map_seconds() + m.fem_seconds()) / m.sand_seconds();
    std::printf("%-8s %4d x %-4d %6lld %4d %10.3f %8.3f %9.3f %8.3f %8.3f %8.1f %%\n",
                dynamic ? "dynamic" : "static", n, n,
                static_cast<long long>(model->sph().point_count()), ratio, m.sand_seconds(),
                m.map_seconds(), assembly, factor, solve, 100.0 * share);
}

} // namespace

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 24;
    const double spacing = argc > 2 ? std::atof(argv[2]) : 20.0;
    const int windows = argc > 3 ? std::atoi(argv[3]) : 20;
    std::printf("coupling cost split: %d windows per run, plate %d x %d MITC4, sand at %g mm\n",
                windows, n, n, spacing);
    std::printf("%-8s %11s %6s %4s %10s %8s %9s %8s %8s %9s\n", "shell", "elements", "points",
                "sub", "SPH [s]", "map [s]", "assem [s]", "fact [s]", "solve[s]", "coupling");
    for (const bool dynamic : {false, true}) {
        for (const int ratio : {1, 10, 100}) {
            run(n, spacing, dynamic, ratio, windows);
        }
    }
    return 0;
}
