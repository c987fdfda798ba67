#pragma once
// The console's report of a trade sweep: its table of runs, knee and round-off noise.

#include "app/trade/trade_grid.hpp"
#include "app/trade/trade_table.hpp"

#include <string>
#include <vector>

namespace grainload::app {

/// A duration as the table prints it: "12.3 s" below 100 s, "123 s" above.
std::string seconds(double s);

/// One row per run (status, elapsed time, steps, the largest change of the budget's figures
/// against the most accurate run, round-off members and runs within the budget marked), then
/// the knee: the cheapest run within `budget`.
void print_table(const std::vector<TradeRun>& grid, const std::vector<TradeResult>& results,
                 const TradeAnalysis& analysis, double budget);

/// The round-off ensemble's scatter per figure and the tolerance it sets (nothing without
/// --noise).
void print_noise(const TradeAnalysis& analysis, double budget);

} // namespace grainload::app
