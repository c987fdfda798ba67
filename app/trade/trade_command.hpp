#pragma once
// The grainload trade command: a sweep of case-key values run as subprocesses.

#include "app/trade/trade_grid.hpp"

#include <optional>
#include <string>
#include <vector>

namespace grainload::app {

/// What `grainload trade` was asked to do.
struct TradeOptions {
    std::string case_file;
    std::string out;                    ///< --out DIR (required)
    std::vector<TradeAxis> axes;        ///< --vary (with their --link and --reference)
    std::vector<std::string> figures;   ///< --figures; empty: all of the most accurate run's
    std::vector<std::string> overrides; ///< --set, applied to every run before the axes
    double budget = 0.02;               ///< --budget
    int jobs = 1;                       ///< --jobs
    std::optional<int> threads;         ///< --threads per run; default cores / jobs
    /// --noise N: the most accurate run repeated N - 1 times with gravity perturbed at 1e-8
    /// (noise_runs), so that each figure's round-off scatter sets a floor under the budget.
    int noise = 1;
};

/// Parses `grainload trade CASE.toml --vary ... --out DIR` (argv[1] is "trade"). Throws
/// io::CaseError (exit 2) on a malformed line.
TradeOptions parse_trade_options(int argc, const char* const* argv);

/// Runs the sweep (docs/user-guide/trade.md): every run of the grid not finished in an earlier
/// invocation, as `grainload run` subprocesses of this executable, --jobs at a time; then
/// DIR/trade.csv, the summary on stdout, the knee, and DIR/trade.svg by scripts/plot_trade.py.
/// Returns the exit code: 0 when the sweep ran (failed runs are rows of the table).
int run_trade(const TradeOptions& options);

/// `grainload trade ...`, from main().
int trade_main(int argc, const char* const* argv);

/// The usage lines of `grainload trade`, for --help.
const char* trade_usage();

} // namespace grainload::app
