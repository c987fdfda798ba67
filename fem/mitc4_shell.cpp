#include "fem/mitc4_shell.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace grainload::fem {

namespace {

constexpr double kNodeR[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kNodeS[4] = {-1.0, -1.0, 1.0, 1.0};
/// Covariant component pairs in ShellVector order: rr, ss, rs, rt, st (r=0, s=1, t=2).
constexpr int kPairs[5][2] = {{0, 0}, {1, 1}, {0, 1}, {0, 2}, {1, 2}};
/// MITC4 tying points (Dvorkin & Bathe 1984, eq. 10): e_rt at A = (0, 1), C = (0, -1);
/// e_st at D = (1, 0), B = (-1, 0). Entry 0 is the integration point itself.
constexpr double kTyingR[5] = {0.0, 0.0, 0.0, 1.0, -1.0};
constexpr double kTyingS[5] = {0.0, 1.0, -1.0, 0.0, 0.0};

Mat3 skew(const Vec3& v) {
    Mat3 m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

/// Gauss-Legendre points and weights on [-1, 1]: roots of P_n by Newton's method from the
/// Chebyshev-like estimate cos(pi (i + 3/4) / (n + 1/2)) (Press et al., Numerical Recipes,
/// section 4.6), accurate to round-off for the n <= 15 used through a shell's thickness.
void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights) {
    if (n < 2 || n > kMaxThicknessPoints) {
        throw std::invalid_argument("MITC4: thickness_points must be between 2 and " +
                                    std::to_string(kMaxThicknessPoints));
    }
    points.assign(static_cast<std::size_t>(n), 0.0);
    weights.assign(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
        double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
        double derivative = 0.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0;
            double p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-16) {
                break;
            }
        }
        points[static_cast<std::size_t>(n - 1 - i)] = x;
        weights[static_cast<std::size_t>(n - 1 - i)] =
            2.0 / ((1.0 - x * x) * derivative * derivative);
    }
}

double von_mises(const Mat3& s) {
    const double d = (s(0, 0) - s(1, 1)) * (s(0, 0) - s(1, 1)) +
                     (s(1, 1) - s(2, 2)) * (s(1, 1) - s(2, 2)) +
                     (s(2, 2) - s(0, 0)) * (s(2, 2) - s(0, 0));
    return std::sqrt(0.5 * d + 3.0 * (s(0, 1) * s(0, 1) + s(1, 2) * s(1, 2) + s(0, 2) * s(0, 2)));
}

/// The stress at thickness coordinate z on the line through the stresses a at za and b at zb:
/// exact for an elastic section, whose stress is linear through the thickness (Kirchhoff-Love
/// and Reissner-Mindlin alike); in a yielded section an estimate that can pass the yield stress
/// by what the line overshoots (a few per cent with five points).
Mat3 along_thickness(const Mat3& a, double za, const Mat3& b, double zb, double z) {
    return a + (b - a) * ((z - za) / (zb - za));
}

} // namespace

/// Covariant base vectors g_r, g_s, g_t of x(r,s,z) = sum h_k (x_k + z a/2 V_k) and their
/// derivatives with respect to the element DOFs (Bathe FEP eq. 5.103 with the director
/// variation dV = dtheta x V).
struct Mitc4Shell::Basis {
    std::array<Vec3, 3> g;
    std::array<Eigen::Matrix<double, 3, 24>, 3> dg;
    /// coefficient[i][k]: d g_i / d V_k (scalar multiple of the identity).
    std::array<std::array<double, 4>, 3> coefficient;
};

