#include "app/trade/trade_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

namespace grainload::app {

namespace {

std::string percent(double relative) {
    if (std::isinf(relative)) {
        return "inf";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.2f %%", 100.0 * relative);
    return text;
}

/// A relative scatter: in percent, or as a plain number where that would read 0.00 %.
std::string scatter(double relative) {
    if (std::isinf(relative) || relative >= 1e-4 || relative == 0.0) {
        return percent(relative);
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.1e", relative);
    return text;
}

/// The largest |change| of a run over the budget's figures, and which figure; none if any is
/// missing.
std::optional<std::pair<double, std::string>> worst_change(const TradeAnalysis& a, std::size_t r) {
    std::pair<double, std::string> worst{0.0, ""};
    for (std::size_t f = 0; f < a.figures.size(); ++f) {
        if (!a.change[r][f]) {
            return std::nullopt;
        }
        if (std::abs(*a.change[r][f]) >= worst.first) {
            worst = {std::abs(*a.change[r][f]), a.figures[f]};
        }
    }
    return worst;
}

} // namespace

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, s < 100.0 ? "%.1f s" : "%.0f s", s);
    return text;
}

void print_table(const std::vector<TradeRun>& grid, const std::vector<TradeResult>& results,
                 const TradeAnalysis& a, double budget) {
    std::size_t width = 3;
    for (const TradeRun& run : grid) {
        width = std::max(width, run.id.size());
    }
    std::printf("%-*s  %-10s %10s %10s  %s\n", static_cast<int>(width), "run", "status", "elapsed",
                "steps", "max |change| against the most accurate run");
    for (std::size_t r = 0; r < grid.size(); ++r) {
        const auto worst = worst_change(a, r);
        std::string change = worst ? percent(worst->first) + " (" + worst->second + ")" : "-";
        if (a.member(r) >= 0) {
            change += a.member(r) == 0 ? "  (most accurate run, round-off member 0)"
                                       : "  (round-off member " + std::to_string(a.member(r)) + ")";
        } else if (r == a.best) {
            change = "(most accurate run)";
        }
        std::printf("%-*s  %-10s %10s %10s  %s%s\n", static_cast<int>(width), grid[r].id.c_str(),
                    results[r].status.c_str(), seconds(results[r].elapsed_s).c_str(),
                    results[r].steps ? std::to_string(*results[r].steps).c_str() : "-",
                    change.c_str(), a.within_budget[r] && a.member(r) < 0 ? "  within budget" : "");
    }
    if (!a.knee) {
        std::printf("knee: none (the most accurate run %s did not complete)\n",
                    grid[a.best].id.c_str());
        return;
    }
    const std::size_t k = *a.knee;
    const auto worst = worst_change(a, k);
    std::printf("knee (budget %s on %zu figures%s): %s, %s, %.1fx less time than the most "
                "accurate run %s (%s); max |change| %s\n",
                percent(budget).c_str(), a.figures.size(),
                a.members.empty() ? "" : ", or 2 sigma of round-off where larger",
                grid[k].id.c_str(), seconds(results[k].elapsed_s).c_str(),
                results[a.best].elapsed_s / std::max(results[k].elapsed_s, 1e-9),
                grid[a.best].id.c_str(), seconds(results[a.best].elapsed_s).c_str(),
                worst ? (percent(worst->first) + " (" + worst->second + ")").c_str() : "-");
}

/// The round-off ensemble's scatter per figure, and the tolerance it sets.
void print_noise(const TradeAnalysis& a, double budget) {
    if (a.members.empty()) {
        return;
    }
    std::printf("round-off noise (the most accurate run and %zu members, gravity x (1 +- k %.0e)); "
                "changes are against the ensemble's mean:\n",
                a.members.size(), kNoiseGravityStep);
    for (std::size_t f = 0; f < a.figures.size(); ++f) {
        if (!a.noise[f]) {
            std::printf("  %s: no scatter (fewer than two members completed with it)\n",
                        a.figures[f].c_str());
            continue;
        }
        const bool wider = a.tolerance[f] > budget;
        std::printf("  %s: mean %.6g, standard deviation %s of it; tolerance %s%s\n",
                    a.figures[f].c_str(), a.reference[f].value_or(0.0),
                    scatter(*a.noise[f]).c_str(), percent(a.tolerance[f]).c_str(),
                    wider ? " (2 sigma: the budget is below this figure's round-off scatter)" : "");
    }
}

} // namespace grainload::app
