#pragma once
// A run's summary.json against the gold file of its case: every figure where it was.

#include "io/json_value.hpp"
#include "support/cli_runner.hpp"
#include "support/tolerances.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace grainload::testing {

/// Top-level entries of summary.json that depend on the machine, not on the case, and so are
/// no figures of the gold file: the thread count the run was given, the wall-clock and CPU
/// times, the rates per second derived from them, and the estimate of `grainload check` (its
/// wall times come from this machine's calibration). Strings (the case file's path, the
/// version, the git hash, the status) and the model's description are not figures.
/// scripts/update_gold.py reads this list from here.
inline constexpr std::array<std::string_view, 6> kMachineFigures = {"threads",
                                                                    "wall_time_s",
                                                                    "cpu_time_s",
                                                                    "particle_steps_per_second",
                                                                    "shell_node_steps_per_second",
                                                                    "estimate"};

/// A figure of a run: its value (nullopt where summary.json writes null, a figure that could
/// not be measured) and unit.
struct GoldFigure {
    std::string name;
    std::optional<double> value;
    std::string unit;
    std::string tolerance; ///< the name of its bound in tolerances.hpp (gold files only)
};

/// `cases/<folder>/gold/<stem>.json` of the case file `cases/<folder>/<stem>.toml`.
inline std::string gold_path(const std::string& case_file) {
    const std::filesystem::path file(case_file);
    return (file.parent_path() / "gold" / file.stem()).string() + ".json";
}

inline bool is_machine_figure(std::string_view name) {
    for (std::string_view machine : kMachineFigures) {
        if (name == machine) {
            return true;
        }
    }
    return false;
}

/// The figures of a parsed summary.json: the top-level numbers other than kMachineFigures
/// (steps, particles, simulated time ...) and every entry of "results".
inline std::vector<GoldFigure> summary_figures(const io::JsonValue& summary) {
    std::vector<GoldFigure> figures;
    for (const auto& [name, value] : summary.object) {
        if (value.type == io::JsonValue::Type::number && !is_machine_figure(name)) {
            figures.push_back({name, value.number, "", ""});
        }
    }
    const io::JsonValue* results = summary.find("results");
    for (std::size_t i = 0; results != nullptr && i < results->object.size(); ++i) {
        const auto& [name, figure] = results->object[i];
        figures.push_back(
            {name, figure.number_at("value"), figure.string_at("unit").value_or(""), ""});
    }
    return figures;
}

/// The figures of a gold file, {"case": ..., "figures": {name: {value, unit, tolerance}}}.
inline std::vector<GoldFigure> gold_figures(const io::JsonValue& gold) {
    std::vector<GoldFigure> figures;
    const io::JsonValue* entries = gold.find("figures");
    for (std::size_t i = 0; entries != nullptr && i < entries->object.size(); ++i) {
        const auto& [name, figure] = entries->object[i];
        figures.push_back({name, figure.number_at("value"), figure.string_at("unit").value_or(""),
                           figure.string_at("tolerance").value_or("")});
    }
    return figures;
}

inline std::string figure_text(const std::optional<double>& value, const std::string& unit) {
    if (!value) {
        return "null";
    }
    std::ostringstream text;
    text.precision(12);
    text << *value << (unit.empty() ? "" : " " + unit);
    return text.str();
}

/// What is wrong with one gold figure against the run's `run` (absent: nullptr); empty when
/// the run's value lies within the gold figure's named tolerance.
inline std::string gold_difference(const GoldFigure& gold, const GoldFigure* run) {
    if (run == nullptr) {
        return "figure '" + gold.name + "' is in the gold file but not in this run";
    }
    const NamedTolerance* tolerance = find_tolerance(gold.tolerance);
    if (tolerance == nullptr) {
        return "figure '" + gold.name + "' names tolerance '" + gold.tolerance +
               "', which tests/support/tolerances.hpp does not define";
    }
    const bool agree = gold.value && run->value ? within(*tolerance, *gold.value, *run->value)
                                                : gold.value.has_value() == run->value.has_value();
    if (agree) {
        return "";
    }
    std::ostringstream text;
    text.precision(3);
    text << "figure '" << gold.name << "': this run " << figure_text(run->value, run->unit)
         << ", gold " << figure_text(gold.value, gold.unit) << ", tolerance '" << tolerance->name
         << "' (" << tolerance->relative << " relative + " << tolerance->absolute << " absolute)";
    if (gold.value && run->value) {
        const double off = std::abs(*run->value - *gold.value);
        text << " allows " << bound(*tolerance, *gold.value) << ", off by " << off;
        if (*gold.value != 0.0) {
            text << " (" << off / std::abs(*gold.value) << " relative)";
        }
    }
    return text.str();
}

/// Every disagreement between the summary.json at `summary_file` and the gold file of
/// `case_file` (a path relative to the source tree): figures off by more than their tolerance,
/// figures of the gold file missing from the run and figures of the run missing from the gold
/// file (a new figure is reviewed before it is kept). Empty when they agree.
inline std::vector<std::string> gold_differences(const std::string& summary_file,
                                                 const std::string& case_file) {
    const std::string gold_file = gold_path(case_file);
    if (!std::filesystem::exists(source_path(gold_file))) {
        return {"no gold file " + gold_file + ": write it with scripts/update_gold.py " +
                case_file};
    }
    const io::JsonValue summary = io::read_json_file(summary_file);
    const io::JsonValue* overrides = summary.find("overrides");
    if (overrides != nullptr && !overrides->array.empty()) {
        return {"the run overrides keys of the case (--set); its gold file holds the case as "
                "shipped"};
    }
    const std::vector<GoldFigure> run = summary_figures(summary);
    const std::vector<GoldFigure> gold = gold_figures(io::read_json_file(source_path(gold_file)));
    const auto named = [](const std::vector<GoldFigure>& figures,
                          const std::string& name) -> const GoldFigure* {
        for (const GoldFigure& figure : figures) {
            if (figure.name == name) {
                return &figure;
            }
        }
        return nullptr;
    };
    std::vector<std::string> differences;
    for (const GoldFigure& figure : gold) {
        if (std::string difference = gold_difference(figure, named(run, figure.name));
            !difference.empty()) {
            differences.push_back(std::move(difference));
        }
    }
    for (const GoldFigure& figure : run) {
        if (named(gold, figure.name) == nullptr) {
            differences.push_back("figure '" + figure.name + "' (" +
                                  figure_text(figure.value, figure.unit) +
                                  ") is in this run but not in the gold file");
        }
    }
    return differences;
}

/// Fails the test, once per figure, where the run of the shipped case file `case_file` (relative
/// to the source tree, run without --set) into the folder `out` moved from its gold file. Each
/// message names the case, the figure, the gold and the run's value and the tolerance.
inline void expect_matches_gold(const std::string& out, const std::string& case_file) {
    for (const std::string& difference : gold_differences(out + "/summary.json", case_file)) {
        ADD_FAILURE() << case_file << " against " << gold_path(case_file) << ": " << difference;
    }
}

} // namespace grainload::testing
