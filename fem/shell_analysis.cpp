#include "fem/shell_analysis.hpp"

#include "fem/dof_index.hpp"
#include "fem/static_increment.hpp"
#include "io/binary_stream.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace grainload::fem {

namespace {

/// Rotation matrix of a rotation vector (Rodrigues' formula).
Mat3 exponential(const Vec3& v) {
    const double angle = v.norm();
    if (angle < 1e-300) {
        return Mat3::Identity();
    }
    return Eigen::AngleAxisd(angle, v / angle).toRotationMatrix();
}

} // namespace

ShellAnalysis::ShellAnalysis(ShellMesh mesh, const materials::Material& material,
                             Kinematics kinematics, int thickness_points)
    : ShellAnalysis(std::move(mesh), {ShellPart{"shell", &material, thickness_points}},
                    kinematics) {}

ShellAnalysis::ShellAnalysis(ShellMesh mesh, std::vector<ShellPart> parts, Kinematics kinematics)
    : mesh_(std::move(mesh)), kinematics_(kinematics), parts_(std::move(parts)) {
    mesh_.validate();
    for (const ShellElement& element : mesh_.elements()) {
        if (element.part < 0 || element.part >= static_cast<int>(parts_.size())) {
            throw std::invalid_argument("shell element of part " + std::to_string(element.part) +
                                        ", but the structure has " + std::to_string(parts_.size()) +
                                        " parts");
        }
    }
    initial_directors_ = element_directors(mesh_);
    const Index n = mesh_.node_count();
    prescribed_.assign(at(kDofs * n), std::numeric_limits<double>::quiet_NaN());
    prescribed_history_.assign(at(kDofs * n), 0);
    histories_.push_back({[](double lambda) { return lambda; }, Eigen::VectorXd::Zero(kDofs * n)});
    additional_forces_ = Eigen::VectorXd::Zero(kDofs * n);
    dofs_ = Eigen::VectorXd::Zero(kDofs * n);
    rotations_.assign(at(n), Mat3::Identity());
    elements_.reserve(at(mesh_.element_count()));
    std::vector<bool> fold(at(n), false);
    for (const Index node : fold_nodes(mesh_)) {
        fold[at(node)] = true;
    }
    for (std::size_t e = 0; e < mesh_.elements().size(); ++e) {
        const ShellElement& element = mesh_.elements()[e];
        const ShellPart& part = parts_[static_cast<std::size_t>(element.part)];
        elements_.emplace_back(element_nodes(e), element.thickness, *part.material,
                               part.thickness_points);
        elements_.back().set_fold_corners({fold[at(element.nodes[0])], fold[at(element.nodes[1])],
                                           fold[at(element.nodes[2])], fold[at(element.nodes[3])]});
    }
    committed_dofs_ = dofs_;
    committed_rotations_ = rotations_;
}

bool ShellAnalysis::constant_tangent() const {
    if (kinematics_ != Kinematics::linear || has_moment_loads_ || !follower_pressures_.empty()) {
        return false;
    }
    return std::all_of(parts_.begin(), parts_.end(), [](const ShellPart& part) {
        return part.material->model() == "linear_elastic";
    });
}

bool ShellAnalysis::prescribes_motion() const {
    return !rigid_rotations_.empty() ||
           std::any_of(prescribed_.begin(), prescribed_.end(),
                       [](double value) { return !std::isnan(value) && value != 0.0; });
}

ShellNodes ShellAnalysis::element_nodes(std::size_t element) const {
    ShellNodes nodes;
    for (std::size_t k = 0; k < 4; ++k) {
        const Index n = mesh_.elements()[element].nodes[k];
        nodes.x[k] = mesh_.node(n) + dofs_.segment<3>(kDofs * n);
        // One rotation per node turns every director attached to it (Dvorkin & Bathe 1984:
        // the rotational DOFs are global, so the folded faces stay rigidly joined).
        nodes.director[k] = rotations_[at(n)] * initial_directors_[element][k];
    }
    return nodes;
}

Vector24 ShellAnalysis::element_dofs(const ShellElement& element,
                                     const Eigen::VectorXd& dofs) const {
    Vector24 a;
    for (int k = 0; k < 4; ++k) {
        a.segment<6>(kDofs * k) = dofs.segment<6>(kDofs * element.nodes[at(k)]);
    }
    return a;
}

