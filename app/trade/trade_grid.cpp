#include "app/trade/trade_grid.hpp"

#include "io/case_error.hpp"
#include "io/units.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

namespace grainload::app {

namespace {

std::string trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
        return {};
    }
    return std::string(text.substr(first, text.find_last_not_of(" \t") - first + 1));
}

/// Splits at commas that stand outside quotes and brackets.
std::vector<std::string> split_values(std::string_view text) {
    std::vector<std::string> values;
    std::string current;
    int depth = 0;
    char quote = 0;
    for (const char c : text) {
        if (quote != 0) {
            quote = c == quote ? 0 : quote;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '[' || c == '{') {
            ++depth;
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == ',' && depth == 0) {
            values.push_back(trimmed(current));
            current.clear();
            continue;
        }
        current += c;
    }
    values.push_back(trimmed(current));
    return values;
}

/// The last name of a dotted key, without an [i] index: "sph.body[0].spacing" -> "spacing".
std::string leaf(std::string_view key) {
    const auto dot = key.rfind('.');
    std::string name(dot == std::string_view::npos ? key : key.substr(dot + 1));
    return name.substr(0, name.find('['));
}

/// A value as a quantity, its quotes dropped ("\"10 mm\"" and "10 mm" alike).
std::optional<io::Quantity> quantity_of(std::string value) {
    if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') &&
        value.back() == value.front()) {
        value = value.substr(1, value.size() - 2);
    }
    std::string error;
    return io::parse_quantity(value, &error);
}

/// A value as it may stand in a directory name.
std::string id_text(std::string_view value) {
    std::string out;
    for (const char c : value) {
        if (std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '+' || c == '-') {
            out += c;
        } else if (c == '/') {
            out += "per";
        } else if (c == '^') {
            out += 'e';
        } else if (c != ' ' && c != '"' && c != '\'') {
            out += '_';
        }
    }
    return out.empty() ? std::string("_") : out;
}

/// The score to minimise under a rule (the most accurate value has the lowest).
double score(AccuracyRule rule, double value) {
    switch (rule) {
    case AccuracyRule::smallest:
        return value;
    case AccuracyRule::closest_to_one:
        return value > 0.0 ? std::abs(std::log(value)) : std::numeric_limits<double>::infinity();
    case AccuracyRule::smallest_limit:
        return value > 0.0 ? value : std::numeric_limits<double>::infinity();
    case AccuracyRule::largest:
        return -value;
    case AccuracyRule::none:
        break;
    }
    return 0.0;
}

} // namespace

TradeAxis parse_trade_axis(std::string_view text, std::string_view option) {
    const std::string where =
        "command line: " + std::string(option) + " '" + std::string(text) + "': ";
    const auto equals = text.find('=');
    if (equals == std::string_view::npos || trimmed(text.substr(0, equals)).empty()) {
        throw io::CaseError(where + "expected KEY=V1,V2,... (e.g. 'sph.body[0].spacing=10 mm,"
                                    "5 mm')");
    }
    TradeAxis axis;
    axis.key = trimmed(text.substr(0, equals));
    axis.values = split_values(text.substr(equals + 1));
    for (std::size_t i = 0; i < axis.values.size(); ++i) {
        if (axis.values[i].empty()) {
            throw io::CaseError(where + "value " + std::to_string(i + 1) + " is empty");
        }
        if (std::find(axis.values.begin(), axis.values.begin() + static_cast<long>(i),
                      axis.values[i]) != axis.values.begin() + static_cast<long>(i)) {
            throw io::CaseError(where + "the value '" + axis.values[i] + "' is given twice");
        }
    }
    return axis;
}

void link_trade_axis(std::vector<TradeAxis>& axes, TradeAxis link) {
    if (axes.empty()) {
        throw io::CaseError("command line: --link '" + link.key +
                            "' must follow the --vary whose values it moves with");
    }
    TradeAxis& axis = axes.back();
    if (link.values.size() != axis.values.size()) {
        throw io::CaseError("command line: --link '" + link.key + "' has " +
                            std::to_string(link.values.size()) + " values, its --vary '" +
                            axis.key + "' has " + std::to_string(axis.values.size()) +
                            ": give one per value");
    }
    axis.linked.push_back(std::move(link));
}

void set_trade_reference(std::vector<TradeAxis>& axes, std::string_view text) {
    const auto equals = text.find('=');
    const std::string key = trimmed(text.substr(0, equals));
    const std::string value =
        equals == std::string_view::npos ? std::string() : trimmed(text.substr(equals + 1));
    for (TradeAxis& axis : axes) {
        if (axis.key != key) {
            continue;
        }
        if (std::find(axis.values.begin(), axis.values.end(), value) == axis.values.end()) {
            throw io::CaseError("command line: --reference '" + std::string(text) +
                                "': expected one of the --vary values of '" + key + "'");
        }
        axis.reference = value;
        return;
    }
    throw io::CaseError("command line: --reference '" + std::string(text) +
                        "': expected KEY=VALUE with KEY one of the --vary keys");
}

