#include "app/resources/discharge_estimate.hpp"

#include "sph/sph_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace grainload::app {

namespace {

/// The particles source `s` creates by `end`: what its rate owes, but no more than its sites
/// hold (a full box owes on); 0 for one that has not started by then.
double created_by(const sph::SourceSet::Source& s, double end) {
    const double stop = std::min(s.end, end);
    if (!(stop > s.start) || !(s.particle_mass > 0.0)) {
        return 0.0;
    }
    return std::min(s.mass_rate * (stop - s.start) / s.particle_mass,
                    static_cast<double>(s.sites.size()));
}

/// The earliest phase `k` can start: the latest stated end of the phases before it, each of
/// which ends no earlier than it began (0 for the first).
double earliest_start(const particles::PhaseSequence& phases, int k) {
    double start = 0.0;
    for (int j = 0; j < k && j < static_cast<int>(phases.phases().size()); ++j) {
        const auto& phase = phases.phases()[static_cast<std::size_t>(j)];
        if (phase.end == particles::PhaseSequence::End::time) {
            start = std::max(start, phase.end_time);
        }
    }
    return start;
}

} // namespace

double average_created(const sph::SphModel& sph, double end) {
    double average = 0.0;
    if (!(end > 0.0)) {
        return average;
    }
    for (const sph::SourceSet::Source& s : sph.sources().sources()) {
        const double stop = std::min(s.end, end);
        average += created_by(s, end) * (end - 0.5 * (s.start + stop)) / end;
    }
    return average;
}

Discharge average_discharged(const sph::SphModel& sph, double end) {
    Discharge d;
    for (std::size_t s = 0; s < sph.sinks().sinks().size(); ++s) {
        if (const auto rate = sph.sinks().outlet_rate(s)) {
            d.rate += *rate;
            d.declared = true;
        }
    }
    if (!d.declared || !sph.solver() || !(end > 0.0)) {
        return d;
    }
    double opening = std::numeric_limits<double>::infinity();
    bool pending = false;
    for (const sph::Wall& wall : sph.solver()->walls()) {
        opening = std::min(opening, wall.removal_time);
        pending = pending || wall.removal_on_settle;
        if (wall.removal_phase >= 0 && !std::isfinite(wall.removal_time)) {
            const double start = earliest_start(sph.phases(), wall.removal_phase);
            d.earliest = d.earliest || start < opening;
            opening = std::min(opening, start);
        }
    }
    if (!std::isfinite(opening) && pending) {
        d.known = false;
        return d;
    }
    d.opening = std::isfinite(opening) ? opening : 0.0;
    d.emptied = std::numeric_limits<double>::infinity();
    const sph::ParticleSet& p = sph.particles();
    double mass = 0.0;
    double count = 0.0;
    for (Index i = 0; i < p.size(); ++i) {
        mass += p.is_wall(i) ? 0.0 : p.mass[i];
        count += p.is_wall(i) ? 0.0 : 1.0;
    }
    for (const sph::SourceSet::Source& source : sph.sources().sources()) {
        const double made = created_by(source, end);
        mass += made * source.particle_mass;
        count += made;
    }
    const double span = end - d.opening;
    if (!(span > 0.0) || !(mass > 0.0) || !(d.rate > 0.0)) {
        return d;
    }
    // Mass taken by t: min(M, W (t - t_open)); its integral over the run, per particle.
    const double emptied = mass / d.rate;
    d.emptied = d.opening + emptied;
    const double integral = span <= emptied ? 0.5 * d.rate * span * span
                                            : 0.5 * mass * emptied + mass * (span - emptied);
    d.average = integral / end * (count / mass);
    return d;
}

namespace {

/// Beverloo's mean velocity through sink s's outlet, W / (rho_b A) (A: B L for a slot, pi D^2 / 4
/// for a circle, B per metre in plane strain); 0 without an outlet.
double outlet_velocity(const particles::Outlet& outlet, double gravity, int dimension) {
    const double area = dimension == 2 ? outlet.width
                        : outlet.length > 0.0
                            ? outlet.width * outlet.length
                            : 0.25 * std::numbers::pi * outlet.width * outlet.width;
    return area > 0.0 && outlet.bulk_density > 0.0
               ? outlet.rate(gravity, dimension) / (outlet.bulk_density * area)
               : 0.0;
}

/// The material particle lowest along `down` at t = 0 (where an outlet under it is).
std::optional<Vec3> lowest_material(const sph::ParticleSet& p, const Vec3& down) {
    std::optional<Vec3> lowest;
    for (Index i = 0; i < p.size(); ++i) {
        if (!p.is_wall(i) && (!lowest || p.position[i].dot(down) > lowest->dot(down))) {
            lowest = p.position[i];
        }
    }
    return lowest;
}

/// The fastest grain's speed while the outlets flow: the largest over the plane sinks below
/// the material of sqrt(v0^2 + 2 g d), d the fall from its lowest point to the plane.
double fastest_grain(const sph::SphModel& sph, const Vec3& gravity) {
    const double g = gravity.norm();
    if (!(g > 0.0)) {
        return 0.0;
    }
    const Vec3 down = gravity / g;
    const auto lowest = lowest_material(sph.particles(), down);
    double fastest = 0.0;
    for (const particles::SinkSet::Sink& sink : sph.sinks().sinks()) {
        const double towards = down.dot(sink.region.normal);
        if (!sink.outlet || !lowest || sink.region.kind != io::Region::Kind::half_space ||
            !(towards > 0.0)) {
            continue;
        }
        const double drop =
            std::max(0.0, (sink.region.point - *lowest).dot(sink.region.normal) / towards);
        const double v0 = outlet_velocity(*sink.outlet, g, sph.dimension());
        fastest = std::max(fastest, std::sqrt(v0 * v0 + 2.0 * g * drop));
    }
    return fastest;
}

} // namespace

FlowStep flow_step(const sph::SphModel& sph, const Discharge& discharge, const Vec3& gravity,
                   double end) {
    FlowStep flow;
    flow.profile.rest = sph.stable_time_step();
    if (!sph.solver() || sph.fixed_time_step() || !discharge.declared || !discharge.known ||
        !(discharge.opening < end) || !std::isfinite(flow.profile.rest)) {
        return flow;
    }
    flow.speed = fastest_grain(sph, gravity);
    if (!(flow.speed > 0.0)) {
        return flow;
    }
    // The step at t = 0 is C h / fastest(c + |v|); the flow adds the grain's speed to it.
    const sph::SphOptions& options = sph.solver()->options();
    const double reach = options.cfl_safety * options.smoothing_length;
    flow.profile.flow = reach / (reach / flow.profile.rest + flow.speed);
    flow.profile.from = discharge.opening;
    flow.profile.to = std::min(discharge.emptied, end);
    return flow;
}

} // namespace grainload::app