void ShellAnalysis::number_equations() {
    equation_.assign(prescribed_.size(), -1);
    free_count_ = 0;
    for (std::size_t d = 0; d < prescribed_.size(); ++d) {
        if (std::isnan(prescribed_[d])) {
            equation_[d] = free_count_++;
        }
    }
    numbered_ = true;
}

Index ShellAnalysis::free_dof_count() const {
    if (numbered_) {
        return free_count_;
    }
    return static_cast<Index>(std::count_if(prescribed_.begin(), prescribed_.end(),
                                            [](double v) { return std::isnan(v); }));
}

const std::vector<Index>& ShellAnalysis::equation_numbers() {
    if (!numbered_) {
        number_equations();
    }
    return equation_;
}

void ShellAnalysis::assemble(SparseSolver::Matrix* tangent, Eigen::VectorXd& internal,
                             const Eigen::VectorXd* prescribed, Eigen::VectorXd* coupling) {
    if (uses_stored_stiffness()) {
        assemble_stored(tangent, internal, prescribed, coupling);
        return;
    }
    const std::vector<Index>& eq = equation_numbers();
    internal = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(prescribed_.size()));
    if (coupling != nullptr) {
        *coupling = Eigen::VectorXd::Zero(internal.size());
    }
    std::vector<Eigen::Triplet<double>> triplets;
    if (tangent != nullptr) {
        triplets.reserve(at(576 * mesh_.element_count()));
    }
    Vector24 force;
    Matrix24 k;
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        const ShellElement& element = mesh_.elements()[e];
        elements_[e].evaluate(element_nodes(e), element_dofs(element, dofs_), kinematics_, force,
                              tangent != nullptr ? &k : nullptr);
        std::array<Index, 24> global{};
        for (int a = 0; a < 24; ++a) {
            global[at(a)] = kDofs * element.nodes[at(a / kDofs)] + a % kDofs;
            internal(global[at(a)]) += force(a);
        }
        if (tangent == nullptr) {
            continue;
        }
        if (prescribed != nullptr && coupling != nullptr) {
            Vector24 ap;
            for (int a = 0; a < 24; ++a) {
                ap(a) = (*prescribed)(global[at(a)]);
            }
            const Vector24 fp = k * ap;
            for (int a = 0; a < 24; ++a) {
                (*coupling)(global[at(a)]) += fp(a);
            }
        }
        for (int a = 0; a < 24; ++a) {
            const Index row = eq[at(global[at(a)])];
            for (int b = 0; b < 24 && row >= 0; ++b) {
                const Index col = eq[at(global[at(b)])];
                if (col >= 0) {
                    triplets.emplace_back(row, col, k(a, b));
                }
            }
        }
    }
    add_follower_loads(internal, tangent != nullptr ? &triplets : nullptr);
    add_node_springs(internal, tangent != nullptr ? &triplets : nullptr, prescribed, coupling);
    if (tangent != nullptr) {
        add_moment_load_stiffness(internal, triplets);
        tangent->resize(free_count_, free_count_);
        tangent->setFromTriplets(triplets.begin(), triplets.end());
    }
}

void ShellAnalysis::add_moment_load_stiffness(const Eigen::VectorXd& internal,
                                              std::vector<Eigen::Triplet<double>>& triplets) {
    // With multiplicative (spin) rotation increments the derivative of the nodal internal
    // moment m has the non-symmetric part -[m]x / 2 (Simo & Vu-Quoc 1986). It vanishes at
    // equilibrium where no moment is applied, and is kept only at nodes carrying a moment
    // load: there it couples the drilling and the twisting rotation, and leaving it out makes
    // Newton diverge once (m/2)^2 exceeds the product of their stiffnesses.
    has_moment_loads_ = false;
    if (kinematics_ == Kinematics::linear) {
        return;
    }
    for (Index n = 0; n < mesh_.node_count(); ++n) {
        bool moment = false;
        for (const LoadHistory& h : histories_) {
            moment = moment || !h.load.segment<3>(kDofs * n + 3).isZero();
        }
        if (!moment) {
            continue;
        }
        has_moment_loads_ = true;
        const Vec3 m = internal.segment<3>(kDofs * n + 3);
        Mat3 skew;
        skew << 0.0, -m.z(), m.y(), m.z(), 0.0, -m.x(), -m.y(), m.x(), 0.0;
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
                const Index row = equation_[at(kDofs * n + 3 + a)];
                const Index col = equation_[at(kDofs * n + 3 + b)];
                if (row >= 0 && col >= 0 && a != b) {
                    triplets.emplace_back(row, col, -0.5 * skew(a, b));
                }
            }
        }
    }
}

