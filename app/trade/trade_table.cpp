#include "app/trade/trade_table.hpp"

#include "io/atomic_file.hpp"
#include "io/case_error.hpp"
#include "io/json_value.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <ostream>

namespace grainload::app {

namespace {

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) {
        return text;
    }
    std::string out = "\"";
    for (const char c : text) {
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    }
    return out + "\"";
}

std::string csv_number(std::optional<double> value) {
    if (!value) {
        return "";
    }
    if (std::isinf(*value)) {
        return *value > 0.0 ? "inf" : "-inf";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", *value);
    return text;
}

std::optional<double> change_of(const TradeFigure* figure, std::optional<double> reference) {
    if (figure == nullptr || !figure->value || !reference) {
        return std::nullopt;
    }
    const double best = *reference;
    const double value = *figure->value;
    if (best == 0.0) {
        return value == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), value);
    }
    return (value - best) / std::abs(best);
}

/// The values of figure `name` in the completed runs of the ensemble (best and members).
std::vector<double> ensemble_values(const std::vector<TradeResult>& results, std::size_t best,
                                    const std::vector<std::size_t>& members,
                                    const std::string& name) {
    std::vector<double> values;
    std::vector<std::size_t> runs{best};
    runs.insert(runs.end(), members.begin(), members.end());
    for (const std::size_t r : runs) {
        const TradeFigure* f = results.at(r).figure(name);
        if (results[r].status == "completed" && f != nullptr && f->value) {
            values.push_back(*f->value);
        }
    }
    return values;
}

/// Sets the reference, noise and tolerance of every figure of `a` (see TradeAnalysis).
void set_references(TradeAnalysis& a, const std::vector<TradeResult>& results, double budget) {
    const TradeResult& best = results.at(a.best);
    for (const std::string& name : a.figures) {
        const std::vector<double> values = ensemble_values(results, a.best, a.members, name);
        const TradeFigure* own = best.figure(name);
        std::optional<double> reference = own != nullptr ? own->value : std::nullopt;
        std::optional<double> noise;
        if (best.status == "completed" && values.size() >= 2) {
            double mean = 0.0;
            for (const double v : values) {
                mean += v / static_cast<double>(values.size());
            }
            double squares = 0.0;
            for (const double v : values) {
                squares += (v - mean) * (v - mean);
            }
            reference = mean;
            const double sd = std::sqrt(squares / static_cast<double>(values.size() - 1));
            noise = mean != 0.0 ? sd / std::abs(mean)
                                : (sd == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
        }
        a.reference.push_back(reference);
        a.noise.push_back(noise);
        a.tolerance.push_back(noise ? std::max(budget, kNoiseSigmas * *noise) : budget);
    }
}

} // namespace

const TradeFigure* TradeResult::figure(const std::string& name) const {
    for (const TradeFigure& f : figures) {
        if (f.name == name) {
            return &f;
        }
    }
    return nullptr;
}

TradeResult read_trade_result(const std::string& directory, int exit_code, double elapsed_s) {
    TradeResult result;
    result.exit_code = exit_code;
    result.elapsed_s = elapsed_s;
    result.status = exit_code == 2 ? "bad_input" : "failed";
    const std::string path = directory + "/summary.json";
    if (!std::filesystem::exists(path)) {
        return result;
    }
    io::JsonValue summary;
    try {
        summary = io::read_json_file(path);
    } catch (const io::JsonError&) {
        return result; // a summary cut short by a crash: the run failed
    }
    result.status = summary.string_at("status").value_or("failed");
    result.wall_time_s = summary.number_at("wall_time_s");
    if (const auto steps = summary.number_at("steps")) {
        result.steps = static_cast<long long>(*steps);
    }
    if (const auto particles = summary.number_at("particles")) {
        result.particles = static_cast<long long>(*particles);
    }
    if (const io::JsonValue* figures = summary.find("results")) {
        for (const auto& [name, entry] : figures->object) {
            TradeFigure f;
            f.name = name;
            f.unit = entry.string_at("unit").value_or("");
            f.value = entry.number_at("value");
            f.reference_error = entry.number_at("relative_error");
            result.figures.push_back(std::move(f));
        }
    }
    return result;
}

int TradeAnalysis::member(std::size_t r) const {
    if (members.empty()) {
        return -1;
    }
    if (r == best) {
        return 0;
    }
    const auto at = std::find(members.begin(), members.end(), r);
    return at == members.end() ? -1 : static_cast<int>(at - members.begin()) + 1;
}

