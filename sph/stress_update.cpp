#include "sph/stress_update.hpp"

#include "sph/rates.hpp"

#include <algorithm>
#include <vector>

namespace grainload::sph {

namespace {

/// Particles whose stresses one task updates: as many as a dynamic chunk used to hold.
constexpr Index kBlock = 64;

/// A block's points of one material, handed to Material::update_points together.
struct PointBatch {
    std::vector<Index> particles;
    std::vector<Voigt6> increments;
    std::vector<Voigt6> stresses;
    std::vector<Voigt6> old_stresses;
    std::vector<double*> states;
    std::vector<materials::PlasticRegion> regions;

    void clear() {
        particles.clear();
        increments.clear();
        stresses.clear();
        old_stresses.clear();
        states.clear();
    }
};

/// The objective rotation and the strain increment of particle i, queued in the batch.
void queue(ParticleSet& p, Index i, double dt, PointBatch& b) {
    const Mat3 q = jaumann_rotation(p.spin[i], dt);
    b.particles.push_back(i);
    b.old_stresses.push_back(stress_voigt(q * stress_tensor(p.stress[i]) * q.transpose()));
    b.stresses.push_back(b.old_stresses.back());
    b.increments.push_back(p.strain_rate[i] * dt);
    b.states.push_back(p.state.data() + p.state_offset[i]);
}

/// sigma_mid . (d eps - D_e^-1 d sigma), engineering shears: the plastic part of the step's
/// stress work per unit volume (zero to round-off for an elastic step).
double plastic_work_density(const materials::ElasticConstants& elastic, const Voigt6& before,
                            const Voigt6& after, const Voigt6& strain_increment) {
    return 0.5 *
           (before + after).dot(strain_increment - elastic.strain_from_stress(after - before));
}

/// The queued points' returns and what the particles keep of them.
void flush(ParticleSet& p, const materials::Material& material, double dt, PointBatch& b,
           std::span<double> plastic_work) {
    b.regions.resize(b.particles.size());
    material.update_points(b.increments, dt, b.stresses, b.states, b.regions);
    const auto size = static_cast<std::size_t>(material.state_size());
    for (std::size_t k = 0; k < b.particles.size(); ++k) {
        const Index i = b.particles[k];
        p.plastic_region[i] = static_cast<int>(b.regions[k]);
        p.plastic_strain[i] = material.equivalent_plastic_strain({b.states[k], size});
        p.stress[i] = b.stresses[k];
        // sigma : D with engineering shear strains is the plain Voigt dot product.
        const double power =
            0.5 * (b.old_stresses[k] + b.stresses[k]).dot(p.strain_rate[i]) / p.density[i];
        p.energy_rate[i] = power;
        p.internal_energy[i] += power * dt;
        if (!plastic_work.empty()) {
            plastic_work[static_cast<std::size_t>(i)] =
                plastic_work_density(material.elastic(), b.old_stresses[k], b.stresses[k],
                                     b.increments[k]) /
                p.density[i];
        }
    }
    b.clear();
}

} // namespace

void update_stresses(ParticleSet& p, std::span<const materials::Material* const> materials,
                     double dt, Index count, std::span<double> plastic_work) {
    const Index n = count < 0 ? p.size() : count;
    const Index blocks = (n + kBlock - 1) / kBlock;
    // Dynamic: wall particles are skipped and plastic returns cost more than elastic steps, so
    // equal index ranges are unequal work (a static split gave one thread every grain of the
    // column collapse, whose walls come after its grains).
#pragma omp parallel
    {
        PointBatch batch;
#pragma omp for schedule(dynamic, 1)
        for (Index block = 0; block < blocks; ++block) {
            int material = -1;
            for (Index i = block * kBlock; i < std::min(n, (block + 1) * kBlock); ++i) {
                if (p.wall_id[i] >= 0) {
                    continue;
                }
                if (p.material_id[i] != material && material >= 0) {
                    flush(p, *materials[static_cast<std::size_t>(material)], dt, batch,
                          plastic_work);
                }
                material = p.material_id[i];
                queue(p, i, dt, batch);
            }
            if (material >= 0) {
                flush(p, *materials[static_cast<std::size_t>(material)], dt, batch, plastic_work);
            }
        }
    }
}

} // namespace grainload::sph
