#include "app/resources/memory_guard.hpp"

#include "app/resources/calibration.hpp"
#include "sph/particle_estimate_reader.hpp"

#include <algorithm>
#include <array>
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

/// The largest generated shell of [fem] ([[fem.shell]] with a `generator`), estimated before
/// its mesh is made.
struct ShellCount {
    double nodes = 0.0;
    double bytes = 0.0;
    std::optional<io::CaseTable> shell;
    std::string_view key; ///< its first element count
};

/// Nodes of a generated shell from its element counts, as the generators lay them (fem/
/// shell_mesh_generators.cpp): (n1 + 1)(n2 + 1) on a plate, cylinder, cone or sphere zone (an
/// upper bound: closed rings and poles share nodes), and the box's five or six faces bounded by
/// 2 (nx + 1)(ny + 1) + 2 (nx + ny + 2)(nz + 1). Counts are clamped to the reader's range
/// (1 to 100000; it refuses others itself), in doubles, which 1e15 nodes do not overflow.
double generated_nodes(const io::CaseTable& shell, const std::string& generator) {
    auto count = [&](std::string_view key) {
        return static_cast<double>(std::clamp<std::int64_t>(shell.integer_or(key, 1), 1, 100000));
    };
    if (generator == "plate") {
        return (count("elements_x") + 1.0) * (count("elements_y") + 1.0);
    }
    if (generator == "box") {
        const double nx = count("elements_x"), ny = count("elements_y"), nz = count("elements_z");
        return 2.0 * (nx + 1.0) * (ny + 1.0) + 2.0 * (nx + ny + 2.0) * (nz + 1.0);
    }
    if (generator == "sphere_zone") {
        return (count("elements_polar") + 1.0) * (count("elements_around") + 1.0);
    }
    if (generator == "cylinder" || generator == "cone") {
        return (count("elements_around") + 1.0) * (count("elements_along") + 1.0);
    }
    return 0.0; // imported meshes are bounded by their files
}

/// The generated shells' memory: 6 DOFs per node at Calibration::shell_bytes_per_dof (the
/// factor of the 256 x 256 plate, app/resources/calibration.hpp), and the largest of them.
ShellCount estimate_shells(const io::CaseTable& root) {
    ShellCount largest;
    const auto fem = root.optional_table("fem");
    if (!fem) {
        return largest;
    }
    constexpr double kDofsPerNode = 6.0;
    const double bytes_per_node = kDofsPerNode * Calibration{}.shell_bytes_per_dof;
    double bytes = 0.0;
    for (const io::CaseTable& shell : fem->array_of_tables("shell")) {
        const std::string generator = shell.string_or("generator", "");
        const double nodes = generated_nodes(shell, generator);
        bytes += nodes * bytes_per_node;
        if (nodes > largest.nodes) {
            largest.nodes = nodes;
            largest.shell = shell;
            largest.key = generator == "plate" || generator == "box" ? "elements_x"
                          : generator == "sphere_zone"               ? "elements_polar"
                                                                     : "elements_around";
        }
    }
    largest.bytes = bytes;
    return largest;
}

[[noreturn]] void refuse_shells(const ShellCount& shells, double available) {
    std::ostringstream message;
    message << "the scene's shells would need about " << gibibytes(shells.bytes)
            << " (the largest, " << shells.shell->path() << ", about " << figure(shells.nodes)
            << " nodes), more than the " << gibibytes(available)
            << " this machine has available (MemAvailable in /proc/meminfo): expected fewer "
               "elements";
    shells.shell->fail(shells.key, message.str());
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

std::optional<double> refuse_oversized_scene(const io::CaseTable& root, int dimension,
                                             const materials::MaterialLibrary& materials,
                                             std::optional<double> available) {
    const sph::ParticleEstimate estimate = sph::estimate_particles(root, dimension, materials);
    const ShellCount shells = estimate_shells(root);
    if (!available) {
        return std::nullopt;
    }
    if (!(estimate.bytes() + shells.bytes > *available)) {
        return (*available - estimate.bytes() - shells.bytes) / estimate.bytes_per_particle;
    }
    const sph::ParticleCount* largest = estimate.largest();
    if (largest == nullptr || shells.bytes > estimate.bytes()) {
        refuse_shells(shells, *available);
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
