#include "sph/stress_update.hpp"

#include "sph/rates.hpp"

#include <Eigen/LU>

namespace grainload::sph {

Mat3 jaumann_rotation(const Vec3& spin, double dt) {
    Mat3 w;
    w << 0.0, -spin.z(), spin.y(), spin.z(), 0.0, -spin.x(), -spin.y(), spin.x(), 0.0;
    const Mat3 half = 0.5 * dt * w;
    return (Mat3::Identity() - half).inverse() * (Mat3::Identity() + half);
}

void update_stresses(ParticleSet& p, std::span<const materials::Material* const> materials,
                     double dt, Index count) {
    const Index n = count < 0 ? p.size() : count;
    // Dynamic: wall particles are skipped and plastic returns cost more than elastic steps, so
    // equal index ranges are unequal work (a static split gave one thread every grain of the
    // column collapse, whose walls come after its grains).
#pragma omp parallel for schedule(dynamic, 64)
    for (Index i = 0; i < n; ++i) {
        if (p.wall_id[i] >= 0) {
            continue;
        }
        const materials::Material& material =
            *materials[static_cast<std::size_t>(p.material_id[i])];
        const Mat3 q = jaumann_rotation(p.spin[i], dt);
        const Voigt6 old_stress = stress_voigt(q * stress_tensor(p.stress[i]) * q.transpose());
        Voigt6 stress = old_stress;
        const Voigt6 strain_increment = p.strain_rate[i] * dt;
        const std::span<double> state(p.state.data() + p.state_offset[i],
                                      static_cast<std::size_t>(material.state_size()));
        p.plastic_region[i] =
            static_cast<int>(material.update(strain_increment, stress, state, nullptr));
        p.plastic_strain[i] = material.equivalent_plastic_strain(state);
        p.stress[i] = stress;
        // sigma : D with engineering shear strains is the plain Voigt dot product.
        const double power = 0.5 * (old_stress + stress).dot(p.strain_rate[i]) / p.density[i];
        p.energy_rate[i] = power;
        p.internal_energy[i] += power * dt;
    }
}

} // namespace grainload::sph
