#include "app/memory_guard.hpp"

#include "sph/particle_estimate.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace grainload::app {

namespace {

std::string figure(double value) {
    std::ostringstream out;
    out.precision(3);
    out << value;
    return out.str();
}

std::string gibibytes(double bytes) {
    return figure(bytes / (1024.0 * 1024.0 * 1024.0)) + " GiB";
}

} // namespace

std::optional<double> available_memory() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    double kib = 0.0;
    std::string unit;
    while (meminfo >> key >> kib >> unit) {
        if (key == "MemAvailable:") {
            return kib * 1024.0;
        }
    }
    return std::nullopt;
}

void refuse_oversized_scene(const io::CaseTable& root, int dimension,
                            std::optional<double> available) {
    const sph::ParticleEstimate estimate = sph::estimate_particles(root, dimension);
    const sph::ParticleCount* largest = estimate.largest();
    if (!available || largest == nullptr || !(estimate.bytes() > *available)) {
        return;
    }
    // The count goes as spacing^-dimension (bodies) or spacing^-(dimension - 1) (walls): the
    // first power is the smaller step, so the spacing it gives fits in every case.
    const double fitting =
        largest->spacing * std::pow(estimate.bytes() / *available, 1.0 / dimension);
    std::ostringstream message;
    message << "the scene would need about " << figure(estimate.total()) << " SPH particles ("
            << largest->table << " \"" << largest->name << "\": " << figure(largest->particles)
            << " from a " << largest->basis << ") and about " << gibibytes(estimate.bytes())
            << " for them (" << estimate.bytes_per_particle
            << " bytes per particle), more than the " << gibibytes(*available)
            << " this machine has available (MemAvailable in /proc/meminfo): expected a spacing "
               "of at least about "
            << figure(fitting) << " m, or a smaller scene";
    const io::CaseTable sph = root.table("sph");
    const bool own_wall_spacing =
        !largest->spacing_key.empty() && largest->table.starts_with("sph.wall");
    if (own_wall_spacing) {
        sph.array_of_tables("wall")[static_cast<std::size_t>(largest->index)].fail("spacing",
                                                                                   message.str());
    }
    // Bodies share one spacing, which walls take by default: the first body's key sets it.
    const int body = largest->table.starts_with("sph.body") ? largest->index : 0;
    sph.array_of_tables("body")[static_cast<std::size_t>(body)].fail("spacing", message.str());
}

} // namespace grainload::app
