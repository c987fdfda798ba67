#include "sph/source.hpp"

#include "io/binary_stream.hpp"
#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "sph/body_generator.hpp"
#include "sph/sph_case_reader.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grainload::sph {

namespace dim = io::dimension;

namespace {

// A step owes whole particles once the owed mass reaches one particle's mass; the sum of the
// steps' rate * dt differs from the exact product by round-off, which must not hold a
// particle back for a step (a few hundred ulps of a particle mass is far below any physics).
constexpr double kOwedRoundOff = 1e-12;

/// Mass rate: kg/s in 3D, kg/(m s) in plane strain (masses there are per metre of depth).
io::Dimension mass_rate_dimension(int dimension) {
    return dimension == 2 ? io::Dimension{1, -1, -1, 0} : io::Dimension{1, 0, -1, 0};
}

/// start and end: times, or "phase:NAME" (the phase's start, resolved by apply_phase_starts).
/// An end before the start is refused where the case fixes both: two times, or two phases
/// (which begin in the order of the table).
void read_window(const io::CaseTable& table, const particles::PhaseSequence* phases,
                 SourceSet::Source& source) {
    if (const auto phase = read_phase_reference(table, "start", phases)) {
        source.start_phase = *phase;
    } else {
        source.start = table.quantity_or("start", dim::kTime, 0.0);
    }
    if (const auto phase = read_phase_reference(table, "end", phases)) {
        source.end_phase = *phase;
    } else if (table.has("end")) {
        source.end = table.quantity("end", dim::kTime);
    }
    const bool times = source.start_phase < 0 && source.end_phase < 0;
    const bool both_phases = source.start_phase >= 0 && source.end_phase >= 0;
    if ((times && !(source.end > source.start)) ||
        (both_phases && !(source.end_phase > source.start_phase))) {
        table.fail("end", "expected an end after start");
    }
}

} // namespace

void SourceSet::apply_phase_starts(const particles::PhaseSequence& phases) {
    for (Source& source : sources_) {
        if (source.start_phase >= 0) {
            source.start = phases.start(source.start_phase);
        }
        if (source.end_phase >= 0) {
            source.end = phases.start(source.end_phase);
        }
    }
}

SourceSet::SourceSet(const io::CaseTable& sph, const std::vector<std::string>& body_names,
                     const std::vector<int>& body_material, const std::vector<double>& body_density,
                     double spacing, int dimension, const Vec3& gravity,
                     const particles::PhaseSequence* phases)
    : spacing_(spacing), dimension_(dimension) {
    for (const auto& table : sph.array_of_tables("source")) {
        Source source;
        source.name = table.string("name");
        io::refuse_repeated_name(table, sources_, source.name, "source", &Source::name);
        source.body = body_index(table, "body", body_names);
        const auto b = static_cast<std::size_t>(source.body);
        source.material = body_material[b];
        source.particle_mass = body_density[b] * std::pow(spacing, dimension);
        if (table.has("shape")) {
            if (table.has("min") || table.has("max")) {
                table.fail(table.has("min") ? "min" : "max",
                           "expected either min and max (a box) or a [sph.source.shape] table");
            }
            source.sites =
                generate_body_points(table.table("shape"), spacing, dimension, body_density[b]);
            Vec3 lower = source.sites.front(), upper = lower;
            for (const Vec3& x : source.sites) {
                lower = lower.cwiseMin(x);
                upper = upper.cwiseMax(x);
            }
            // The sites' box, grown by half a spacing: the cells they stand for.
            const Vec3 half = Vec3::Constant(0.5 * spacing);
            source.region = io::Region::box(lower - half, upper + half, dimension);
        } else {
            const Vec3 lower = table.vector("min", dim::kLength);
            const Vec3 upper = table.vector("max", dim::kLength);
            for (int a = 0; a < dimension; ++a) {
                if (!(upper[a] - lower[a] >= spacing)) {
                    table.fail("max", "expected max above min by at least the body's spacing (" +
                                          std::to_string(spacing) + " m) in every direction");
                }
            }
            source.region = io::Region::box(lower, upper, dimension);
            source.sites = lattice(source.region, spacing, dimension);
        }
        // Lowest sites first (against gravity), so that a source as tall as the fill creates
        // its particles row by row from the bottom up; the order within a row is the lattice's.
        if (gravity.squaredNorm() > 0.0) {
            const Vec3 up = -gravity.normalized();
            std::stable_sort(source.sites.begin(), source.sites.end(),
                             [&](const Vec3& p, const Vec3& q) {
                                 return p.dot(up) < q.dot(up) - 1e-9 * spacing;
                             });
        }
        source.mass_rate = table.positive_quantity("mass_rate", mass_rate_dimension(dimension));
        read_window(table, phases, source);
        source.velocity = table.vector_or("velocity", dim::kVelocity, Vec3::Zero());
        if (dimension == 2) {
            source.velocity.z() = 0.0;
        }
        sources_.push_back(std::move(source));
    }
}

