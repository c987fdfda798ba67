// Shell FEM solve benchmark: the standard benchmarks at increasing mesh sizes, with accuracy
// beside the time spent in assembly, factorisation and solution and the peak memory.
// Usage: shell_solve [largest n for the Scordelis-Lo roof and the plate, default 64]
//                    [plate n ...: only these plate meshes, e.g. 410 for about 1e6 DOF]
#include "fem/shell_benchmarks.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sys/resource.h>

namespace {

using namespace grainload;
using namespace grainload::fem;
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

double peak_memory_mib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

struct Timing {
    double assembly = 0.0;
    double factorisation = 0.0;
    double solution = 0.0;
    std::string solver;
    double gflops = 0.0; ///< factorisation rate of the supernodal Cholesky [GFlop/s]
};

/// One linear solve, timed phase by phase (the same steps as ShellAnalysis::solve_linear).
Timing timed_linear_solve(ShellAnalysis& analysis) {
    Timing t;
    const std::vector<Index>& eq = analysis.equation_numbers();
    SparseSolver::Matrix k;
    Eigen::VectorXd internal;
    const auto t0 = Clock::now();
    analysis.assemble(&k, internal);
    const auto t1 = Clock::now();
    SparseSolver solver;
    solver.factorize(k);
    const auto t2 = Clock::now();
    Eigen::VectorXd rhs(analysis.free_dof_count());
    for (std::size_t d = 0; d < eq.size(); ++d) {
        if (eq[d] >= 0) {
            rhs(eq[d]) = analysis.reference_load()(static_cast<Eigen::Index>(d));
        }
    }
    const Eigen::VectorXd x = solver.solve(rhs);
    const auto t3 = Clock::now();
    Eigen::VectorXd full = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(eq.size()));
    for (std::size_t d = 0; d < eq.size(); ++d) {
        if (eq[d] >= 0) {
            full(static_cast<Eigen::Index>(d)) = x(eq[d]);
        }
    }
    analysis.update_state(full);
    t.assembly = seconds(t0, t1);
    t.factorisation = seconds(t1, t2);
    t.solution = seconds(t2, t3);
    t.solver = std::string(SparseSolver::name(solver.method()));
    t.gflops = solver.cholesky_flops() / std::max(solver.factorization_seconds(), 1e-9) / 1e9;
    return t;
}

void print_row(const char* name, int n, Index dofs, double value, double reference,
               const Timing& t) {
    std::printf("%-20s %5d %9lld %12.7g %+8.3f %% %9.3f %9.3f %9.3f %9.1f %7.2f  %s\n", name, n,
                static_cast<long long>(dofs), value,
                reference != 0.0 ? 100.0 * (value / reference - 1.0) : 0.0, t.assembly,
                t.factorisation, t.solution, peak_memory_mib(), t.gflops, t.solver.c_str());
}

void run_benchmark(const std::function<ShellBenchmark(int)>& make, int n) {
    ShellBenchmark b = make(n);
    const Timing t = timed_linear_solve(*b.analysis);
    print_row(b.name.c_str(), n, b.analysis->free_dof_count(), b.monitored_value(), b.reference, t);
}

/// Simply supported square plate (a = 1 m, t = 0.01 m, steel) under uniform pressure;
/// reference: Kirchhoff plate centre deflection 0.00406235 q a^4 / D (Timoshenko &
/// Woinowsky-Krieger 1959, Table 8). Edges as bench/calculix/write_inp.py's default "hard"
/// support, so that the CalculiX plate rows compare like with like: all translations fixed and
/// no rotation about the edge normal (dw/ds = 0 along the edge, Kirchhoff's support).
void run_plate(int n) {
    const double young = 2.1e11, nu = 0.3, t = 0.01, q = 1e3;
    const materials::LinearElastic steel(materials::ElasticConstants::from_young(7850, young, nu));
    ShellAnalysis analysis(make_plate(1.0, 1.0, n, n, t), steel, Kinematics::linear, 2);
    const ShellMesh& mesh = analysis.mesh();
    for (const char* edge : {"x0", "x1"}) {
        analysis.prescribe(mesh.node_set(edge), {0, 1, 2, 3});
    }
    for (const char* edge : {"y0", "y1"}) {
        analysis.prescribe(mesh.node_set(edge), {0, 1, 2, 4});
    }
    analysis.add_pressure(-q);
    const Timing timing = timed_linear_solve(analysis);
    const double d = young * t * t * t / (12.0 * (1.0 - nu * nu));
    const double reference = 0.00406235 * q / d;
    const Index centre = mesh.nearest_node(Vec3(0.5, 0.5, 0.0));
    print_row("SS plate (pressure)", n, analysis.free_dof_count(),
              std::abs(analysis.displacement(centre).z()), reference, timing);
}

} // namespace

int main(int argc, char** argv) {
    const int largest = argc > 1 ? std::atoi(argv[1]) : 64;
    std::printf("%-20s %5s %9s %12s %11s %9s %9s %9s %9s %7s  %s\n", "benchmark", "n", "DOF",
                "value", "error", "assemb s", "factor s", "solve s", "peak MiB", "GFlop/s",
                "solver");
    if (argc > 2) { // explicit plate meshes only (the large single runs)
        for (int i = 2; i < argc; ++i) {
            run_plate(std::atoi(argv[i]));
        }
        return 0;
    }
    for (int n = 4; n <= largest; n *= 2) {
        run_benchmark(scordelis_lo_roof, n);
    }
    for (int n = 4; n <= std::min(largest, 64); n *= 2) {
        run_benchmark(pinched_cylinder, n);
    }
    for (int n = 4; n <= std::min(largest, 64); n *= 2) {
        run_benchmark(pinched_hemisphere, n);
    }
    for (int n = 8; n <= 2 * largest; n *= 2) {
        run_plate(n);
    }
    return 0;
}