void ShellAnalysis::update_state(const Eigen::VectorXd& increment) {
    dofs_ += increment;
    if (kinematics_ == Kinematics::linear) {
        return;
    }
    // Multiplicative rotation update R <- exp(dtheta) R: the directors follow finite
    // incremental rotations exactly (Bathe FEP eq. 6.122 in its exact form).
    for (Index n = 0; n < mesh_.node_count(); ++n) {
        rotations_[at(n)] = exponential(increment.segment<3>(kDofs * n + 3)) * rotations_[at(n)];
    }
}

void ShellAnalysis::commit() {
    for (auto& e : elements_) {
        e.commit();
    }
    committed_dofs_ = dofs_;
    committed_rotations_ = rotations_;
    stresses_stale_ = uses_stored_stiffness();
}

void ShellAnalysis::revert_to_committed() {
    for (auto& e : elements_) {
        e.revert();
    }
    dofs_ = committed_dofs_;
    rotations_ = committed_rotations_;
}

bool ShellAnalysis::increment(double from, double to, const NewtonSettings& settings,
                              StepReport& report) {
    StaticIncrement problem(*this, from, to, settings);
    std::vector<NewtonIteration> log;
    try {
        if (!newton_.solve(problem, settings, log, report)) {
            return false;
        }
    } catch (const std::runtime_error&) {
        // A material update that failed or a singular tangent: the caller cuts back.
        return false;
    }
    commit();
    report.log.insert(report.log.end(), log.begin(), log.end());
    report.iterations.push_back(static_cast<int>(log.size()));
    return true;
}

StepReport ShellAnalysis::advance_load(double target, int increments,
                                       const NewtonSettings& settings) {
    StepReport report;
    const double nominal = (target - load_factor_) / std::max(increments, 1);
    double step = nominal;
    int consecutive_cutbacks = 0;
    while (std::abs(target - load_factor_) > 1e-12 * std::abs(nominal)) {
        const double to = std::abs(target - load_factor_) < std::abs(step) * (1.0 + 1e-9)
                              ? target
                              : load_factor_ + step;
        if (increment(load_factor_, to, settings, report)) {
            load_factor_ = to;
            ++report.increments;
            consecutive_cutbacks = 0;
            step = std::abs(step * 2.0) < std::abs(nominal) ? step * 2.0 : nominal;
            continue;
        }
        revert_to_committed();
        ++report.cutbacks;
        if (++consecutive_cutbacks > settings.max_cutbacks) {
            report.load_factor = load_factor_;
            return report;
        }
        step *= 0.5;
    }
    report.converged = true;
    report.load_factor = load_factor_;
    return report;
}

StepReport ShellAnalysis::equilibrate(const NewtonSettings& settings) {
    StepReport report;
    report.converged = increment(load_factor_, load_factor_, settings, report);
    if (!report.converged) {
        revert_to_committed();
    }
    report.increments = report.converged ? 1 : 0;
    report.load_factor = load_factor_;
    return report;
}

StepReport ShellAnalysis::solve_linear() {
    return advance_load(1.0, 1, NewtonSettings{});
}

Vec3 ShellAnalysis::displacement(Index node) const {
    return dofs_.segment<3>(kDofs * node);
}

Vec3 ShellAnalysis::rotation(Index node) const {
    if (kinematics_ == Kinematics::linear) {
        return dofs_.segment<3>(kDofs * node + 3);
    }
    const Eigen::AngleAxisd aa(rotations_[at(node)]);
    return aa.angle() * aa.axis();
}

Vec3 ShellAnalysis::director(Index element, int corner) const {
    const Index node = mesh_.element(element).nodes[at(corner)];
    const Vec3& initial = initial_directors_[at(element)][at(corner)];
    if (kinematics_ == Kinematics::linear) {
        // Linear kinematics: the director moves by theta x V (Bathe FEP eq. 5.111's linear
        // part), the motion the element's own strains are computed from.
        return initial + dofs_.segment<3>(kDofs * node + 3).cross(initial);
    }
    return rotations_[at(node)] * initial;
}

Eigen::VectorXd ShellAnalysis::tangent_response(const Eigen::VectorXd& load) {
    return tangent_inverse()(load);
}

