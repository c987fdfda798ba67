#include "materials/principal_stress.hpp"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>

namespace grainload::materials {

namespace {

// The Voigt slots of io/types.hpp: (row, column) of the tensor component each one holds.
constexpr std::array<std::array<int, 2>, 6> kSlots{
    {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}}};

// T with sigma_voigt = T sigma'_voigt for sigma = Q sigma' Q^T, both stress-like: a shear slot of
// sigma' stands for its two symmetric components, hence the two products.
Matrix6 rotation(const Mat3& q) {
    Matrix6 t;
    for (int row = 0; row < 6; ++row) {
        const int a = kSlots[row][0];
        const int b = kSlots[row][1];
        for (int column = 0; column < 6; ++column) {
            const int k = kSlots[column][0];
            const int l = kSlots[column][1];
            t(row, column) = column < 3 ? q(a, k) * q(b, k) : q(a, k) * q(b, l) + q(a, l) * q(b, k);
        }
    }
    return t;
}

} // namespace

PrincipalStresses principal_stresses(const Voigt6& stress) {
    Mat3 tensor;
    tensor << stress(0), stress(3), stress(5), stress(3), stress(1), stress(4), stress(5),
        stress(4), stress(2);
    // The iterative solver, not the closed form: it keeps full accuracy for the nearly equal
    // principal stresses of a granular column at rest (a triaxial state, two values equal).
    const Eigen::SelfAdjointEigenSolver<Mat3> solver(tensor);
    // Eigen sorts ascending; the Mohr-Coulomb convention is descending.
    PrincipalStresses p;
    p.values = solver.eigenvalues().reverse();
    p.directions = solver.eigenvectors().rowwise().reverse();
    return p;
}

Voigt6 from_principal(const Vec3& values, const Mat3& directions) {
    const Mat3 tensor = directions * values.asDiagonal() * directions.transpose();
    Voigt6 v;
    for (int slot = 0; slot < 6; ++slot) {
        v(slot) = tensor(kSlots[slot][0], kSlots[slot][1]);
    }
    return v;
}

Matrix6 isotropic_function_derivative(const Mat3& jacobian, const Vec3& values,
                                      const Vec3& trial_values, const Mat3& directions) {
    Matrix6 principal = Matrix6::Zero();
    principal.topLeftCorner<3, 3>() = jacobian;
    const double scale = trial_values.cwiseAbs().maxCoeff();
    for (int slot = 3; slot < 6; ++slot) {
        const int i = kSlots[slot][0];
        const int j = kSlots[slot][1];
        const double gap = trial_values(i) - trial_values(j);
        principal(slot, slot) = std::abs(gap) > 1e-12 * scale ? (values(i) - values(j)) / gap
                                                              : jacobian(i, i) - jacobian(i, j);
    }
    // sigma' = Q^T sigma Q maps with rotation(Q^T).
    return rotation(directions) * principal * rotation(directions.transpose());
}

} // namespace grainload::materials