Mitc4Shell::Mitc4Shell(const ShellNodes& initial, double thickness,
                       const materials::Material& material, int thickness_points)
    : initial_(initial), thickness_(thickness), material_(&material) {
    gauss_legendre(thickness_points, z_points_, z_weights_);
    const auto local_axes = [&](double r, double s) {
        const Basis mid = basis(initial_, r, s, 0.0);
        const Vec3 e3 = mid.g[0].cross(mid.g[1]).normalized();
        const Vec3 e1 = mid.g[0].normalized();
        Mat3 axes;
        axes << e1, e3.cross(e1), e3;
        return axes;
    };
    const Mat3 centre = local_axes(0.0, 0.0);
    const double g = 1.0 / std::sqrt(3.0);
    for (const double s : {-g, g}) {
        for (const double r : {-g, g}) {
            // Local frame (Bathe FEP eq. 5.117): e3 normal to the mid-surface, e1 along g_r.
            const Mat3 frame = local_axes(r, s);
            for (std::size_t iz = 0; iz < z_points_.size(); ++iz) {
                const Basis ref = basis(initial_, r, s, z_points_[iz]);
                Mat3 jacobian;
                jacobian << ref.g[0], ref.g[1], ref.g[2];
                // Rows of J^-1 are the contravariant base vectors G^i; a(i, a) = G^i . e_a.
                const Mat3 a = jacobian.inverse() * frame;
                PointFrame pf;
                for (int c = 0; c < 5; ++c) {
                    Mat3 unit = Mat3::Zero();
                    unit(kPairs[c][0], kPairs[c][1]) = 1.0;
                    unit(kPairs[c][1], kPairs[c][0]) = 1.0;
                    const Mat3 local = a.transpose() * unit * a;
                    pf.transform.col(c) << local(0, 0), local(1, 1), 2.0 * local(0, 1),
                        2.0 * local(1, 2), 2.0 * local(2, 0);
                }
                pf.weight = z_weights_[iz] * jacobian.determinant();
                pf.z = z_points_[iz];
                pf.to_centre = centre.transpose() * frame;
                frames_.push_back(pf);
            }
        }
    }
    MaterialPoint point;
    point.state.assign(static_cast<std::size_t>(material.state_size()), 0.0);
    material.initialise_state(point.state);
    committed_.assign(frames_.size(), point);
    trial_ = committed_;
}

Mitc4Shell::Basis Mitc4Shell::basis(const ShellNodes& nodes, double r, double s, double z) const {
    Basis b;
    const double half = 0.5 * thickness_;
    for (auto& g : b.g) {
        g.setZero();
    }
    for (auto& dg : b.dg) {
        dg.setZero();
    }
    for (int k = 0; k < 4; ++k) {
        const double h = 0.25 * (1.0 + r * kNodeR[k]) * (1.0 + s * kNodeS[k]);
        const double hr = 0.25 * kNodeR[k] * (1.0 + s * kNodeS[k]);
        const double hs = 0.25 * kNodeS[k] * (1.0 + r * kNodeR[k]);
        const Vec3& x = nodes.x[static_cast<std::size_t>(k)];
        const Vec3& v = nodes.director[static_cast<std::size_t>(k)];
        b.coefficient[0][static_cast<std::size_t>(k)] = hr * z * half;
        b.coefficient[1][static_cast<std::size_t>(k)] = hs * z * half;
        b.coefficient[2][static_cast<std::size_t>(k)] = h * half;
        b.g[0] += hr * (x + z * half * v);
        b.g[1] += hs * (x + z * half * v);
        b.g[2] += h * half * v;
        const Mat3 dv = -skew(v); // d(theta x v)/d theta
        b.dg[0].block<3, 3>(0, 6 * k) = hr * Mat3::Identity();
        b.dg[1].block<3, 3>(0, 6 * k) = hs * Mat3::Identity();
        for (std::size_t i = 0; i < 3; ++i) {
            b.dg[i].block<3, 3>(0, 6 * k + 3) = b.coefficient[i][static_cast<std::size_t>(k)] * dv;
        }
    }
    return b;
}

