#include "particles/sink.hpp"

#include "io/binary_stream.hpp"
#include "io/output_streams.hpp"
#include "io/steady_rate.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace grainload::particles {

double Outlet::rate(double gravity, int dimension) const {
    const double root_g = std::sqrt(gravity);
    const double reduced = kBeverlooGrain * grain_size;
    if (dimension == 2 || length > 0.0) {
        return kBeverlooSlot * bulk_density * root_g * (dimension == 2 ? 1.0 : length - reduced) *
               std::pow(width - reduced, 1.5);
    }
    return kBeverlooCircle * bulk_density * root_g * std::pow(width - reduced, 2.5);
}

std::string Outlet::form(int dimension) const {
    std::string grain = "k d = 0 (no grain_size in the material)";
    if (grain_size > 0.0) {
        char text[160];
        std::snprintf(text, sizeof text, "k d = 1.5 x %g m (grain_size of material '%s')",
                      grain_size, grain_material.c_str());
        grain = text;
    }
    const char* law = dimension == 2 ? "C' rho_b sqrt(g) (B - k d)^1.5 per metre, C' = 1.03"
                      : length > 0.0 ? "C' rho_b sqrt(g) (L - k d) (B - k d)^1.5, C' = 1.03"
                                     : "C rho_b sqrt(g) (D - k d)^2.5, C = 0.58";
    return std::string("Beverloo, Leniger & van de Velde 1961: ") + law + "; " + grain;
}

Index SinkSet::collect_departures(const ParticleView& p, double time, std::vector<char>& gone) {
    (void)time;
    Index flagged = 0;
    for (Index i = 0; i < p.size(); ++i) {
        if (p.is_wall(i) || gone[static_cast<std::size_t>(i)]) {
            continue;
        }
        for (Sink& sink : sinks_) {
            if ((sink.body < 0 || sink.body == p.body_id[i]) &&
                sink.region.contains(p.position[i])) {
                gone[static_cast<std::size_t>(i)] = 1;
                sink.discharged += p.mass[i];
                ++flagged;
                break;
            }
        }
    }
    return flagged;
}

double SinkSet::discharged() const {
    double sum = 0.0;
    for (const Sink& sink : sinks_) {
        sum += sink.discharged;
    }
    return sum;
}

bool SinkSet::record(double time) {
    if (!history_times_.empty() && !(time > history_times_.back())) {
        return false;
    }
    history_times_.push_back(time);
    std::vector<double> row;
    for (const Sink& sink : sinks_) {
        row.push_back(sink.discharged);
    }
    history_.push_back(std::move(row));
    return true;
}

std::string SinkSet::csv_header() const {
    const std::string mass_unit = dimension_ == 2 ? "kg_per_m" : "kg";
    return "time_s,sink,discharged_mass_" + mass_unit + ",rate_" + mass_unit + "_per_s\n";
}

std::string SinkSet::last_rows() const {
    std::ostringstream out;
    out.precision(10);
    const std::size_t k = history_times_.size() - 1;
    for (std::size_t s = 0; k < history_times_.size() && s < sinks_.size(); ++s) {
        const double rate = k == 0 ? 0.0
                                   : (history_[k][s] - history_[k - 1][s]) /
                                         (history_times_[k] - history_times_[k - 1]);
        out << history_times_[k] << ',' << sinks_[s].name << ',' << history_[k][s] << ',' << rate
            << '\n';
    }
    return out.str();
}

void SinkSet::at_output(double time, io::OutputStreams& output) {
    if (record(time)) {
        output.open("discharge.csv", csv_header()).append(last_rows());
    }
}

void SinkSet::append_results(std::vector<io::ResultFigure>& results) const {
    const std::string mass_unit = dimension_ == 2 ? "kg/m" : "kg";
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t s = 0; s < sinks_.size(); ++s) {
        const std::string prefix = "sink_" + sinks_[s].name;
        results.push_back(
            {prefix + "_discharged_mass", sinks_[s].discharged, mass_unit, std::nullopt, ""});
        std::vector<double> mass;
        for (const auto& row : history_) {
            mass.push_back(row[s]);
        }
        // summary.json writes NaN as null: too little discharged, or too few output instants.
        const auto fit = io::steady_rate(history_times_, mass);
        const auto beverloo = outlet_rate(s);
        results.push_back({prefix + "_steady_rate", fit ? fit->rate : nan, mass_unit + "/s",
                           beverloo, beverloo ? sinks_[s].outlet->form(dimension_) : ""});
        results.push_back(
            {prefix + "_steady_window_start", fit ? fit->start : nan, "s", std::nullopt, ""});
        results.push_back(
            {prefix + "_steady_window_end", fit ? fit->end : nan, "s", std::nullopt, ""});
    }
}

std::optional<double> SinkSet::outlet_rate(std::size_t s) const {
    const Sink& sink = sinks_.at(s);
    if (!sink.outlet) {
        return std::nullopt;
    }
    return share_ * sink.outlet->rate(gravity_, dimension_);
}

std::vector<double> SinkSet::state() const {
    std::vector<double> state{static_cast<double>(history_times_.size())};
    for (const Sink& sink : sinks_) {
        state.push_back(sink.discharged);
    }
    for (std::size_t k = 0; k < history_times_.size(); ++k) {
        state.push_back(history_times_[k]);
        state.insert(state.end(), history_[k].begin(), history_[k].end());
    }
    return state;
}

void SinkSet::set_state(const std::vector<double>& state) {
    const std::size_t sinks = sinks_.size();
    const auto rows = !state.empty() ? io::state_count(state[0], static_cast<double>(state.size()),
                                                       "the sinks' history rows")
                                     : 0;
    if (state.empty() || state.size() != 1 + sinks + rows * (1 + sinks)) {
        throw std::runtime_error("checkpoint: the sinks' state does not match the case's " +
                                 std::to_string(sinks) + " sinks");
    }
    std::size_t k = 1;
    for (Sink& sink : sinks_) {
        sink.discharged = state[k++];
    }
    history_times_.clear();
    history_.clear();
    for (std::size_t r = 0; r < rows; ++r) {
        history_times_.push_back(state[k++]);
        history_.emplace_back(state.begin() + static_cast<std::ptrdiff_t>(k),
                              state.begin() + static_cast<std::ptrdiff_t>(k + sinks));
        k += sinks;
    }
}

void SinkSet::write_checkpoint(std::ostream& out) const {
    io::write_array(out, state());
}

void SinkSet::read_checkpoint(std::istream& in) {
    std::vector<double> values;
    io::read_array(in, values);
    set_state(values);
}

} // namespace grainload::particles
