#include "sph/total_lagrangian.hpp"

#include "particles/neighbour_list.hpp"
#include "sph/rates.hpp"

#include <Eigen/LU>
#include <cmath>

namespace grainload::sph {

TotalLagrangian::TotalLagrangian(const ParticleSet& p, const SmoothingKernel& kernel)
    : dimension_(kernel.dimension()), reference_position_(p.position),
      reference_density_(p.density) {
    const Index n = p.size();
    std::vector<char> wall(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) {
        wall[i] = p.is_wall(i) ? 1 : 0;
    }
    particles::NeighbourList search(kernel.support_radius(), 0.0, dimension_);
    search.update(p.position, wall, true);
    const double support_squared = kernel.support_radius() * kernel.support_radius();
    offset_.assign(static_cast<std::size_t>(n) + 1, 0);
    correction_.assign(static_cast<std::size_t>(n), Mat3::Identity());
    for (Index i = 0; i < n; ++i) {
        offset_[i + 1] = offset_[i];
        if (wall[i]) {
            continue;
        }
        Mat3 moment = Mat3::Zero();
        for (const Index j : search.neighbours(i)) {
            const Vec3 x_ij = p.position[i] - p.position[j];
            const double r2 = x_ij.squaredNorm();
            if (wall[j] || p.body_id[j] != p.body_id[i] || r2 >= support_squared || r2 == 0.0) {
                continue;
            }
            const Vec3 gradient = kernel.gradient(x_ij, std::sqrt(r2));
            neighbour_.push_back(static_cast<std::int32_t>(j));
            gradient_factor_.push_back(gradient.dot(x_ij) / r2);
            moment.noalias() += (-p.mass[j] / p.density[j] * x_ij) * gradient.transpose();
            ++offset_[i + 1];
        }
        correction_[i] = correction_inverse(moment, dimension_).transpose();
    }
    neighbour_.shrink_to_fit();
    gradient_factor_.shrink_to_fit();
    deformation_gradient_.assign(static_cast<std::size_t>(n), Mat3::Identity());
    piola_correction_.assign(static_cast<std::size_t>(n), Mat3::Zero());
}

void TotalLagrangian::compute_kinematics(ParticleSet& p, std::vector<Mat3>& velocity_gradient) {
    const Index n = p.size();
    velocity_gradient.resize(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(dynamic, 128)
    for (Index i = 0; i < n; ++i) {
        if (p.is_wall(i)) {
            velocity_gradient[i].setZero();
            continue;
        }
        const Vec3 ui = p.position[i] - reference_position_[i];
        const Vec3 vi = p.velocity[i];
        Mat3 displacement_gradient = Mat3::Zero();
        Mat3 rate = Mat3::Zero();
        for (Index k = offset_[i]; k < offset_[i + 1]; ++k) {
            const Index j = neighbour_[k];
            const double volume = p.mass[j] / reference_density_[j];
            const Vec3 g = volume * reference_gradient(i, j, k);
            displacement_gradient.noalias() +=
                (p.position[j] - reference_position_[j] - ui) * g.transpose();
            rate.noalias() += (p.velocity[j] - vi) * g.transpose();
        }
        const Mat3 f = Mat3::Identity() + displacement_gradient * correction_[i].transpose();
        deformation_gradient_[i] = f;
        const Mat3 l = rate * correction_[i].transpose() * f.inverse();
        p.density[i] = reference_density_[i] / f.determinant();
        velocity_gradient[i] = l;
        store_kinematics(p, i, l);
    }
}

void TotalLagrangian::add_stress_forces(ParticleSet& p) {
    const Index n = p.size();
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        if (p.is_wall(i)) {
            continue;
        }
        const Mat3& f = deformation_gradient_[i];
        const Mat3 piola = f.determinant() * stress_tensor(p.stress[i]) * f.inverse().transpose();
        piola_correction_[i] = piola * correction_[i];
    }
#pragma omp parallel for schedule(dynamic, 128)
    for (Index i = 0; i < n; ++i) {
        if (p.is_wall(i)) {
            continue;
        }
        Vec3 force = Vec3::Zero();
        for (Index k = offset_[i]; k < offset_[i + 1]; ++k) {
            const Index j = neighbour_[k];
            const double volume = p.mass[j] / reference_density_[j];
            force.noalias() += volume * ((piola_correction_[i] + piola_correction_[j]) *
                                         reference_gradient(i, j, k));
        }
        p.acceleration[i] += force / reference_density_[i];
    }
}

std::size_t TotalLagrangian::bytes() const {
    auto held = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return held(offset_) + held(neighbour_) + held(gradient_factor_) + held(reference_position_) +
           held(reference_density_) + held(correction_) + held(deformation_gradient_) +
           held(piola_correction_);
}

} // namespace grainload::sph
