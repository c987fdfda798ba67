#pragma once
// Small plane-strain scenes shared by the SPH verification tests.

// Small plane-strain scenes shared by the SPH verification tests.

#include "materials/linear_elastic.hpp"
#include "sph/lattice_fill.hpp"
#include "sph/sph_solver.hpp"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

namespace grainload::sph::testing {

/// Elastic aluminium-like solid; E, nu chosen per test.
inline const materials::LinearElastic& elastic_material(double young, double poisson,
                                                        double density) {
    static std::vector<std::unique_ptr<materials::LinearElastic>> kept;
    kept.push_back(std::make_unique<materials::LinearElastic>(
        materials::ElasticConstants::from_young(density, young, poisson)));
    return *kept.back();
}

inline SphOptions plane_strain_options(double spacing) {
    SphOptions options;
    options.dimension = 2;
    options.kernel = KernelType::cubic_spline;
    options.smoothing_length = 1.3 * spacing;
    options.particle_spacing = spacing;
    // These verifications check the plain SPH sums; the ones that need the corrected gradient
    // switch it on themselves.
    options.kernel_gradient_correction = false;
    return options;
}

/// Mean of `value(i)` over the particles selected by `pick(i)`.
inline double mean_over(const ParticleSet& p, const std::function<bool(Index)>& pick,
                        const std::function<double(Index)>& value) {
    double sum = 0.0;
    int count = 0;
    for (Index i = 0; i < p.size(); ++i) {
        if (pick(i)) {
            sum += value(i);
            ++count;
        }
    }
    return count > 0 ? sum / count : 0.0;
}

/// Linear interpolation of the time at which `series` (sampled at `times`) first crosses
/// `level` going down; NaN if it never does.
inline double first_crossing_down(const std::vector<double>& times,
                                  const std::vector<double>& series, double level) {
    for (std::size_t k = 1; k < series.size(); ++k) {
        if (series[k - 1] > level && series[k] <= level) {
            const double s = (series[k - 1] - level) / (series[k - 1] - series[k]);
            return times[k - 1] + s * (times[k] - times[k - 1]);
        }
    }
    return std::nan("");
}

/// Smallest distance between neighbouring particles, in units of the spacing; with
/// `between_bodies_only`, only pairs from different bodies count (contact interpenetration).
inline double smallest_neighbour_distance(const SphSolver& solver, bool between_bodies_only) {
    const auto& p = solver.particles();
    double smallest = std::numeric_limits<double>::infinity();
    for (Index i = 0; i < p.size(); ++i) {
        for (const Index j : solver.neighbours().neighbours(i)) {
            if (!between_bodies_only || p.body_id[i] != p.body_id[j]) {
                smallest = std::min(smallest, (p.position[i] - p.position[j]).norm());
            }
        }
    }
    return smallest / solver.options().particle_spacing;
}

} // namespace grainload::sph::testing
