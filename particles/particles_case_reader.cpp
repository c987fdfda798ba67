#include "particles/particles_case_reader.hpp"

#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "io/units.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace grainload::particles {

namespace dim = io::dimension;

namespace {

constexpr std::string_view kPhasePrefix = "phase:";
constexpr double kNever = std::numeric_limits<double>::infinity();

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

/// A settle fraction lies strictly between 0 and 1 ([sph.settle] and a settled phase alike).
double read_fraction(const io::CaseTable& table) {
    const double fraction = table.number("kinetic_energy_fraction");
    if (!(fraction > 0.0 && fraction < 1.0)) {
        table.fail("kinetic_energy_fraction", "expected a fraction between 0 and 1, e.g. 1e-3");
    }
    return fraction;
}

/// `end` of a phase table: a time, "settled" or "discharged"; anything else is refused here,
/// with the three forms named, rather than as a malformed time.
PhaseSequence::End read_end_kind(const io::CaseTable& table) {
    const std::string text = table.string("end");
    if (text == "settled") {
        return PhaseSequence::End::settled;
    }
    if (text == "discharged") {
        return PhaseSequence::End::discharged;
    }
    std::string error;
    const auto quantity = io::parse_quantity(text, &error);
    if (!quantity || !(quantity->dimension == dim::kTime)) {
        table.fail("end", "expected a time (e.g. \"1.2 s\"), \"settled\" (with "
                          "kinetic_energy_fraction) or \"discharged\" (with discharged_mass), "
                          "got \"" +
                              text + "\"");
    }
    return PhaseSequence::End::time;
}

/// Mass discharged: kg in 3D, kg per metre of depth in plane strain (the particles' masses).
io::Dimension discharged_mass_dimension(int dimension) {
    return dimension == 2 ? io::Dimension{1, -1, 0, 0} : dim::kMass;
}

/// The phase of one table; `previous_end` is the stated end of the phase before when that and
/// every earlier phase end at stated times (+inf otherwise), which a stated end must follow.
PhaseSequence::Phase read_phase(const io::CaseTable& table, double previous_end) {
    PhaseSequence::Phase phase;
    phase.name = table.string("name");
    if (phase.name.empty()) {
        table.fail("name", "expected a non-empty name");
    }
    phase.end = table.has("end") ? read_end_kind(table) : PhaseSequence::End::run;
    using End = PhaseSequence::End;
    if (phase.end == End::time) {
        phase.end_time = table.positive_quantity("end", dim::kTime);
        if (std::isfinite(previous_end) && !(phase.end_time > previous_end)) {
            std::ostringstream message;
            message << "expected an end after the previous phase's end (" << previous_end << " s)";
            table.fail("end", message.str());
        }
    }
    if (phase.end == End::settled) {
        phase.watch = SettleWatch(read_fraction(table), kNever);
    } else if (table.has("kinetic_energy_fraction")) {
        table.fail("kinetic_energy_fraction", "applies to end = \"settled\" only");
    }
    if (phase.end == End::discharged) {
        phase.discharged_mass = table.positive_quantity(
            "discharged_mass", discharged_mass_dimension(table.spatial_dimension()));
        phase.mass_unit = table.spatial_dimension() == 2 ? "kg/m" : "kg";
    } else if (table.has("discharged_mass")) {
        table.fail("discharged_mass", "applies to end = \"discharged\" only");
    }
    return phase;
}

} // namespace

SinkSet read_sinks(const io::CaseTable& scene, const BodyNames& bodies, int dimension,
                   double gravity, double share, const std::vector<SinkSet::BodyGrain>& grains) {
    std::vector<SinkSet::Sink> sinks;
    for (const auto& table : scene.array_of_tables("sink")) {
        SinkSet::Sink sink;
        sink.name = table.string("name");
        io::refuse_repeated_name(table, sinks, sink.name, "sink", &SinkSet::Sink::name);
        sink.region = read_region(table, dimension);
        if (table.has("body")) {
            sink.body = io::index_by_name(
                table, "body", bodies.names, [](const std::string& s) { return s; },
                bodies.declared_in.c_str());
        }
        sink.outlet = read_outlet(table, dimension);
        if (sink.outlet) {
            read_grain(table, sink.body, grains, *sink.outlet);
        }
        sinks.push_back(std::move(sink));
    }
    return SinkSet(std::move(sinks), dimension, gravity, share);
}

SettleWatch read_settle_watch(const io::CaseTable& settle) {
    const double fraction = read_fraction(settle);
    const double after =
        settle.quantity_or("after", dim::kTime, io::default_value(kSettleKeys, "after"));
    if (!(after >= 0.0)) {
        settle.fail("after", "expected a time >= 0 s");
    }
    return SettleWatch(fraction, after);
}

PhaseSequence read_phases(const io::CaseTable& root) {
    const auto tables = root.array_of_tables("phase");
    std::vector<PhaseSequence::Phase> phases;
    double previous_end = 0.0;
    for (std::size_t k = 0; k < tables.size(); ++k) {
        PhaseSequence::Phase phase = read_phase(tables[k], previous_end);
        io::refuse_repeated_name(tables[k], phases, phase.name, "phase",
                                 &PhaseSequence::Phase::name);
        if (phase.end == PhaseSequence::End::run && k + 1 < tables.size()) {
            tables[k].fail("", "only the last phase may run to the end of the run: expected "
                               "end = a time, \"settled\" or \"discharged\"");
        }
        previous_end = phase.end == PhaseSequence::End::time ? phase.end_time : kNever;
        phases.push_back(std::move(phase));
    }
    return PhaseSequence(std::move(phases));
}

std::optional<int> read_phase_reference(const io::CaseTable& table, std::string_view key,
                                        const PhaseSequence* phases) {
    const auto text = table.string_if(key);
    if (!text || text->substr(0, kPhasePrefix.size()) != kPhasePrefix) {
        return std::nullopt;
    }
    const std::string_view name = std::string_view(*text).substr(kPhasePrefix.size());
    const std::vector<PhaseSequence::Phase> none;
    const std::vector<PhaseSequence::Phase>& list = phases != nullptr ? phases->phases() : none;
    for (std::size_t k = 0; k < list.size(); ++k) {
        if (list[k].name == name) {
            return static_cast<int>(k);
        }
    }
    const std::string known = io::quoted_names(list, &PhaseSequence::Phase::name);
    table.fail(key, "expected phase:NAME with the name of a [[phase]] (" +
                        (known.empty() ? std::string("none defined") : known) + "), got \"" +
                        *text + "\"");
}

bool window_in_order(double start, double end, int start_phase, int end_phase) {
    if (start_phase < 0 && end_phase < 0) {
        return end > start;
    }
    return start_phase < 0 || end_phase < 0 || end_phase > start_phase;
}

} // namespace grainload::particles
