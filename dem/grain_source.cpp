#include "dem/grain_source.hpp"

#include "dem/grain_generator.hpp"
#include "io/binary_stream.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace grainload::dem {

namespace {

/// Draws of a grain's centre before its source's box counts as full for the step.
constexpr int kDraws = 100;

} // namespace

GrainSources::GrainSources(std::vector<SourceSettings> sources,
                           const std::vector<BodySettings>& bodies,
                           std::vector<double> body_density, const SphereSet& spheres,
                           const std::vector<PlaneWall>& walls)
    : bodies_(bodies), body_density_(std::move(body_density)), spheres_(spheres), walls_(walls) {
    for (SourceSettings& settings : sources) {
        Source source;
        source.generator.seed(settings.seed);
        source.settings = std::move(settings);
        sources_.push_back(std::move(source));
    }
}

double GrainSources::created_mass() const {
    double sum = 0.0;
    for (const Source& source : sources_) {
        sum += source.created_mass;
    }
    return sum;
}

void GrainSources::find_near(const SourceSettings& source) {
    // A sphere that can touch a grain in the box lies within the largest radius of the scene
    // and the grain's of it.
    const double largest = bodies_[static_cast<std::size_t>(source.body)].radius_max;
    near_.clear();
    for (Index i = 0; i < spheres_.size(); ++i) {
        const Vec3 reach = Vec3::Constant(largest + spheres_.radius[i]);
        const Vec3& x = spheres_.position[i];
        if ((x.array() > (source.min - reach).array()).all() &&
            (x.array() < (source.max + reach).array()).all()) {
            near_.push_back(i);
        }
    }
}

bool GrainSources::free(const Vec3& centre, double radius) const {
    for (const Index i : near_) {
        const double reach = radius + spheres_.radius[i];
        if ((spheres_.position[i] - centre).squaredNorm() < reach * reach) {
            return false;
        }
    }
    for (const auto& [other, other_radius] : placed_) {
        const double reach = radius + other_radius;
        if ((other - centre).squaredNorm() < reach * reach) {
            return false;
        }
    }
    return std::none_of(walls_.begin(), walls_.end(), [&](const PlaneWall& wall) {
        return !wall.removed && wall.touched_by(centre, radius);
    });
}

void GrainSources::add_placed(const particles::Arrival& arrival) {
    const auto body = static_cast<std::size_t>(arrival.body);
    const GrainShape shape = grain_shape(bodies_[body], arrival.radius, body_density_[body]);
    for (std::size_t s = 0; s < shape.offsets.size(); ++s) {
        placed_.emplace_back(arrival.position + arrival.orientation * shape.offsets[s],
                             shape.radii[s]);
    }
}

std::optional<particles::Arrival> GrainSources::draw(Source& source) {
    const SourceSettings& s = source.settings;
    const BodySettings& body = bodies_[static_cast<std::size_t>(s.body)];
    const double r = draw_radius(body, source.generator);
    const GrainShape shape = grain_shape(body, r, body_density_[static_cast<std::size_t>(s.body)]);
    for (int attempt = 0; attempt < kDraws; ++attempt) {
        // As a body's own grains are placed: a sphere keeps the identity, its draws are the
        // centre's alone; a clump's orientation comes first, then a centre where all of it lies
        // in the box, and each of its spheres must be free.
        const Eigen::Quaterniond turned = body.spheres > 1 ? random_orientation(source.generator)
                                                           : Eigen::Quaterniond::Identity();
        const Vec3 reach = grain_reach(shape, turned);
        Vec3 centre;
        for (int a = 0; a < 3; ++a) {
            centre[a] = s.min[a] + reach[a] +
                        (s.max[a] - s.min[a] - 2.0 * reach[a]) * uniform(source.generator);
        }
        bool fits = true;
        for (std::size_t k = 0; k < shape.offsets.size() && fits; ++k) {
            fits = free(centre + turned * shape.offsets[k], shape.radii[k]);
        }
        if (fits) {
            particles::Arrival arrival;
            arrival.position = centre;
            arrival.velocity = s.velocity;
            arrival.mass = shape.mass;
            arrival.body = s.body;
            arrival.material = body.material;
            arrival.radius = r;
            arrival.orientation = turned;
            return arrival;
        }
    }
    return std::nullopt;
}

void GrainSources::collect_arrivals(const particles::ParticleView& /*particles*/, double t,
                                    double dt, std::vector<particles::Arrival>& arrivals) {
    placed_.clear();
    for (const particles::Arrival& arrival : arrivals) {
        add_placed(arrival);
    }
    for (Source& source : sources_) {
        const SourceSettings& s = source.settings;
        // The share of the step inside [start, end].
        const double open = std::min(t + dt, s.end) - std::max(t, s.start);
        if (open > 0.0) {
            source.due += s.rate * open;
        }
        if (source.due >= 1.0) {
            find_near(s);
        }
        while (source.due >= 1.0 && (!s.count || source.created < *s.count)) {
            const auto arrival = draw(source);
            if (!arrival) {
                if (!source.waited) {
                    std::ostringstream text;
                    text << "source " << s.name << ": its box is full at t = " << t + dt
                         << " s; its grains wait for room";
                    events_.push_back(text.str());
                    source.waited = true;
                }
                break;
            }
            arrivals.push_back(*arrival);
            add_placed(*arrival);
            source.due -= 1.0;
            ++source.created;
            source.created_mass += arrival->mass;
        }
    }
}

void GrainSources::apply_phase_starts(const particles::PhaseSequence& phases) {
    for (Source& source : sources_) {
        if (source.settings.start_phase >= 0) {
            source.settings.start = phases.start(source.settings.start_phase);
        }
        if (source.settings.end_phase >= 0) {
            source.settings.end = phases.start(source.settings.end_phase);
        }
    }
}

void GrainSources::append_results(std::vector<io::ResultFigure>& results) const {
    for (const Source& source : sources_) {
        const std::string prefix = "source_" + source.settings.name;
        results.push_back(
            {prefix + "_created", static_cast<double>(source.created), "", std::nullopt, ""});
        results.push_back({prefix + "_created_mass", source.created_mass, "kg", std::nullopt, ""});
    }
}

void GrainSources::take_events(std::vector<std::string>& events) {
    events.insert(events.end(), events_.begin(), events_.end());
    events_.clear();
}

void GrainSources::write_checkpoint(std::ostream& out) const {
    for (const Source& source : sources_) {
        std::ostringstream state;
        state << source.generator;
        io::write_string(out, state.str());
        io::write_value(out, source.due);
        io::write_value(out, static_cast<std::int64_t>(source.created));
        io::write_value(out, source.created_mass);
        io::write_value(out, static_cast<std::uint8_t>(source.waited ? 1 : 0));
    }
}

void GrainSources::read_checkpoint(std::istream& in) {
    for (Source& source : sources_) {
        std::istringstream state(io::read_string(in));
        state >> source.generator;
        if (!state) {
            throw std::runtime_error("checkpoint: source '" + source.settings.name +
                                     "' holds no generator state");
        }
        source.due = io::read_value<double>(in);
        source.created = static_cast<Index>(io::read_value<std::int64_t>(in));
        source.created_mass = io::read_value<double>(in);
        source.waited = io::read_value<std::uint8_t>(in) != 0;
    }
    events_.clear();
}

} // namespace grainload::dem
