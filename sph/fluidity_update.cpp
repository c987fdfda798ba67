#include "sph/fluidity_update.hpp"

#include "materials/nonlocal_fluidity.hpp"
#include "materials/voigt_algebra.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::sph {

bool FluidityUpdate::needed(std::span<const materials::Material* const> materials) {
    return std::any_of(materials.begin(), materials.end(), [](const materials::Material* m) {
        return m != nullptr && m->nonlocal_fluidity() != nullptr;
    });
}

void FluidityUpdate::connect(const ParticleSet& particles, Index count,
                             std::span<const GhostImage> images,
                             std::span<const materials::Material* const> materials,
                             const particles::NeighbourList& list) {
    carries_.assign(static_cast<std::size_t>(count), char{0});
    for (Index i = 0; i < count; ++i) {
        if (particles.wall_id[i] < 0) {
            const materials::Material* m = materials[particles.material_id[i]];
            carries_[i] = static_cast<char>(m->nonlocal_fluidity() != nullptr);
        }
    }
    std::vector<Index> sources;
    sources.reserve(images.size());
    for (const GhostImage& image : images) {
        sources.push_back(image.source);
    }
    field_.connect(list, count, sources, carries_, particles.body_id);
}

void FluidityUpdate::apply(ParticleSet& particles, Index count, std::span<const GhostImage> images,
                           std::span<const materials::Material* const> materials,
                           const particles::NeighbourList& list, const SmoothingKernel& kernel) {
    if (!field_.connected_to(list.generation())) {
        connect(particles, count, images, materials, list);
    }
    const auto n = static_cast<std::size_t>(count);
    active_.assign(n, char{0});
    volume_.resize(n);
    local_.assign(n, 0.0);
    screening_.assign(n, 0.0);
    values_.assign(n, 0.0);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < count; ++i) {
        volume_[i] = particles.mass[i] / particles.density[i];
        if (carries_[i] == 0) {
            continue;
        }
        const materials::NonlocalFluidity& fluidity =
            *materials[particles.material_id[i]]->nonlocal_fluidity();
        const Voigt6& stress = particles.stress[i];
        const double pressure = -materials::voigt::trace(stress) / 3.0;
        const double* state = particles.state.data() + particles.state_offset[i];
        values_[i] = state[fluidity.fluidity_index];
        if (!(pressure > 0.0)) {
            continue;
        }
        const double mu =
            materials::voigt::norm(materials::voigt::deviator(stress)) / std::sqrt(2.0) / pressure;
        active_[i] = 1;
        local_[i] = fluidity.local_fluidity(mu, pressure);
        screening_[i] = fluidity.screening(mu);
    }
    field_.weigh(particles.position, volume_, active_, kernel);
    const FluiditySolve done = field_.solve(local_, screening_, values_);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < count; ++i) {
        if (carries_[i] != 0) {
            const int excess =
                materials[particles.material_id[i]]->nonlocal_fluidity()->excess_index;
            particles.state[particles.state_offset[i] + excess] =
                active_[i] != 0 ? values_[i] - local_[i] : 0.0;
        }
    }
    ++solves_;
    iterations_ += done.iterations;
    worst_residual_ = std::max(worst_residual_, done.residual);
    most_iterations_ = std::max(most_iterations_, done.iterations);
}

std::size_t FluidityUpdate::bytes() const {
    auto held = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return field_.bytes() + held(carries_) + held(active_) + held(volume_) + held(local_) +
           held(screening_) + held(values_);
}

} // namespace grainload::sph