std::vector<Vec3> SourceSet::lattice(const io::Region& box, double spacing, int dimension) {
    std::array<int, 3> count{1, 1, 1};
    for (int a = 0; a < dimension; ++a) {
        count[a] = std::max(1, static_cast<int>(std::floor((box.upper[a] - box.lower[a]) / spacing *
                                                           (1.0 + kOwedRoundOff))));
    }
    std::vector<Vec3> sites;
    for (int k = 0; k < count[2]; ++k) {
        for (int j = 0; j < count[1]; ++j) {
            for (int i = 0; i < count[0]; ++i) {
                Vec3 x = box.lower + spacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
                if (dimension == 2) {
                    x.z() = 0.0;
                }
                sites.push_back(x);
            }
        }
    }
    return sites;
}

std::vector<particles::Arrival> SourceSet::collect(const particles::ParticleView& particles,
                                                   double t, double dt) {
    std::vector<particles::Arrival> arrivals;
    for (std::size_t s = 0; s < sources_.size(); ++s) {
        Source& source = sources_[s];
        const double active = std::min(t + dt, source.end) - std::max(t, source.start);
        if (active > 0.0) {
            source.owed += source.mass_rate * active;
        }
        if (source.owed >= source.particle_mass * (1.0 - kOwedRoundOff)) {
            collect_one(source, particles, arrivals);
        }
    }
    return arrivals;
}

void SourceSet::collect_one(Source& source, const particles::ParticleView& particles,
                            std::vector<particles::Arrival>& arrivals) const {
    // Only particles within a spacing of the box can block a site: gather them once.
    const double gap = kMinimumGap * spacing_;
    std::vector<Vec3> near;
    const Vec3 margin = Vec3::Constant(spacing_);
    for (Index i = 0; i < particles.size(); ++i) {
        const Vec3& x = particles.position[i];
        if ((x.array() >= (source.region.lower - margin).array()).all() &&
            (x.array() <= (source.region.upper + margin).array()).all()) {
            near.push_back(x);
        }
    }
    for (const particles::Arrival& a : arrivals) {
        near.push_back(a.position);
    }
    const std::size_t n = source.sites.size();
    for (std::size_t tried = 0; tried < n; ++tried) {
        if (source.owed < source.particle_mass * (1.0 - kOwedRoundOff)) {
            break;
        }
        const Vec3& site = source.sites[source.cursor];
        source.cursor = (source.cursor + 1) % n;
        const bool free = std::none_of(near.begin(), near.end(), [&](const Vec3& x) {
            return (x - site).squaredNorm() < gap * gap;
        });
        if (!free) {
            continue;
        }
        arrivals.push_back(
            {site, source.velocity, source.particle_mass, source.body, source.material});
        near.push_back(site);
        source.owed -= source.particle_mass;
        source.created += source.particle_mass;
    }
}

double SourceSet::created() const {
    double sum = 0.0;
    for (const Source& source : sources_) {
        sum += source.created;
    }
    return sum;
}

std::vector<double> SourceSet::state() const {
    std::vector<double> state;
    for (const Source& source : sources_) {
        state.push_back(source.owed);
        state.push_back(source.created);
        state.push_back(static_cast<double>(source.cursor));
    }
    return state;
}

void SourceSet::set_state(const std::vector<double>& state) {
    if (state.size() != 3 * sources_.size()) {
        throw std::runtime_error("checkpoint: the sources' state does not match the case's " +
                                 std::to_string(sources_.size()) + " sources");
    }
    for (std::size_t s = 0; s < sources_.size(); ++s) {
        sources_[s].owed = state[3 * s];
        sources_[s].created = state[3 * s + 1];
        // The next site to try: an index into the sites.
        sources_[s].cursor =
            io::state_count(state[3 * s + 2], static_cast<double>(sources_[s].sites.size()) - 1.0,
                            "the cursor of source '" + sources_[s].name + "'");
    }
}

void SourceSet::collect_arrivals(const particles::ParticleView& particles, double t, double dt,
                                 std::vector<particles::Arrival>& arrivals) {
    const std::vector<particles::Arrival> mine = collect(particles, t, dt);
    arrivals.insert(arrivals.end(), mine.begin(), mine.end());
}

void SourceSet::write_checkpoint(std::ostream& out) const {
    io::write_array(out, state());
}

void SourceSet::read_checkpoint(std::istream& in) {
    std::vector<double> values;
    io::read_array(in, values);
    set_state(values);
}

} // namespace grainload::sph