std::function<Eigen::VectorXd(const Eigen::VectorXd&)> ShellAnalysis::tangent_inverse() {
    // The matrix lives as long as the function: UMFPACK's factor (the LU fallback of a tangent
    // CHOLMOD refuses) solves with pointers into it.
    auto k = std::make_shared<SparseSolver::Matrix>();
    Eigen::VectorXd internal;
    set_assembly_load_factor(load_factor_);
    assemble(k.get(), internal);
    for (auto& e : elements_) {
        e.revert();
    }
    auto solver = std::make_shared<SparseSolver>();
    solver->factorize(*k, tangent_symmetric());
    return [k, solver, eq = equation_numbers(), free = free_count_](const Eigen::VectorXd& load) {
        Eigen::VectorXd response = Eigen::VectorXd::Zero(load.size());
        scatter_free(eq, solver->solve(free_part(eq, free, load)), response);
        return response;
    };
}

Eigen::VectorXd ShellAnalysis::reactions() {
    set_assembly_load_factor(load_factor_);
    Eigen::VectorXd internal;
    assemble(nullptr, internal);
    for (auto& e : elements_) {
        e.revert();
    }
    return internal - applied_forces(load_factor_);
}

Eigen::VectorXd ShellAnalysis::lumped_mass() const {
    Eigen::VectorXd m = Eigen::VectorXd::Zero(dofs_.size());
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        const Vector24 me = elements_[e].lumped_mass();
        const ShellElement& element = mesh_.elements()[e];
        for (int a = 0; a < 24; ++a) {
            m(kDofs * element.nodes[at(a / kDofs)] + a % kDofs) += me(a);
        }
    }
    return m;
}

SparseSolver::Matrix ShellAnalysis::consistent_mass() const {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(at(96 * mesh_.element_count()));
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        const Matrix24 me = elements_[e].consistent_mass();
        const ShellElement& element = mesh_.elements()[e];
        for (int a = 0; a < 24; ++a) {
            for (int b = a % kDofs; b < 24; b += kDofs) { // only like components couple
                triplets.emplace_back(kDofs * element.nodes[at(a / kDofs)] + a % kDofs,
                                      kDofs * element.nodes[at(b / kDofs)] + b % kDofs, me(a, b));
            }
        }
    }
    SparseSolver::Matrix m(dofs_.size(), dofs_.size());
    m.setFromTriplets(triplets.begin(), triplets.end());
    return m;
}

void ShellAnalysis::write_state(std::ostream& out) const {
    refresh_stresses();
    io::write_value(out, load_factor_);
    io::write_array(out, std::vector<double>(committed_dofs_.begin(), committed_dofs_.end()));
    io::write_array(out, committed_rotations_);
    for (const auto& e : elements_) {
        std::vector<Voigt6> tensors;
        std::vector<double> states;
        for (const auto& p : e.committed_points()) {
            tensors.push_back(p.strain);
            tensors.push_back(p.stress);
            states.insert(states.end(), p.state.begin(), p.state.end());
        }
        io::write_array(out, tensors);
        io::write_array(out, states);
    }
}

void ShellAnalysis::read_state(std::istream& in) {
    load_factor_ = io::read_value<double>(in);
    std::vector<double> dofs;
    io::read_array(in, dofs);
    io::read_array(in, committed_rotations_);
    if (dofs.size() != static_cast<std::size_t>(dofs_.size()) ||
        committed_rotations_.size() != at(mesh_.node_count())) {
        throw std::runtime_error("shell checkpoint does not match the model (node count)");
    }
    committed_dofs_ = Eigen::Map<const Eigen::VectorXd>(dofs.data(), dofs_.size());
    for (auto& e : elements_) {
        std::vector<Voigt6> tensors;
        std::vector<double> states;
        io::read_array(in, tensors);
        io::read_array(in, states);
        std::vector<MaterialPoint> points = e.committed_points();
        if (tensors.size() != 2 * points.size()) {
            throw std::runtime_error("shell checkpoint does not match the model (points)");
        }
        std::size_t offset = 0;
        for (std::size_t p = 0; p < points.size(); ++p) {
            points[p].strain = tensors[2 * p];
            points[p].stress = tensors[2 * p + 1];
            for (auto& v : points[p].state) {
                v = states.at(offset++);
            }
        }
        e.restore_points(std::move(points));
    }
    stresses_stale_ = false;
    revert_to_committed();
}

} // namespace grainload::fem