void Mitc4Shell::covariant_strain(const ShellNodes& current, double r, double s, double z,
                                  ShellVector& strain, Eigen::Matrix<double, 5, 24>& derivative,
                                  std::array<Basis, 5>& bases) const {
    std::array<double, 5> value{};
    for (std::size_t p = 0; p < 5; ++p) {
        // Tying points are evaluated at the same thickness coordinate as the point itself.
        const double rp = p == 0 ? r : kTyingR[p];
        const double sp = p == 0 ? s : kTyingS[p];
        bases[p] = basis(current, rp, sp, z);
    }
    std::array<Basis, 5> reference;
    for (std::size_t p = 0; p < 5; ++p) {
        reference[p] = basis(initial_, p == 0 ? r : kTyingR[p], p == 0 ? s : kTyingS[p], z);
    }
    // e_ij = (g_i.g_j - G_i.G_j)/2 (Green-Lagrange, covariant; Bathe FEP eq. 6.41).
    const auto component = [&](std::size_t p, int i, int j, double& e,
                               Eigen::Matrix<double, 1, 24>& de) {
        const Basis& b = bases[p];
        const Basis& b0 = reference[p];
        const auto ui = static_cast<std::size_t>(i);
        const auto uj = static_cast<std::size_t>(j);
        e = 0.5 * (b.g[ui].dot(b.g[uj]) - b0.g[ui].dot(b0.g[uj]));
        de = 0.5 * (b.g[ui].transpose() * b.dg[uj] + b.g[uj].transpose() * b.dg[ui]);
    };
    Eigen::Matrix<double, 1, 24> d1, d2;
    double e1 = 0.0;
    double e2 = 0.0;
    for (int c = 0; c < 3; ++c) {
        Eigen::Matrix<double, 1, 24> d;
        component(0, kPairs[c][0], kPairs[c][1], value[static_cast<std::size_t>(c)], d);
        derivative.row(c) = d;
    }
    // Assumed transverse shear strains (Dvorkin & Bathe 1984, eq. 10).
    component(1, 0, 2, e1, d1);
    component(2, 0, 2, e2, d2);
    value[3] = 0.5 * (1.0 + s) * e1 + 0.5 * (1.0 - s) * e2;
    derivative.row(3) = 0.5 * (1.0 + s) * d1 + 0.5 * (1.0 - s) * d2;
    component(3, 1, 2, e1, d1);
    component(4, 1, 2, e2, d2);
    value[4] = 0.5 * (1.0 + r) * e1 + 0.5 * (1.0 - r) * e2;
    derivative.row(4) = 0.5 * (1.0 + r) * d1 + 0.5 * (1.0 - r) * d2;
    for (int c = 0; c < 5; ++c) {
        strain(c) = value[static_cast<std::size_t>(c)];
    }
}

void Mitc4Shell::add_geometric_stiffness(const ShellNodes& current,
                                         const std::array<Basis, 5>& bases, double r, double s,
                                         const ShellVector& weights, Matrix24& stiffness) const {
    // Second variation of e_ij: (dg_i.dg_j + dg_j.dg_i)/2 plus the director terms
    // (g_i.ddg_j + g_j.ddg_i)/2 with ddV[a, b] = (a x (b x V) + b x (a x V))/2, i.e.
    // w.ddV[a, b] = a^T (sym(V w^T) - (w.V) I) b for the exponential director update.
    const auto term = [&](const Basis& b, int i, int j, double w) {
        const auto ui = static_cast<std::size_t>(i);
        const auto uj = static_cast<std::size_t>(j);
        stiffness.noalias() +=
            (0.5 * w) * (b.dg[ui].transpose() * b.dg[uj] + b.dg[uj].transpose() * b.dg[ui]);
        for (std::size_t k = 0; k < 4; ++k) {
            const Vec3& v = current.director[k];
            const auto m = [&](const Vec3& g) -> Mat3 {
                return 0.5 * (v * g.transpose() + g * v.transpose()) - g.dot(v) * Mat3::Identity();
            };
            const Mat3 block =
                b.coefficient[uj][k] * m(b.g[ui]) + b.coefficient[ui][k] * m(b.g[uj]);
            const int o = 6 * static_cast<int>(k) + 3;
            stiffness.block<3, 3>(o, o) += (0.5 * w) * block;
        }
    };
    term(bases[0], 0, 0, weights(0));
    term(bases[0], 1, 1, weights(1));
    term(bases[0], 0, 1, weights(2));
    term(bases[1], 0, 2, weights(3) * 0.5 * (1.0 + s));
    term(bases[2], 0, 2, weights(3) * 0.5 * (1.0 - s));
    term(bases[3], 1, 2, weights(4) * 0.5 * (1.0 + r));
    term(bases[4], 1, 2, weights(4) * 0.5 * (1.0 - r));
}

