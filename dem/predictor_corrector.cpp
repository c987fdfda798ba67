// The predictor-corrector of Lazarevic, Dvornik & Fresl (2002, "Diskretno numericko modeliranje
// opterecenja silosa", Gradevinar 54, 135-144, section 4) as a DemModel step: the acceleration at
// the step's start held over it predicts the state at its end (eq. 18); the forces there give the
// equilibrium acceleration, and its difference from the one assumed, the unbalanced
// acceleration (eqs. 20-21), corrects the state as an acceleration varying linearly over the
// step (eqs. 22-23); the corrector repeats (the method's implicit form, eq. 25) until no grain's
// unbalanced acceleration exceeds a fraction of g (eq. 26) or the passes run out. The forces of
// the last pass's state are the next step's start, as the seed's algorithm 5 evaluates them.
// Applied alike to a grain's angular momentum under its torque.

#include "dem/dem_model.hpp"
#include "dem/grain_motion.hpp"

#include <algorithm>

namespace grainload::dem {

namespace {

/// Eq. 18: the start's acceleration held over the step.
constexpr MotionWeights kPredictor{{0.5, 0.0}, {1.0, 0.0}};
/// Eq. 23: the acceleration linear from a(t) to a(t + dt): v + dt (a(t) + a(t + dt)) / 2,
/// x + dt v + dt^2 (a(t) / 3 + a(t + dt) / 6).
constexpr MotionWeights kCorrector{{1.0 / 3.0, 1.0 / 6.0}, {0.5, 0.5}};

} // namespace

void DemModel::move_from_start(double dt, const MotionWeights& w) {
    GrainSet& g = grains_;
    const Index n = g.size();
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const Vec3 start = start_.force[k] / g.mass[i];
        const Vec3 end = g.force[i] / g.mass[i];
        g.position[i] =
            start_.position[k] +
            dt * (start_.velocity[k] + dt * (w.position[0] * start + w.position[1] * end));
        g.velocity[i] = start_.velocity[k] + dt * (w.velocity[0] * start + w.velocity[1] * end);
        if (!(g.inertia[i].x() > 0.0)) {
            continue;
        }
        // The angular momentum over the step (its mean, which turns the grain, as the position
        // moves by the mean velocity) and at its end.
        const Vec3 mean = start_.momentum[k] +
                          dt * (w.position[0] * start_.torque[k] + w.position[1] * g.torque[i]);
        const Vec3 last = start_.momentum[k] +
                          dt * (w.velocity[0] * start_.torque[k] + w.velocity[1] * g.torque[i]);
        if (g.isotropic(i)) {
            g.orientation[i] = rotated(start_.orientation[k], dt / g.inertia[i].x() * mean);
            g.angular_velocity[i] = last / g.inertia[i].x();
        } else {
            // A clump turns with the angular velocity its mean momentum has at the step's
            // middle orientation (as in the Verlet step: Euler's equations to second order).
            const Vec3 first = spin_of(start_.orientation[k], g.inertia[i], mean);
            const Eigen::Quaterniond middle = rotated(start_.orientation[k], 0.5 * dt * first);
            g.orientation[i] =
                rotated(start_.orientation[k], dt * spin_of(middle, g.inertia[i], mean));
            g.angular_velocity[i] = spin_of(g.orientation[i], g.inertia[i], last);
        }
    }
    spheres_.place(g);
}

void DemModel::predictor_corrector_step(double t, double dt) {
    GrainSet& g = grains_;
    const Index n = g.size();
    start_.position = g.position;
    start_.velocity = g.velocity;
    start_.orientation = g.orientation;
    start_.force = g.force;
    start_.torque = g.torque;
    start_.momentum.resize(static_cast<std::size_t>(n));
    start_.assumed.resize(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        start_.momentum[k] =
            g.isotropic(i) ? Vec3(g.inertia[i].x() * g.angular_velocity[i])
                           : momentum_of(g.orientation[i], g.inertia[i], g.angular_velocity[i]);
        start_.assumed[k] = g.force[i] / g.mass[i];
    }
    start_.springs.resize(spheres_.springs.size());
    for (std::size_t k = 0; k < spheres_.springs.size(); ++k) {
        start_.springs[k].assign(spheres_.springs[k].begin(), spheres_.springs[k].end());
    }
    step_ = dt;
    move_from_start(dt, kPredictor);
    evaluate(t + dt);
    const double tolerance = settings_.corrector_tolerance * gravity_.norm();
    for (int pass = 1; pass <= settings_.corrector_passes; ++pass) {
        // Eqs. 21 and 26: the largest unbalanced acceleration of this state.
        double unbalanced = 0.0;
#pragma omp parallel for schedule(static) reduction(max : unbalanced)
        for (Index i = 0; i < n; ++i) {
            const auto k = static_cast<std::size_t>(i);
            const Vec3 now = g.force[i] / g.mass[i];
            unbalanced = std::max(unbalanced, (now - start_.assumed[k]).norm());
            start_.assumed[k] = now;
        }
        move_from_start(dt, kCorrector);
        for (std::size_t k = 0; k < spheres_.springs.size(); ++k) {
            spheres_.springs[k].assign(start_.springs[k].begin(), start_.springs[k].end());
        }
        evaluate(t + dt);
        if (unbalanced < tolerance) {
            break;
        }
    }
}

} // namespace grainload::dem
