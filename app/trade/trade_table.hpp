#pragma once
// The table of a grainload trade sweep: each run's figures against the most accurate run's.

#include "app/trade/trade_grid.hpp"

#include <optional>
#include <string>
#include <vector>

namespace grainload::app {

/// One figure of a run's summary.json.
struct TradeFigure {
    std::string name;
    std::string unit;
    std::optional<double> value;           ///< null in the summary (a diverged figure): none
    std::optional<double> reference_error; ///< the summary's relative_error, if it has a reference
};

/// What one run of a sweep produced.
struct TradeResult {
    /// "completed" or "unstable" (summary.json's status), "bad_input" (exit 2 without a
    /// summary), "failed" (any other end without a summary: exit 1, a signal, a crash).
    std::string status = "failed";
    int exit_code = -1;                ///< -1: ended by a signal
    double elapsed_s = 0.0;            ///< the run's process, start to end, as the sweep timed it
    std::optional<double> wall_time_s; ///< summary.json's (the time loop alone)
    std::optional<long long> steps;
    std::optional<long long> particles;
    std::vector<TradeFigure> figures;

    const TradeFigure* figure(const std::string& name) const;
};

/// Reads `directory`/summary.json, if any, into a result with the given exit code and time.
TradeResult read_trade_result(const std::string& directory, int exit_code, double elapsed_s);

/// A figure's change counts as within budget up to this many of its round-off standard
/// deviations when that exceeds the budget: a run of the ensemble's own distribution lies within
/// 2 sigma of its mean about 95 % of the time (normal scatter), so a change below it cannot be
/// told from round-off.
inline constexpr double kNoiseSigmas = 2.0;

/// Each run's figures against the most accurate run's, and the knee.
struct TradeAnalysis {
    std::size_t best = 0;             ///< the most accurate run (index into the runs)
    std::vector<std::size_t> members; ///< the round-off ensemble's other runs (--noise)
    std::vector<std::string> figures; ///< the figures that count for the budget
    /// Per figure: what changes are measured against: the mean over the completed runs of the
    /// ensemble (the most accurate run and its members) when two or more have the figure,
    /// otherwise the most accurate run's value; none when that is missing.
    std::vector<std::optional<double>> reference;
    /// Per figure: the ensemble's sample standard deviation over |reference|; none without two
    /// values (no --noise, or members that failed).
    std::vector<std::optional<double>> noise;
    /// Per figure: the largest |change| within budget: max(budget, kNoiseSigmas * noise).
    std::vector<double> tolerance;
    /// Per run and figure: (value - reference) / |reference|; 0 when both are 0, +-inf when
    /// only the reference is 0; none when either value is missing.
    std::vector<std::vector<std::optional<double>>> change;
    std::vector<bool> within_budget; ///< completed, and |change| <= tolerance for every figure
    /// The run of least elapsed time within budget (ties: fewer steps), not counting the
    /// ensemble's members (they repeat the most accurate setting); none when the most accurate
    /// run did not complete.
    std::optional<std::size_t> knee;

    /// The ensemble member number of run r: 0 for the most accurate run, k for its k-th
    /// member, -1 for any other run and for every run without an ensemble.
    int member(std::size_t r) const;
};

/// `figures` empty: every figure of the most accurate run. A named figure that the most
/// accurate run lacks is refused (io::CaseError listing those it has). `members`: the runs of
/// the most accurate run's round-off ensemble besides itself (empty without --noise).
TradeAnalysis analyse_trade(const std::vector<TradeResult>& results, std::size_t best,
                            std::vector<std::string> figures, double budget,
                            const std::vector<std::size_t>& members = {});

/// trade.csv: one row per run and figure (one row with an empty figure for a run without
/// figures): run, one column per axis key (its value in that run), status, exit_code,
/// elapsed_s, wall_time_s, steps, particles, figure, unit, value, change, noise, tolerance,
/// reference_error, within_budget, most_accurate, noise_member, knee. Written atomically.
void write_trade_csv(const std::string& path, const std::vector<TradeAxis>& axes,
                     const std::vector<TradeRun>& grid, const std::vector<TradeResult>& results,
                     const TradeAnalysis& analysis);

/// The cells of one CSV line, quotes ("a, b" and doubled "") undone.
std::vector<std::string> split_csv_line(const std::string& line);

/// Parses "2%" or "0.02" (a relative error > 0); throws io::CaseError.
double parse_budget(const std::string& text);

} // namespace grainload::app
