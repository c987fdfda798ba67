#pragma once
// The named tolerances a gold file gives its figures: each bound defined once, with its source.

#include <array>
#include <cmath>
#include <string_view>

namespace grainload::testing {

/// A bound on how far a figure may move from its gold value: |run - gold| <= absolute +
/// relative |gold|. The absolute part is in the figure's own SI unit and only matters for
/// figures whose gold value is zero or near it.
struct NamedTolerance {
    std::string_view name;
    double relative;
    double absolute;
};

/// The tolerances of the gold files (cases/*/gold/*.json). Gold values are the figures of a run
/// on one thread: OMP_NUM_THREADS=1 and --threads 1, one thread for the SPH sums and for the
/// BLAS under the shells' sparse factorisation. The tests run on one thread (--threads 1, or
/// OMP_NUM_THREADS=1 for the suite) or on all cores (the default: 2 on the 2-core machine
/// where CI runs `ctest -j2`), and another thread count sums the SPH pairs and the
/// factorisation's blocks in another order (docs/user-guide.md, "--threads"). Each bound is
/// sized on the spread between one and two threads (OMP_NUM_THREADS and --threads 1, then 2) of
/// the 30 small cases the regression tests run (`scripts/update_gold.py --spread`, the 2-core
/// machine, Release build): the largest spread of the cases that carry the name takes up
/// about half of its bound, room for the orders of other thread counts, and no more.
/// scripts/update_gold.py reads the names from here.
inline constexpr std::array<NamedTolerance, 4> kTolerances = {{
    // Counts and figures the case file fixes: steps, particles, material points, shell nodes,
    // simulated time, initial and created mass. Measured: identical on 1 and 2 threads in
    // every small case.
    {"exact", 0.0, 0.0},
    // Sums whose order changes with the thread count, where round-off stays round-off: bodies
    // settling, slumping, avalanching and sliding, filling, staggered coupled plates, and the
    // two short discharges that measured so (silo_hopper_small, hopper_closure_small).
    // Measured over these 22 cases: at most 6.2e-11 of the figure beyond the absolute part
    // (tilting_plate_cone_small's plate force, 4.3e-9 N of 69 N, after the heap avalanched;
    // 9.5e-12 elsewhere) and 1.6e-12 absolute (sand_on_plate_small's sand momentum, 1.6e-12
    // kg m/s of 1.4e-3; a container wall's horizontal force, a residual of 6.5e-12 N, moved
    // 1.1e-12 N).
    {"round_off", 1.5e-10, 3e-12},
    // Coupled runs whose shells are solved by Newton iterations to a force tolerance
    // (fem/newton_solver.hpp) on a sparse factorisation whose BLAS sums in blocks per thread:
    // round-off in the load and in the factors moves the converged answer within that
    // tolerance. Measured over sand_on_strip_small and silo_janssen_small: 1.8e-6 N on a
    // support reaction of 1 mN (silo_janssen_small's base_a_z), 1.5e-6 N on one of 4.6 N
    // (3.2e-7 of it); the wall forces of 16 N moved by 2.7e-8 of themselves.
    {"solver", 1e-7, 4e-6},
    // Discharges: grains leaving through an orifice amplify a change of summation order as
    // any granular flow does (docs/theory/sph.md, "Neighbours"). Measured over the five hopper
    // and silo discharges and closures (small) and the wagon's: 1.44e-6 of the figure beyond
    // the absolute part (silo_discharge_small's right wall force, 2.1e-5 N of 14.2 N) and
    // 8.6e-8 N on the horizontal 5 mN of hopper_shell_small's interface force.
    {"granular_flow", 5e-6, 1.5e-7},
}};

/// The tolerance called `name`; nullptr when none is.
inline const NamedTolerance* find_tolerance(std::string_view name) {
    for (const NamedTolerance& tolerance : kTolerances) {
        if (tolerance.name == name) {
            return &tolerance;
        }
    }
    return nullptr;
}

/// How far a figure of gold value `gold` may move under `tolerance`.
inline double bound(const NamedTolerance& tolerance, double gold) {
    return tolerance.absolute + tolerance.relative * std::abs(gold);
}

inline bool within(const NamedTolerance& tolerance, double gold, double run) {
    return std::abs(run - gold) <= bound(tolerance, gold);
}

} // namespace grainload::testing
