#include "fem/dof_index.hpp"
#include "fem/shell_analysis.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

// Loads, prescribed values and their histories: the parts of ShellAnalysis that define what is
// applied at a load factor lambda (static: lambda = load factor or time; dynamic: time).

namespace grainload::fem {

int ShellAnalysis::add_history(History scale) {
    histories_.push_back({std::move(scale), Eigen::VectorXd::Zero(dofs_.size())});
    return static_cast<int>(histories_.size()) - 1;
}

Eigen::VectorXd& ShellAnalysis::active_load() {
    return histories_.at(at(active_history_)).load;
}

bool ShellAnalysis::loads_change(double from, double to) const {
    // Relative round-off tolerance: times accumulated in floating point land a hair before a
    // breakpoint, and an increment of 1e-16 would leave Newton nothing to converge on but
    // round-off.
    for (const LoadHistory& h : histories_) {
        const double a = h.scale(from), b = h.scale(to);
        if (std::abs(a - b) > 1e-12 * std::max({1.0, std::abs(a), std::abs(b)})) {
            return true;
        }
    }
    return false;
}

bool ShellAnalysis::history_acts(int index) const {
    if (!histories_.at(at(index)).load.isZero(0.0)) {
        return true;
    }
    for (std::size_t d = 0; d < prescribed_.size(); ++d) {
        if (prescribed_history_[d] == index && !std::isnan(prescribed_[d]) &&
            prescribed_[d] != 0.0) {
            return true;
        }
    }
    return std::any_of(
               rigid_rotations_.begin(), rigid_rotations_.end(),
               [&](const RigidRotation& r) { return r.history == index && r.angle != 0.0; }) ||
           std::any_of(
               follower_pressures_.begin(), follower_pressures_.end(),
               [&](const FollowerPressure& f) { return f.history == index && f.pressure != 0.0; });
}

Eigen::VectorXd ShellAnalysis::applied_forces(double lambda) const {
    Eigen::VectorXd f = additional_forces_;
    for (const LoadHistory& h : histories_) {
        if (!h.load.isZero()) {
            f += h.scale(lambda) * h.load;
        }
    }
    return f;
}

void ShellAnalysis::prescribe_rigid_rotation(const std::vector<Index>& nodes, const Vec3& axis,
                                             const Vec3& point, double angle) {
    rigid_rotations_.push_back({nodes, axis.normalized(), point, angle, active_history_});
    prescribe(nodes, {0, 1, 2, 3, 4, 5});
}

Eigen::VectorXd ShellAnalysis::prescribed_at(double lambda) const {
    Eigen::VectorXd values = Eigen::VectorXd::Zero(dofs_.size());
    std::vector<double> scale(histories_.size());
    for (std::size_t h = 0; h < histories_.size(); ++h) {
        scale[h] = histories_[h].scale(lambda);
    }
    for (std::size_t d = 0; d < prescribed_.size(); ++d) {
        if (!std::isnan(prescribed_[d])) {
            values(static_cast<Eigen::Index>(d)) =
                scale[at(prescribed_history_[d])] * prescribed_[d];
        }
    }
    // A finite rotation is not proportional to its angle: the translations come from the exact
    // rotation matrix, so that a lifted edge follows the circle, not its tangent. The rotation
    // vector theta * axis composes exactly with the multiplicative update (increments are
    // coaxial).
    for (const RigidRotation& r : rigid_rotations_) {
        const double theta = scale[at(r.history)] * r.angle;
        const Mat3 rotation = Eigen::AngleAxisd(theta, r.axis).toRotationMatrix();
        for (const Index n : r.nodes) {
            const Vec3 arm = mesh_.node(n) - r.point;
            values.segment<3>(kDofs * n) = rotation * arm - arm;
            values.segment<3>(kDofs * n + 3) = theta * r.axis;
        }
    }
    return values;
}

void ShellAnalysis::prescribe(Index node, int dof, double value) {
    prescribed_[at(kDofs * node + dof)] = value;
    prescribed_history_[at(kDofs * node + dof)] = active_history_;
    numbered_ = false;
}

void ShellAnalysis::prescribe(const std::vector<Index>& nodes, std::initializer_list<int> dofs,
                              double value) {
    for (const Index n : nodes) {
        for (const int d : dofs) {
            prescribe(n, d, value);
        }
    }
}

void ShellAnalysis::add_nodal_load(Index node, int dof, double value) {
    active_load()(kDofs * node + dof) += value;
}

void ShellAnalysis::add_surface_load(const SurfaceTraction& traction) {
    // Consistent nodal loads sum_gp h_k q |G_r x G_s| over 2 x 2 Gauss points of the initial
    // mid-surface (Bathe FEP eq. 4.22, surface term).
    constexpr double nr[4] = {-1.0, 1.0, 1.0, -1.0};
    constexpr double ns[4] = {-1.0, -1.0, 1.0, 1.0};
    const double g = 1.0 / std::sqrt(3.0);
    Eigen::VectorXd& load = active_load();
    for (const auto& e : mesh_.elements()) {
        if (active_part_ >= 0 && e.part != active_part_) {
            continue;
        }
        for (const double s : {-g, g}) {
            for (const double r : {-g, g}) {
                Vec3 gr = Vec3::Zero();
                Vec3 gs = Vec3::Zero();
                for (std::size_t k = 0; k < 4; ++k) {
                    gr += 0.25 * nr[k] * (1.0 + s * ns[k]) * mesh_.node(e.nodes[k]);
                    gs += 0.25 * ns[k] * (1.0 + r * nr[k]) * mesh_.node(e.nodes[k]);
                }
                const Vec3 normal = gr.cross(gs);
                const double area = normal.norm();
                const Vec3 q = traction(e, normal / area);
                for (std::size_t k = 0; k < 4; ++k) {
                    const double h = 0.25 * (1.0 + r * nr[k]) * (1.0 + s * ns[k]);
                    load.segment<3>(kDofs * e.nodes[k]) += h * area * q;
                }
            }
        }
    }
}

void ShellAnalysis::add_area_load(const Vec3& force_per_area) {
    add_surface_load([&](const ShellElement&, const Vec3&) { return force_per_area; });
}

void ShellAnalysis::add_pressure(double pressure) {
    add_surface_load(
        [&](const ShellElement&, const Vec3& normal) { return Vec3(pressure * normal); });
}

void ShellAnalysis::add_follower_pressure(double pressure) {
    follower_pressures_.push_back({pressure, active_history_, active_part_});
}

namespace {

/// The bilinear shape functions h_k of a quadrilateral at (r, s), their derivatives along r and
/// s, and the covariant base vectors g_r, g_s of its current nodes x there.
struct QuadPoint {
    double h[4], hr[4], hs[4];
    Vec3 gr = Vec3::Zero(), gs = Vec3::Zero();
};

QuadPoint quad_point(const std::array<Vec3, 4>& x, double r, double s) {
    constexpr double nr[4] = {-1.0, 1.0, 1.0, -1.0};
    constexpr double ns[4] = {-1.0, -1.0, 1.0, 1.0};
    QuadPoint q;
    for (std::size_t k = 0; k < 4; ++k) {
        q.h[k] = 0.25 * (1.0 + r * nr[k]) * (1.0 + s * ns[k]);
        q.hr[k] = 0.25 * nr[k] * (1.0 + s * ns[k]);
        q.hs[k] = 0.25 * ns[k] * (1.0 + r * nr[k]);
        q.gr += q.hr[k] * x[k];
        q.gs += q.hs[k] * x[k];
    }
    return q;
}

Mat3 skew(const Vec3& v) {
    Mat3 m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

/// The load stiffness of a follower pressure p at one Gauss point q of an element with `nodes`,
///   -d f_i / d x_k = -p h_i (h_k,s [g_r]x - h_k,r [g_s]x),
/// scattered to the free equations (`equation` per DOF, -1: constrained) of the nodes'
/// translations.
void add_follower_stiffness(const QuadPoint& q, double p, const std::array<Index, 4>& nodes,
                            const std::vector<Index>& equation,
                            std::vector<Eigen::Triplet<double>>& triplets) {
    const Mat3 sr = skew(q.gr), ss = skew(q.gs);
    for (std::size_t i = 0; i < 4; ++i) {
        for (std::size_t k = 0; k < 4; ++k) {
            const Mat3 block = -p * q.h[i] * (q.hs[k] * sr - q.hr[k] * ss);
            for (int a = 0; a < 3; ++a) {
                const Index row = equation[at(kDofs * nodes[i] + a)];
                for (int b = 0; b < 3 && row >= 0; ++b) {
                    const Index col = equation[at(kDofs * nodes[k] + b)];
                    if (col >= 0) {
                        triplets.emplace_back(row, col, block(a, b));
                    }
                }
            }
        }
    }
}

} // namespace

void ShellAnalysis::add_follower_loads(Eigen::VectorXd& internal,
                                       std::vector<Eigen::Triplet<double>>* triplets) const {
    // f_i = p sum_gp h_i (g_r x g_s) on the current mid-surface (2 x 2 Gauss points): the
    // pressure follows the deformed normal and area. Assembled into the internal forces with
    // a minus sign, so that the residual keeps F - Fu; the load stiffness (add_follower_stiffness)
    // is not symmetric (Bathe FEP section 6.3.3; Hibbitt 1979). The rotations do not enter.
    const double g = 1.0 / std::sqrt(3.0);
    for (const FollowerPressure& follower : follower_pressures_) {
        const double p =
            histories_[at(follower.history)].scale(assembly_load_factor_) * follower.pressure;
        if (p == 0.0) {
            continue;
        }
        for (const auto& e : mesh_.elements()) {
            if (follower.part >= 0 && e.part != follower.part) {
                continue;
            }
            std::array<Vec3, 4> x;
            for (std::size_t k = 0; k < 4; ++k) {
                x[k] = mesh_.node(e.nodes[k]) + dofs_.segment<3>(kDofs * e.nodes[k]);
            }
            for (const double s : {-g, g}) {
                for (const double r : {-g, g}) {
                    const QuadPoint q = quad_point(x, r, s);
                    const Vec3 normal = q.gr.cross(q.gs);
                    for (std::size_t i = 0; i < 4; ++i) {
                        internal.segment<3>(kDofs * e.nodes[i]) -= p * q.h[i] * normal;
                    }
                    if (triplets != nullptr) {
                        add_follower_stiffness(q, p, e.nodes, equation_, *triplets);
                    }
                }
            }
        }
    }
}

void ShellAnalysis::add_gravity(const Vec3& acceleration) {
    add_surface_load([&](const ShellElement& e, const Vec3&) {
        const double rho = parts_[at(e.part)].material->density();
        return Vec3(rho * e.thickness * acceleration);
    });
}

} // namespace grainload::fem