std::vector<TradeRun> trade_grid(const std::vector<TradeAxis>& axes) {
    std::vector<std::string> names;
    for (const TradeAxis& axis : axes) {
        names.push_back(leaf(axis.key));
    }
    // Two axes of the same last name ("body[0].spacing", "wall[0].spacing") use the full key.
    const std::vector<std::string> leaves = names;
    for (std::size_t a = 0; a < axes.size(); ++a) {
        if (std::count(leaves.begin(), leaves.end(), leaves[a]) > 1) {
            names[a] = id_text(axes[a].key);
        }
    }
    std::vector<TradeRun> runs(1);
    for (std::size_t a = 0; a < axes.size(); ++a) {
        std::vector<TradeRun> next;
        for (const TradeRun& run : runs) {
            for (std::size_t v = 0; v < axes[a].values.size(); ++v) {
                TradeRun r = run;
                r.index.push_back(v);
                r.id += (r.id.empty() ? "" : "-") + names[a] + "_" + id_text(axes[a].values[v]);
                r.overrides.push_back(axes[a].key + "=" + axes[a].values[v]);
                for (const TradeAxis& link : axes[a].linked) {
                    r.overrides.push_back(link.key + "=" + link.values[v]);
                }
                next.push_back(std::move(r));
            }
        }
        runs = std::move(next);
    }
    return runs;
}

AccuracyRule accuracy_rule(std::string_view key) {
    const std::string name = leaf(key);
    for (const char* smallest :
         {"spacing", "cfl_safety", "time_step", "window", "iteration_tolerance"}) {
        if (name == smallest) {
            return AccuracyRule::smallest;
        }
    }
    if (name == "stiffness_scale") {
        return AccuracyRule::closest_to_one;
    }
    if (name == "max_subcycles") {
        return AccuracyRule::smallest_limit;
    }
    if (name == "max_iterations") {
        return AccuracyRule::largest;
    }
    return AccuracyRule::none;
}

std::string describe(AccuracyRule rule) {
    switch (rule) {
    case AccuracyRule::smallest:
        return "the smallest value";
    case AccuracyRule::closest_to_one:
        return "the value closest to 1";
    case AccuracyRule::smallest_limit:
        return "the smallest positive value (0 = no limit)";
    case AccuracyRule::largest:
        return "the largest value";
    case AccuracyRule::none:
        break;
    }
    return "no rule (give --reference KEY=VALUE)";
}

std::vector<std::size_t> most_accurate(const std::vector<TradeAxis>& axes) {
    std::vector<std::size_t> best;
    for (const TradeAxis& axis : axes) {
        if (axis.reference) {
            best.push_back(static_cast<std::size_t>(
                std::find(axis.values.begin(), axis.values.end(), *axis.reference) -
                axis.values.begin()));
            continue;
        }
        const AccuracyRule rule = accuracy_rule(axis.key);
        if (rule == AccuracyRule::none) {
            throw io::CaseError("command line: --vary '" + axis.key +
                                "': no rule says which of its values is the most accurate; "
                                "give it with --reference '" +
                                axis.key + "=VALUE'");
        }
        std::size_t chosen = 0;
        double lowest = std::numeric_limits<double>::infinity();
        std::optional<io::Dimension> dimension;
        for (std::size_t v = 0; v < axis.values.size(); ++v) {
            const auto q = quantity_of(axis.values[v]);
            if (!q || (dimension && q->dimension != *dimension)) {
                throw io::CaseError("command line: --vary '" + axis.key + "': the value '" +
                                    axis.values[v] +
                                    "' is not a quantity comparable with the others; give the "
                                    "most accurate one with --reference");
            }
            dimension = q->dimension;
            if (const double s = score(rule, q->value); s < lowest) {
                lowest = s;
                chosen = v;
            }
        }
        best.push_back(chosen);
    }
    return best;
}

std::size_t find_run(const std::vector<TradeRun>& grid, const std::vector<std::size_t>& best) {
    for (std::size_t r = 0; r < grid.size(); ++r) {
        if (grid[r].index == best) {
            return r;
        }
    }
    return grid.size();
}

std::vector<TradeRun> noise_runs(const TradeRun& best, const std::array<double, 3>& gravity,
                                 int dimension, int members) {
    std::vector<TradeRun> runs;
    for (int k = 1; k < members; ++k) {
        const double step = kNoiseGravityStep * ((k + 1) / 2) * (k % 2 == 1 ? 1.0 : -1.0);
        std::string value = "\"";
        for (int d = 0; d < dimension; ++d) {
            char component[40];
            std::snprintf(component, sizeof component, "%.17g ",
                          gravity[static_cast<std::size_t>(d)] * (1.0 + step));
            value += component;
        }
        TradeRun run = best;
        run.id = best.id + "-noise_" + std::to_string(k);
        run.overrides.push_back("case.gravity=" + value + "m/s^2\"");
        runs.push_back(std::move(run));
    }
    return runs;
}

} // namespace grainload::app