TradeAnalysis analyse_trade(const std::vector<TradeResult>& results, std::size_t best,
                            std::vector<std::string> figures, double budget,
                            const std::vector<std::size_t>& members) {
    TradeAnalysis a;
    a.best = best;
    a.members = members;
    const TradeResult& reference = results.at(best);
    if (figures.empty()) {
        for (const TradeFigure& f : reference.figures) {
            figures.push_back(f.name);
        }
    }
    const bool reference_ok = reference.status == "completed";
    for (const std::string& name : figures) {
        if (reference_ok && reference.figure(name) == nullptr) {
            std::string known;
            for (const TradeFigure& f : reference.figures) {
                known += (known.empty() ? "" : ", ") + f.name;
            }
            throw io::CaseError("command line: --figures: the most accurate run has no figure '" +
                                name + "' (it has: " + (known.empty() ? "none" : known) + ")");
        }
    }
    a.figures = figures;
    set_references(a, results, budget);
    for (const TradeResult& r : results) {
        std::vector<std::optional<double>> changes;
        bool ok = reference_ok && r.status == "completed";
        for (std::size_t f = 0; f < figures.size(); ++f) {
            changes.push_back(change_of(r.figure(figures[f]), a.reference[f]));
            ok = ok && changes.back() && std::abs(*changes.back()) <= a.tolerance[f];
        }
        a.change.push_back(std::move(changes));
        a.within_budget.push_back(ok);
    }
    for (std::size_t r = 0; r < results.size(); ++r) {
        if (!a.within_budget[r] || a.member(r) > 0) {
            continue;
        }
        if (!a.knee) {
            a.knee = r;
            continue;
        }
        const TradeResult& k = results[*a.knee];
        const bool cheaper = results[r].elapsed_s < k.elapsed_s ||
                             (results[r].elapsed_s == k.elapsed_s &&
                              results[r].steps.value_or(0) < k.steps.value_or(0));
        a.knee = cheaper ? r : *a.knee;
    }
    return a;
}

void write_trade_csv(const std::string& path, const std::vector<TradeAxis>& axes,
                     const std::vector<TradeRun>& grid, const std::vector<TradeResult>& results,
                     const TradeAnalysis& analysis) {
    io::write_file_atomically(path, [&](std::ostream& out) {
        out << "run";
        for (const TradeAxis& axis : axes) {
            out << ',' << csv_field(axis.key);
        }
        out << ",status,exit_code,elapsed_s,wall_time_s,steps,particles,figure,unit,value,change,"
               "noise,tolerance,reference_error,within_budget,most_accurate,noise_member,knee\n";
        for (std::size_t r = 0; r < grid.size(); ++r) {
            const TradeResult& result = results[r];
            std::string head = csv_field(grid[r].id);
            for (std::size_t a = 0; a < axes.size(); ++a) {
                head += ',' + csv_field(axes[a].values[grid[r].index[a]]);
            }
            head += ',' + result.status + ',' + std::to_string(result.exit_code) + ',' +
                    csv_number(result.elapsed_s) + ',' + csv_number(result.wall_time_s) + ',' +
                    (result.steps ? std::to_string(*result.steps) : "") + ',' +
                    (result.particles ? std::to_string(*result.particles) : "") + ',';
            const int member = analysis.member(r);
            const std::string tail = std::string(",") + (analysis.within_budget[r] ? "1" : "0") +
                                     ',' + (analysis.best == r ? "1" : "0") + ',' +
                                     (member >= 0 ? std::to_string(member) : "") + ',' +
                                     (analysis.knee == r ? "1" : "0") + '\n';
            if (result.figures.empty()) {
                out << head << ",,,,,," << tail;
            }
            for (const TradeFigure& f : result.figures) {
                const auto at = std::find(analysis.figures.begin(), analysis.figures.end(), f.name);
                std::optional<double> change;
                std::optional<double> noise;
                std::optional<double> tolerance;
                if (at != analysis.figures.end()) {
                    const auto i = static_cast<std::size_t>(at - analysis.figures.begin());
                    change = analysis.change[r][i];
                    noise = analysis.noise[i];
                    tolerance = analysis.tolerance[i];
                }
                out << head << csv_field(f.name) << ',' << csv_field(f.unit) << ','
                    << csv_number(f.value) << ',' << csv_number(change) << ',' << csv_number(noise)
                    << ',' << csv_number(tolerance) << ',' << csv_number(f.reference_error) << tail;
            }
        }
    });
}

std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            cells.back() += '"';
            ++i;
        } else if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            cells.emplace_back();
        } else {
            cells.back() += c;
        }
    }
    return cells;
}

double parse_budget(const std::string& text) {
    const bool percent = text.ends_with('%');
    const std::string number = percent ? text.substr(0, text.size() - 1) : text;
    double value = 0.0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (error != std::errc() || end != number.data() + number.size() || !(value > 0.0) ||
        !std::isfinite(value)) {
        throw io::CaseError("command line: --budget expects a relative error > 0, as '2%' or "
                            "'0.02', got '" +
                            text + "'");
    }
    return percent ? value / 100.0 : value;
}

} // namespace grainload::app
