#include "sph/scene_limits.hpp"

#include "io/case_table.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <sstream>

namespace grainload::sph {

GravityStrain gravity_strain(const ParticleSet& particles,
                             const materials::MaterialLibrary& materials, const Vec3& gravity,
                             double spacing, double contact_stiffness) {
    GravityStrain result;
    const double g = gravity.norm();
    if (g == 0.0) {
        return result;
    }
    const Vec3 down = gravity / g;
    struct Extent {
        double low = std::numeric_limits<double>::infinity();
        double high = -std::numeric_limits<double>::infinity();
        int material = -1;
    };
    std::map<int, Extent> bodies;
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.is_wall(i)) {
            continue;
        }
        Extent& e = bodies[particles.body_id[i]];
        const double depth = particles.position[i].dot(down);
        e.low = std::min(e.low, depth);
        e.high = std::max(e.high, depth);
        e.material = particles.material_id[i];
    }
    for (const auto& [body, e] : bodies) {
        const materials::Material& law = materials[e.material];
        const materials::ElasticConstants& elastic = law.elastic();
        const double stress = law.density() * g * (e.high - e.low + spacing);
        const double modulus = elastic.bulk_modulus + 4.0 / 3.0 * elastic.shear_modulus;
        if (modulus > 0.0 && stress / modulus > result.strain) {
            result.strain = stress / modulus;
            result.material_body = body;
            result.material = e.material;
            result.stress = stress;
        }
        if (contact_stiffness > 0.0 && stress / contact_stiffness > result.contact) {
            result.contact = stress / contact_stiffness;
            result.contact_body = body;
            result.contact_stress = stress;
        }
    }
    return result;
}

void check_gravity_strain(const io::CaseTable& root, const ParticleSet& particles,
                          const materials::MaterialLibrary& materials,
                          const std::vector<std::string>& body_names, const Vec3& gravity,
                          double spacing, double contact_stiffness) {
    const GravityStrain g =
        gravity_strain(particles, materials, gravity, spacing, contact_stiffness);
    if (g.strain > kLargestGravityStrain) {
        const io::CaseTable table =
            root.array_of_tables("material")[static_cast<std::size_t>(g.material)];
        const bool deck = table.has("from_lsdyna");
        const char* key = table.has("stiffness_scale")  ? "stiffness_scale"
                          : deck                        ? "from_lsdyna"
                          : table.has("youngs_modulus") ? "youngs_modulus"
                                                        : "bulk_modulus";
        std::ostringstream message;
        message.precision(3);
        message << "body \"" << body_names[static_cast<std::size_t>(g.material_body)]
                << "\" carries rho g H = " << g.stress << " Pa at its base under gravity, a strain "
                << "of " << g.strain << " against the P-wave modulus K + 4G/3 of material \""
                << materials.name(g.material) << "\", above " << kLargestGravityStrain
                << ": its elastic constants no longer describe it; expected K + 4G/3 of at least "
                << g.stress / kLargestGravityStrain << " Pa";
        if (deck) {
            // Density and moduli both come from the deck, as its units convert them.
            message << " (the deck's RO, BULK and G read in \""
                    << table.table("from_lsdyna").string("units") << "\")";
        }
        table.fail(key, message.str());
    }
    if (g.contact > kLargestGravityStrain) {
        std::ostringstream message;
        message.precision(3);
        message << "body \"" << body_names[static_cast<std::size_t>(g.contact_body)]
                << "\" presses rho g H = " << g.contact_stress << " Pa on what it stands on, "
                << g.contact << " of the contact stiffness: it would sink into the walls; "
                << "expected a contact stiffness of at least "
                << g.contact_stress / kLargestGravityStrain << " Pa";
        root.table("sph").table("contact").fail("stiffness", message.str());
    }
}

std::string impact_warning(const ParticleSet& particles, const std::vector<std::string>& body_names,
                           double contact_stiffness) {
    if (!(contact_stiffness > 0.0)) {
        return "";
    }
    double worst = 0.0;
    Index at = -1;
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.is_wall(i)) {
            continue;
        }
        const double pressure = particles.density[i] * particles.velocity[i].squaredNorm();
        if (pressure > worst) {
            worst = pressure;
            at = i;
        }
    }
    if (worst <= contact_stiffness) {
        return "";
    }
    std::ostringstream message;
    message.precision(3);
    message << "body \"" << body_names[static_cast<std::size_t>(particles.body_id[at])]
            << "\" starts at " << particles.velocity[at].norm() << " m/s: rho v^2 = " << worst
            << " Pa exceeds the contact stiffness " << contact_stiffness
            << " Pa, so its particles can pass a rigid wall; a contact stiffness of at least "
            << worst << " Pa stops them";
    return message.str();
}

} // namespace grainload::sph