Matrix24 Mitc4Shell::drilling_stiffness(const ShellNodes& current,
                                        const Matrix24& stiffness) const {
    double largest = 0.0;
    for (int k = 0; k < 4; ++k) {
        largest =
            std::max(largest, stiffness.block<3, 3>(6 * k + 3, 6 * k + 3).diagonal().maxCoeff());
    }
    Matrix24 spring = Matrix24::Zero();
    for (std::size_t k = 0; k < 4; ++k) {
        if (fold_corners_[k]) {
            continue;
        }
        const Vec3& v = current.director[k];
        const int o = 6 * static_cast<int>(k) + 3;
        spring.block<3, 3>(o, o) = kDrillingFactor * largest * v * v.transpose();
    }
    return spring;
}

void Mitc4Shell::keep_strain_operators() {
    // Under linear kinematics the derivative is that of the initial geometry (evaluate()).
    strain_operators_.clear();
    strain_operators_.reserve(frames_.size());
    const double g = 1.0 / std::sqrt(3.0);
    std::array<Basis, 5> bases;
    for (const double s : {-g, g}) {
        for (const double r : {-g, g}) {
            for (const double z : z_points_) {
                ShellVector covariant;
                StrainDerivative derivative;
                covariant_strain(initial_, r, s, z, covariant, derivative, bases);
                strain_operators_.push_back(derivative);
            }
        }
    }
}

ShellVector Mitc4Shell::linear_strain(std::size_t point, const StrainDerivative& derivative,
                                      const Vector24& linear_dofs) const {
    const ShellVector covariant = derivative * linear_dofs;
    return frames_[point].transform * covariant;
}

void Mitc4Shell::update_stresses(const Vector24& linear_dofs) {
    if (strain_operators_.empty()) {
        keep_strain_operators();
    }
    for (std::size_t point = 0; point < frames_.size(); ++point) {
        plane_stress_update(*material_, linear_strain(point, strain_operators_[point], linear_dofs),
                            committed_[point], trial_[point], nullptr);
    }
}

void Mitc4Shell::evaluate(const ShellNodes& current, const Vector24& linear_dofs,
                          Kinematics kinematics, Vector24& force, Matrix24* stiffness,
                          Matrix24* drilling) {
    const bool linear = kinematics == Kinematics::linear;
    const bool kept = linear && !strain_operators_.empty();
    const ShellNodes& geometry = linear ? initial_ : current;
    force.setZero();
    if (stiffness != nullptr) {
        stiffness->setZero();
    }
    const double g = 1.0 / std::sqrt(3.0);
    std::size_t point = 0;
    std::array<Basis, 5> bases;
    for (const double s : {-g, g}) {
        for (const double r : {-g, g}) {
            for (std::size_t iz = 0; iz < z_points_.size(); ++iz, ++point) {
                const PointFrame& pf = frames_[point];
                ShellVector covariant;
                StrainDerivative computed;
                if (!kept) {
                    covariant_strain(geometry, r, s, pf.z, covariant, computed, bases);
                }
                const StrainDerivative& derivative = kept ? strain_operators_[point] : computed;
                const ShellVector strain = linear ? linear_strain(point, derivative, linear_dofs)
                                                  : ShellVector(pf.transform * covariant);
                const Eigen::Matrix<double, 5, 24> b = pf.transform * derivative;
                ShellMatrix c;
                const ShellVector stress =
                    plane_stress_update(*material_, strain, committed_[point], trial_[point],
                                        stiffness != nullptr ? &c : nullptr);
                // Internal force sum B^T S dV (thesis eq. 5.2.10).
                force.noalias() += pf.weight * (b.transpose() * stress);
                if (stiffness == nullptr) {
                    continue;
                }
                stiffness->noalias() += pf.weight * (b.transpose() * c * b);
                if (!linear) {
                    const ShellVector weights = pf.weight * (pf.transform.transpose() * stress);
                    add_geometric_stiffness(geometry, bases, r, s, weights, *stiffness);
                }
            }
        }
    }
    if (stiffness == nullptr) {
        return;
    }
    const Matrix24 spring = drilling_stiffness(geometry, *stiffness);
    if (drilling != nullptr) {
        *drilling = spring;
    } else {
        *stiffness += spring;
    }
}

