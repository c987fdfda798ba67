#include "coupling/coupling_monitor.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <optional>
#include <string>
#include <vector>

namespace grainload::coupling {
namespace {

// The staggered static exchange on one degree of freedom: a wall of compliance C (U = C A)
// takes in window n the load A(n) and moves linearly from U(n-1) to U(n) while the sand
// pushes with a load whose window mean is P(n); the next window's load is
// A(n+1) = A(n) + omega (P(n) - A(n)) (coupled_model.cpp, CoupledModel::advance). The sand's
// work is P(n) (U(n) - U(n-1)) (the wall's velocity is constant in the window, so the mean
// load is exact), the shell's 1/2 (A(n-1) + A(n)) (U(n) - U(n-1)) (run_window).
struct Exchange {
    double compliance = 1e-3; // [m/N]
    double omega = 1.0;
    std::vector<double> applied{0.0}; // A(0) = 0
};

// Runs `windows` windows of 10 ms; `mean_load(u_start, u_end, n)` is the sand's mean load
// over window n while the wall moves from u_start to u_end. Returns the monitor.
CouplingMonitor run(Exchange& exchange, int windows,
                    const std::function<double(double, double, int)>& mean_load,
                    std::vector<std::optional<std::string>>* checks = nullptr,
                    double limit = 0.05) {
    CouplingMonitor monitor;
    double load = 0.0; // A(1): the first window's load, nothing produced yet
    for (int n = 1; n <= windows; ++n) {
        const double before = exchange.compliance * exchange.applied.back();
        const double after = exchange.compliance * load;
        const double produced = mean_load(before, after, n);
        WindowRecord record;
        record.time = 0.01 * n;
        record.length = 0.01;
        record.sand_work = produced * (after - before);
        record.shell_work = 0.5 * (exchange.applied.back() + load) * (after - before);
        monitor.add(record);
        if (checks != nullptr) {
            checks->push_back(monitor.check(limit, 0.0));
        }
        exchange.applied.push_back(load);
        load += exchange.omega * (produced - load);
    }
    exchange.applied.push_back(load);
    return monitor;
}

// A load that rises over 20 windows to 1000 N and stays (a sand settling on a static wall),
// relaxation 0.5: the error equals the staggered exchange's identity
// E = 1/2 sum d(n) C d(n) + 1/omega sum d(n+1) C d(n), d(n) = A(n) - A(n-1) (algebra from the
// update rule; round-off only, 1e-12), it is positive (the interface dissipates what a static
// wall cannot hold as vibration), and it is no diagnosis even against a limit it exceeds.
TEST(CouplingMonitor, ASettlingLoadIsDissipatedNotDiagnosed) {
    Exchange exchange;
    exchange.omega = 0.5;
    std::vector<std::optional<std::string>> checks;
    const auto ramp = [](double, double, int n) { return 1000.0 * std::min(1.0, n / 20.0); };
    const CouplingMonitor monitor = run(exchange, 60, ramp, &checks, 1e-3);
    const std::vector<double>& a = exchange.applied;
    double identity = 0.0;
    for (std::size_t n = 1; n + 1 < a.size(); ++n) {
        const double d = a[n] - a[n - 1];
        const double next = a[n + 1] - a[n];
        identity += exchange.compliance * (0.5 * d * d + next * d / exchange.omega);
    }
    EXPECT_NEAR(monitor.energy_error() / identity, 1.0, 1e-12);
    EXPECT_GT(monitor.energy_error(), 0.1 * monitor.sand_work());
    EXPECT_GT(monitor.relative_energy_error(0.0), 1e-3);
    EXPECT_NEAR(monitor.created_energy(), 0.0, 1e-12 * monitor.sand_work());
    for (const auto& check : checks) {
        EXPECT_FALSE(check.has_value()) << *check;
    }
}

// A load applied at once (1000 N in the first window, omega 1) is the textbook case: the sand
// works F . C F, the static wall stores 1/2 C F^2, and the half the wall does not hold as
// vibration is the interface's dissipation (1e-12: round-off).
TEST(CouplingMonitor, ASuddenLoadLosesHalfItsWorkOnAStaticWall) {
    Exchange exchange;
    const CouplingMonitor monitor = run(exchange, 10, [](double, double, int) { return 1000.0; });
    const double stored = 0.5 * exchange.compliance * 1000.0 * 1000.0;
    EXPECT_NEAR(monitor.shell_work() / stored, 1.0, 1e-12);
    EXPECT_NEAR(monitor.sand_work() / (2.0 * stored), 1.0, 1e-12);
    EXPECT_NEAR(monitor.created_energy(), 0.0, 1e-12);
}

// The sand as an elastic foundation behind the wall: its load falls by k_s per metre the wall
// gives way, P = F0 - k_s U, its window mean at the wall's mean position. With omega 1 the
// exchange runs A(n+1) = F0 - g (A(n-1) + A(n)) / 2, g = k_s C, whose roots solve
// l^2 + (g/2) l + g/2 = 0. g = 10: l = -1.38 and -3.62, the load alternates with growing
// amplitude, the shell receives more than the sand's work (the error falls below its largest
// value), and the watchdog names it once that creation passes the limit and has grown for
// kGrowthWindows windows. g = 0.25: |l|^2 = g/2 < 1, the oscillation decays, no diagnosis.
TEST(CouplingMonitor, AGrowingAlternationCreatesEnergyAndIsDiagnosed) {
    const auto foundation = [](double stiffness) {
        return
            [stiffness](double u0, double u1, int) { return 1000.0 - stiffness * 0.5 * (u0 + u1); };
    };
    Exchange unstable;
    std::vector<std::optional<std::string>> checks;
    const CouplingMonitor grown = run(unstable, 30, foundation(10.0 / 1e-3), &checks);
    EXPECT_LT(grown.energy_error(), 0.0);
    EXPECT_GT(grown.created_energy(), 0.05 * std::abs(grown.sand_work()));
    int first = 0;
    while (first < static_cast<int>(checks.size()) && !checks[static_cast<std::size_t>(first)]) {
        ++first;
    }
    ASSERT_LT(first, static_cast<int>(checks.size())) << "never diagnosed";
    // Not before the creation has grown for kGrowthWindows windows.
    EXPECT_GE(first + 1, CouplingMonitor::kGrowthWindows);
    const std::string& diagnosis = *checks[static_cast<std::size_t>(first)];
    EXPECT_NE(diagnosis.find("the interface created energy"), std::string::npos) << diagnosis;
    EXPECT_NE(diagnosis.find("coupling window " + std::to_string(first + 1)), std::string::npos)
        << diagnosis;

    Exchange stable;
    checks.clear();
    const CouplingMonitor settled = run(stable, 60, foundation(0.25 / 1e-3), &checks, 1e-3);
    // At rest the load is F0 / (1 + g) (the foundation's balance).
    EXPECT_NEAR(stable.applied.back() / (1000.0 / 1.25), 1.0, 1e-9);
    for (const auto& check : checks) {
        EXPECT_FALSE(check.has_value()) << *check;
    }
    EXPECT_GE(settled.energy_error(), 0.0);
}

// The checkpoint carries the largest error and its time, so a restarted run measures the
// creation from the same value: 14 values, and a monitor set from them diagnoses alike.
TEST(CouplingMonitor, TheCheckpointCarriesTheLargestError) {
    Exchange exchange;
    const CouplingMonitor monitor =
        run(exchange, 8, [](double u0, double u1, int) { return 1000.0 - 3e3 * 0.5 * (u0 + u1); });
    const std::vector<double> state = monitor.state();
    ASSERT_EQ(state.size(), 14u);
    CouplingMonitor restored;
    restored.set_state(state);
    EXPECT_EQ(restored.created_energy(), monitor.created_energy());
    EXPECT_EQ(restored.energy_error(), monitor.energy_error());
    EXPECT_THROW(restored.set_state(std::vector<double>(12, 0.0)), std::runtime_error);
}

} // namespace
} // namespace grainload::coupling
