#include "sph/source_case_reader.hpp"

#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "particles/particles_case_reader.hpp"
#include "sph/body_shape_reader.hpp"
#include "sph/sph_case_reader.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::sph {

namespace dim = io::dimension;

namespace {

/// Mass rate: kg/s in 3D, kg/(m s) in plane strain (masses there are per metre of depth).
io::Dimension mass_rate_dimension(int dimension) {
    return dimension == 2 ? io::Dimension{1, -1, -1, 0} : io::Dimension{1, 0, -1, 0};
}

/// start and end: times, or "phase:NAME" (the phase's start, resolved by apply_phase_starts).
/// An end before the start is refused where the case fixes both: two times, or two phases
/// (which begin in the order of the table).
void read_window(const io::CaseTable& table, const particles::PhaseSequence* phases,
                 SourceSet::Source& source) {
    if (const auto phase = particles::read_phase_reference(table, "start", phases)) {
        source.start_phase = *phase;
    } else {
        source.start =
            table.quantity_or("start", dim::kTime, io::default_value(kSourceKeys, "start"));
    }
    if (const auto phase = particles::read_phase_reference(table, "end", phases)) {
        source.end_phase = *phase;
    } else if (table.has("end")) {
        source.end = table.quantity("end", dim::kTime);
    }
    if (!particles::window_in_order(source.start, source.end, source.start_phase,
                                    source.end_phase)) {
        table.fail("end", "expected an end after start");
    }
}

} // namespace

SourceSet read_sources(const io::CaseTable& sph, const std::vector<std::string>& body_names,
                       const std::vector<int>& body_material,
                       const std::vector<double>& body_density, double spacing, int dimension,
                       const Vec3& gravity, const particles::PhaseSequence* phases) {
    std::vector<SourceSet::Source> sources;
    for (const auto& table : sph.array_of_tables("source")) {
        SourceSet::Source source;
        source.name = table.string("name");
        io::refuse_repeated_name(table, sources, source.name, "source", &SourceSet::Source::name);
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
            source.sites = SourceSet::lattice(source.region, spacing, dimension);
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
        source.velocity = table.vector_or("velocity", dim::kVelocity,
                                          io::default_vector(kSourceKeys, "velocity"));
        if (dimension == 2) {
            source.velocity.z() = 0.0;
        }
        sources.push_back(std::move(source));
    }
    return SourceSet(std::move(sources), spacing, dimension);
}

} // namespace grainload::sph
