#include "sph/source.hpp"

#include "io/binary_stream.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grainload::sph {

namespace {

// A step owes whole particles once the owed mass reaches one particle's mass; the sum of the
// steps' rate * dt differs from the exact product by round-off, which must not hold a
// particle back for a step (a few hundred ulps of a particle mass is far below any physics).
constexpr double kOwedRoundOff = 1e-12;

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
