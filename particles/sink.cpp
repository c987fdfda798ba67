#include "particles/sink.hpp"

#include "io/binary_stream.hpp"
#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "io/output_streams.hpp"
#include "io/steady_rate.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace grainload::particles {

namespace dim = io::dimension;

namespace {

io::Region read_region(const io::CaseTable& table, int dimension) {
    const std::string type = table.choice("type", {"plane", "box"});
    if (type == "plane") {
        const Vec3 point = table.vector("point", dim::kLength);
        Vec3 normal = table.vector("normal", dim::kNone);
        if (dimension == 2) {
            normal.z() = 0.0;
        }
        if (!(normal.norm() > 0.0)) {
            table.fail("normal", "expected a non-zero normal pointing out of the scene");
        }
        return io::Region::half_space(point, normal, dimension);
    }
    const Vec3 lower = table.vector("min", dim::kLength);
    const Vec3 upper = table.vector("max", dim::kLength);
    for (int a = 0; a < dimension; ++a) {
        if (!(upper[a] > lower[a])) {
            table.fail("max", "expected max > min in every direction");
        }
    }
    return io::Region::box(lower, upper, dimension);
}

std::optional<Outlet> read_outlet(const io::CaseTable& table, int dimension) {
    if (!table.has("outlet_width")) {
        for (const char* key : {"outlet_length", "bulk_density"}) {
            if (table.has(key)) {
                table.fail(key, "needs outlet_width (the outlet's effective width)");
            }
        }
        return std::nullopt;
    }
    Outlet outlet;
    outlet.width = table.positive_quantity("outlet_width", dim::kLength);
    if (table.has("outlet_length")) {
        if (dimension == 2) {
            table.fail("outlet_length", "plane strain: the outlet is a slot per metre of depth");
        }
        outlet.length = table.positive_quantity("outlet_length", dim::kLength);
    }
    outlet.bulk_density = table.positive_quantity("bulk_density", dim::kDensity);
    return outlet;
}

/// The grain size of the bodies the sink takes (`body`, or every body): the one their
/// materials declare; bodies without one (a structure, a continuum) do not count. Two different
/// sizes leave Beverloo's k d undefined: the sink must name its body. An outlet no wider than
/// k d passes nothing in Beverloo's law, which is then no reference.
void read_grain(const io::CaseTable& table, int body, const std::vector<SinkSet::BodyGrain>& grains,
                Outlet& outlet) {
    for (std::size_t b = 0; b < grains.size(); ++b) {
        const auto& grain = grains[b];
        if ((body >= 0 && static_cast<int>(b) != body) || !grain.size) {
            continue;
        }
        if (outlet.grain_size > 0.0 && *grain.size != outlet.grain_size) {
            table.fail("outlet_width", "the bodies it takes declare different grain sizes "
                                       "(materials '" +
                                           outlet.grain_material + "' and '" + grain.material +
                                           "'): expected `body`, the one whose grains flow");
        }
        outlet.grain_size = *grain.size;
        outlet.grain_material = grain.material;
    }
    const double reduced = kBeverlooGrain * outlet.grain_size;
    if (outlet.width <= reduced || (outlet.length > 0.0 && outlet.length <= reduced)) {
        table.fail(outlet.length > 0.0 && outlet.length <= reduced ? "outlet_length"
                                                                   : "outlet_width",
                   "expected an outlet wider than k d = " + std::to_string(reduced) +
                       " m (Beverloo's k = 1.5 times the grain_size of material '" +
                       outlet.grain_material + "'): narrower, the law gives no flow");
    }
}

} // namespace

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

SinkSet::SinkSet(const io::CaseTable& scene, const BodyNames& bodies, int dimension, double gravity,
                 double share, const std::vector<BodyGrain>& grains)
    : dimension_(dimension), gravity_(gravity), share_(share) {
    for (const auto& table : scene.array_of_tables("sink")) {
        Sink sink;
        sink.name = table.string("name");
        io::refuse_repeated_name(table, sinks_, sink.name, "sink", &Sink::name);
        sink.region = read_region(table, dimension);
        if (table.has("body")) {
            sink.body = bodies.index(table, "body");
        }
        sink.outlet = read_outlet(table, dimension);
        if (sink.outlet) {
            read_grain(table, sink.body, grains, *sink.outlet);
        }
        sinks_.push_back(std::move(sink));
    }
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
