#include "materials/mohr_coulomb_return.hpp"

#include <Eigen/Dense>

namespace grainload::materials {

namespace {

// One plane of the hexagon: s_major is its largest principal stress, s_minor its smallest;
// its yield normal a and flow direction b are (1 + sin) e_major - (1 - sin) e_minor with
// phi and psi.
struct Plane {
    Vec3 normal;
    Vec3 flow;
};

Plane plane(const MohrCoulombSurface& m, int major, int minor) {
    Plane p{Vec3::Zero(), Vec3::Zero()};
    p.normal(major) = 1.0 + m.sin_phi;
    p.normal(minor) = -(1.0 - m.sin_phi);
    p.flow(major) = 1.0 + m.sin_psi;
    p.flow(minor) = -(1.0 - m.sin_psi);
    return p;
}

// The elastic law in principal components: ds = D de with D = lambda 1 1^T + 2G I.
Mat3 principal_stiffness(const ElasticConstants& elastic) {
    return Mat3::Constant(elastic.lame_lambda()) + 2.0 * elastic.shear_modulus * Mat3::Identity();
}

bool ordered(const Vec3& s, double tolerance) {
    return s(0) - s(1) >= -tolerance && s(1) - s(2) >= -tolerance;
}

// Planes a (and b): s = s_tr - sum_k dg_k D b_k with a_l . s - 2c cos(phi) = 0 for each active
// plane l, a linear system A dg = f_tr with A_lk = a_l . D b_k; d s / d s_tr = I - (D B) A^-1 N^T.
template <int N>
bool return_to_planes(const Mat3& stiffness, const MohrCoulombSurface& m,
                      const std::array<Plane, N>& planes, const Vec3& trial, PrincipalReturn& r) {
    Eigen::Matrix<double, 3, N> flows;
    Eigen::Matrix<double, 3, N> normals;
    Eigen::Matrix<double, N, 1> yields;
    for (int k = 0; k < N; ++k) {
        flows.col(k) = stiffness * planes[k].flow;
        normals.col(k) = planes[k].normal;
        yields(k) = planes[k].normal.dot(trial) - 2.0 * m.cohesion * m.cos_phi;
    }
    const Eigen::Matrix<double, N, N> system = normals.transpose() * flows;
    const Eigen::Matrix<double, N, 1> multipliers = system.inverse() * yields;
    if ((multipliers.array() < 0.0).any()) {
        return false;
    }
    r.stress = trial - flows * multipliers;
    r.jacobian = Mat3::Identity() - flows * system.inverse() * normals.transpose();
    return true;
}

} // namespace

double MohrCoulombSurface::yield(const Vec3& s) const {
    return (s(0) - s(2)) + (s(0) + s(2)) * sin_phi - 2.0 * cohesion * cos_phi;
}

PrincipalReturn mohr_coulomb_principal_return(const ElasticConstants& elastic,
                                              const MohrCoulombSurface& m, const Vec3& trial) {
    PrincipalReturn r;
    r.stress = trial;
    if (m.yield(trial) <= 0.0) {
        return r;
    }
    // Orderings are checked to round-off of the trial's size: a return that lands on a corner
    // exactly may leave s1 - s2 at -1e-16 of it.
    const double tolerance = 1e-12 * (trial.cwiseAbs().maxCoeff() + m.apex());
    const Mat3 stiffness = principal_stiffness(elastic);
    if (return_to_planes<1>(stiffness, m, {plane(m, 0, 2)}, trial, r) &&
        ordered(r.stress, tolerance)) {
        r.region = PlasticRegion::failure_surface;
        return r;
    }
    // The main return crossed s1 = s2 (towards the compression meridian) or s2 = s3 (the
    // extension meridian): that corner's second plane is the neighbour across the crossing.
    const Vec3 main = r.stress;
    const bool compression = main(1) - main(0) > main(2) - main(1);
    const Plane second = compression ? plane(m, 1, 2) : plane(m, 0, 1);
    if (return_to_planes<2>(stiffness, m, {plane(m, 0, 2), second}, trial, r) &&
        ordered(r.stress, tolerance)) {
        r.region = PlasticRegion::corner;
        return r;
    }
    r.region = PlasticRegion::apex;
    r.stress = Vec3::Constant(m.apex());
    r.jacobian = Mat3::Zero();
    return r;
}

} // namespace grainload::materials