ShellResultants Mitc4Shell::resultants() const {
    ShellResultants out;
    const double half = 0.5 * thickness_;
    const std::size_t nz = z_points_.size();
    const std::vector<double>& z = z_points_;
    std::array<Mat3, kMaxThicknessPoints> column; // no allocation per element and window
    // committed_ holds the thickness points of each in-plane point in turn, lowest first.
    for (std::size_t first = 0; first < committed_.size(); first += nz) {
        for (std::size_t iz = 0; iz < nz; ++iz) {
            const Voigt6& s = committed_[first + iz].stress;
            Mat3 tensor;
            tensor << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
            const Mat3& t = frames_[first + iz].to_centre;
            column[iz] = t * tensor * t.transpose();
            const Eigen::Vector3d in_plane(column[iz](0, 0), column[iz](1, 1), column[iz](0, 1));
            out.membrane += 0.25 * z_weights_[iz] * half * in_plane;
            out.bending += 0.25 * z_weights_[iz] * half * z[iz] * half * in_plane;
            out.plastic_strain =
                std::max(out.plastic_strain,
                         material_->equivalent_plastic_strain(committed_[first + iz].state));
        }
        // The faces z = -1, +1 and the mid-surface: no Gauss-Legendre point lies on a face
        // (the outermost of two is at 1/sqrt(3), where a bending stress is 58 % of the face's),
        // so the stress is carried there along the line through the two nearest points.
        const std::size_t mid = nz / 2;
        const Mat3 bottom = along_thickness(column[0], z[0], column[1], z[1], -1.0);
        const Mat3 top = along_thickness(column[nz - 2], z[nz - 2], column[nz - 1], z[nz - 1], 1.0);
        const Mat3 middle =
            nz % 2 == 1 ? column[mid]
                        : along_thickness(column[mid - 1], z[mid - 1], column[mid], z[mid], 0.0);
        out.von_mises_bottom += 0.25 * von_mises(bottom);
        out.von_mises_top += 0.25 * von_mises(top);
        out.von_mises_middle += 0.25 * von_mises(middle);
    }
    return out;
}

Vector24 Mitc4Shell::lumped_mass() const {
    double area = 0.0;
    const double g = 1.0 / std::sqrt(3.0);
    for (const double s : {-g, g}) {
        for (const double r : {-g, g}) {
            const Basis b = basis(initial_, r, s, 0.0);
            area += b.g[0].cross(b.g[1]).norm();
        }
    }
    const double rho = material_->density();
    Vector24 m;
    for (int k = 0; k < 4; ++k) {
        m.segment<3>(6 * k).setConstant(0.25 * rho * thickness_ * area);
        m.segment<3>(6 * k + 3).setConstant(0.25 * rho * thickness_ * thickness_ * thickness_ /
                                            12.0 * area);
    }
    return m;
}

Matrix24 Mitc4Shell::consistent_mass() const {
    const double rho = material_->density();
    const double translation = rho * thickness_;
    const double rotation = rho * thickness_ * thickness_ * thickness_ / 12.0;
    Matrix24 m = Matrix24::Zero();
    const double g = 1.0 / std::sqrt(3.0);
    for (const double s : {-g, g}) {
        for (const double r : {-g, g}) {
            const Basis b = basis(initial_, r, s, 0.0);
            const double area = b.g[0].cross(b.g[1]).norm();
            for (int i = 0; i < 4; ++i) {
                const double hi = 0.25 * (1.0 + r * kNodeR[i]) * (1.0 + s * kNodeS[i]);
                for (int j = 0; j < 4; ++j) {
                    const double hj = 0.25 * (1.0 + r * kNodeR[j]) * (1.0 + s * kNodeS[j]);
                    for (int d = 0; d < 3; ++d) {
                        m(6 * i + d, 6 * j + d) += translation * hi * hj * area;
                        m(6 * i + 3 + d, 6 * j + 3 + d) += rotation * hi * hj * area;
                    }
                }
            }
        }
    }
    return m;
}

} // namespace grainload::fem
