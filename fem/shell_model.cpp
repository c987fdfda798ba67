#include "fem/shell_model.hpp"

#include "io/binary_stream.hpp"
#include "io/output_streams.hpp"

#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace grainload::fem {

namespace {

/// Result names are snake_case identifiers, as the SPH side's: a solver is named by the
/// first word of SparseSolver::name() in lower case ("cholmod", "umfpack").
std::string solver_identifier(const std::string& solver) {
    std::string id = solver.substr(0, solver.find(' '));
    for (char& c : id) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return id;
}

} // namespace

ShellModel::ShellModel(const ShellModelSettings& settings, std::unique_ptr<ShellAnalysis> analysis,
                       std::vector<std::string> part_names, std::vector<ShellMonitor> monitors,
                       std::vector<ShellReaction> support_reactions)
    : part_names_(std::move(part_names)), analysis_(std::move(analysis)),
      monitors_(std::move(monitors)), support_reactions_(std::move(support_reactions)),
      settings_(settings.newton), load_time_(settings.load_time), dynamic_(settings.dynamic),
      time_step_(settings.time_step), increments_per_step_(settings.increments_per_step) {
    // Advanced step after step, a linear shell's stiffness is worth keeping: every later step's
    // internal forces come from it (a coupled window's cost was the element loop).
    analysis_->store_stiffness();
    // The analysis' load factor is the time: history 0 (loads without a time_function) ramps
    // to 1 at load_time and holds.
    const double load_time = load_time_;
    analysis_->set_history(0, [load_time](double t) { return std::min(t / load_time, 1.0); });
    reactions_ = Eigen::VectorXd::Zero(6 * analysis_->mesh().node_count());
    if (dynamic_) {
        const double gamma = settings.integrator_gamma;
        // beta = (gamma + 1/2)^2 / 4: unconditionally stable, the trapezoidal rule at 1/2;
        // for HHT this is (1 - alpha)^2 / 4.
        newmark_ =
            std::make_unique<NewmarkIntegrator>(*analysis_, 0.25 * (gamma + 0.5) * (gamma + 0.5),
                                                gamma, settings.integrator_alpha, settings.mass);
        newmark_->initialise(Eigen::VectorXd::Zero(6 * analysis_->mesh().node_count()));
    }
}

double ShellModel::stable_time_step() const {
    // Implicit solution: no stability limit; a dynamic analysis asks for its accuracy step.
    return dynamic_ ? time_step_ : std::numeric_limits<double>::infinity();
}

void ShellModel::advance(double t, double dt) {
    if (failure_) {
        return;
    }
    if (!dynamic_ && !analysis_->loads_change(analysis_->load_factor(), t + dt)) {
        analysis_->set_load_factor(t + dt); // nothing to solve: every history is constant
        return;
    }
    solve_step(t, dt);
}

void ShellModel::advance_with_forces(double t, double dt, const Eigen::VectorXd& forces) {
    if (failure_) {
        return;
    }
    analysis_->set_additional_forces(forces);
    solve_step(t, dt);
}

void ShellModel::restore_forces(const Eigen::VectorXd& forces) {
    analysis_->set_additional_forces(forces);
    reactions_ = analysis_->reactions();
}

double ShellModel::kinetic_energy() const {
    return dynamic_ ? newmark_->kinetic_energy() : 0.0;
}

double ShellModel::strain_energy() const {
    // Undeformed (as when a scene is built and its figures listed): no energy, and no
    // assembly of every element to find it.
    if (analysis_->dofs().isZero(0.0)) {
        return 0.0;
    }
    // Assembling touches the elements' trial states, which the committed state restores.
    Eigen::VectorXd internal;
    analysis_->assemble(nullptr, internal);
    analysis_->revert_to_committed();
    return 0.5 * analysis_->dofs().dot(internal);
}

void ShellModel::solve_step(double t, double dt) {
    const double target = t + dt;
    ShellStepLog entry;
    entry.time = t + dt;
    entry.report = dynamic_ ? newmark_->step(dt, target, settings_)
                            : analysis_->advance_load(target, increments_per_step_, settings_);
    entry.load_factor = analysis_->history_value(0, analysis_->load_factor());
    if (!entry.report.converged) {
        std::ostringstream why;
        why << "shell structure (" << part_list()
            << "): Newton-Raphson did not converge at t = " << target << " s after "
            << entry.report.cutbacks
            << " cut-backs; last converged t = " << analysis_->load_factor() << " s (load factor "
            << entry.load_factor << ")";
        if (const Index dof = entry.report.worst_dof; dof >= 0) {
            why << "; largest out-of-balance force at " << dof_name(dof) << " (part "
                << part_of_node(dof / 6) << "): " << entry.report.worst_residual
                << (dof % 6 < 3 ? " N" : " N m");
        }
        failure_ = why.str();
    }
    totals_.add(entry.load_factor, entry.report);
    factorisations_ += entry.report.factorisations;
    back_substitutions_ += entry.report.back_substitutions;
    log_.push_back(std::move(entry));
    reactions_ = analysis_->reactions();
}

std::optional<std::string> ShellModel::diagnose() const {
    if (failure_) {
        return failure_;
    }
    for (Index n = 0; n < analysis_->mesh().node_count(); ++n) {
        if (!analysis_->displacement(n).allFinite()) {
            return "shell node " + std::to_string(n) + " (part " + part_of_node(n) +
                   "): displacement is not finite";
        }
    }
    return std::nullopt;
}

std::string ShellModel::part_list() const {
    std::string list;
    for (const std::string& name : part_names_) {
        list += (list.empty() ? "" : ", ") + name;
    }
    return list;
}

std::string ShellModel::part_of_node(Index node) const {
    for (const ShellElement& element : analysis_->mesh().elements()) {
        for (const Index n : element.nodes) {
            if (n == node) {
                return part_names_[static_cast<std::size_t>(element.part)];
            }
        }
    }
    return "none";
}

void ShellModel::append_blocks(io::Frame& frame) const {
    append_blocks(frame, {}, {});
}

void ShellModel::append_blocks(io::Frame& frame, const std::vector<io::FieldArray>& node_fields,
                               const std::vector<io::FieldArray>& element_fields,
                               const std::string& label) const {
    const ShellAnalysis& a = *analysis_;
    const ShellMesh& mesh = a.mesh();
    for (std::size_t part = 0; part < part_names_.size(); ++part) {
        // Each part is a block of its own: its elements and the nodes they use, renumbered.
        const std::vector<Index> elements = mesh.part_elements(static_cast<int>(part));
        std::vector<Index> local(static_cast<std::size_t>(mesh.node_count()), -1);
        std::vector<Index> nodes;
        for (const Index e : elements) {
            for (const Index n : mesh.element(e).nodes) {
                if (local[static_cast<std::size_t>(n)] < 0) {
                    local[static_cast<std::size_t>(n)] = static_cast<Index>(nodes.size());
                    nodes.push_back(n);
                }
            }
        }
        io::Block block;
        block.name = part_names_[part];
        block.kind = io::Block::Kind::shell;
        append_node_fields(block, nodes, node_fields, label);
        for (const Index e : elements) {
            auto cell = mesh.element(e).nodes;
            for (Index& n : cell) {
                n = local[static_cast<std::size_t>(n)];
            }
            if (mesh.element(e).is_triangle()) {
                cell[3] = -1;
            }
            block.cells.push_back(cell);
        }
        append_element_fields(block, elements, element_fields, label);
        frame.blocks.push_back(std::move(block));
    }
}

namespace {

/// The entries of `field` (a value per node or element of the whole mesh) at `indices`.
io::FieldArray slice(const io::FieldArray& field, const std::vector<Index>& indices) {
    io::FieldArray part{field.name, field.components, {}};
    const auto c = static_cast<std::size_t>(field.components);
    for (const Index i : indices) {
        for (std::size_t k = 0; k < c; ++k) {
            part.values.push_back(field.values[c * static_cast<std::size_t>(i) + k]);
        }
    }
    return part;
}

} // namespace

void ShellModel::append_node_fields(io::Block& block, const std::vector<Index>& nodes,
                                    const std::vector<io::FieldArray>& extra,
                                    const std::string& label) const {
    const ShellAnalysis& a = *analysis_;
    io::FieldArray displacement{label + "displacement", 3, {}}, rotation{label + "rotation", 3, {}};
    io::FieldArray reaction{label + "reaction_force", 3, {}};
    io::FieldArray moment{label + "reaction_moment", 3, {}};
    for (const Index n : nodes) {
        const Vec3 u = a.displacement(n);
        const Vec3 r = a.rotation(n);
        block.points.push_back(a.mesh().node(n) + u);
        displacement.values.insert(displacement.values.end(), u.begin(), u.end());
        rotation.values.insert(rotation.values.end(), r.begin(), r.end());
        for (int d = 0; d < 3; ++d) {
            reaction.values.push_back(reactions_(6 * n + d));
            moment.values.push_back(reactions_(6 * n + 3 + d));
        }
    }
    block.point_arrays = {displacement, rotation, reaction, moment};
    for (const io::FieldArray& field : extra) {
        block.point_arrays.push_back(slice(field, nodes));
    }
}

void ShellModel::append_element_fields(io::Block& block, const std::vector<Index>& elements,
                                       const std::vector<io::FieldArray>& extra,
                                       const std::string& label) const {
    const ShellAnalysis& a = *analysis_;
    io::FieldArray membrane{label + "membrane_force", 3, {}};
    io::FieldArray bending{label + "bending_moment", 3, {}};
    io::FieldArray top{label + "von_mises_top", 1, {}}, middle{label + "von_mises_middle", 1, {}};
    io::FieldArray bottom{label + "von_mises_bottom", 1, {}};
    io::FieldArray plastic{label + "plastic_strain", 1, {}};
    io::FieldArray thickness{"thickness", 1, {}};
    for (const Index e : elements) {
        const ShellResultants r = a.elements()[static_cast<std::size_t>(e)].resultants();
        membrane.values.insert(membrane.values.end(), r.membrane.begin(), r.membrane.end());
        bending.values.insert(bending.values.end(), r.bending.begin(), r.bending.end());
        top.values.push_back(r.von_mises_top);
        middle.values.push_back(r.von_mises_middle);
        bottom.values.push_back(r.von_mises_bottom);
        plastic.values.push_back(r.plastic_strain);
        thickness.values.push_back(a.mesh().element(e).thickness);
    }
    block.cell_arrays = {membrane, bending, top, middle, bottom, plastic, thickness};
    for (const io::FieldArray& field : extra) {
        block.cell_arrays.push_back(slice(field, elements));
    }
}

void ShellModel::append_results(double, std::vector<io::ResultFigure>& results) const {
    for (const ShellReaction& r : support_reactions_) {
        Vec3 sum = Vec3::Zero();
        for (const Index n : r.nodes) {
            sum += reactions_.segment<3>(6 * n);
        }
        for (int a = 0; a < 3; ++a) {
            results.push_back({r.name + "_" + std::string(1, static_cast<char>('x' + a)), sum[a],
                               "N", std::nullopt, ""});
        }
    }
    for (const ShellMonitor& m : monitors_) {
        const double value = m.dof < 3 ? analysis_->displacement(m.node)(m.dof)
                                       : analysis_->rotation(m.node)(m.dof - 3);
        io::ResultFigure figure;
        figure.name = m.name;
        figure.value = m.magnitude ? std::abs(value) : value;
        figure.unit = m.dof < 3 ? "m" : "rad";
        figure.reference = m.reference;
        figure.source = m.source;
        results.push_back(figure);
    }
    if (totals_.any) {
        results.push_back({"fem_load_factor", totals_.last_load_factor, "", std::nullopt, ""});
        results.push_back({"fem_newton_iterations_last_step",
                           static_cast<double>(totals_.last_iterations), "", std::nullopt,
                           totals_.last_solver});
        // Which factorisation ran: steps whose last solve went through each solver.
        for (const auto& [solver, steps] : totals_.steps_by_solver) {
            results.push_back({"fem_steps_solved_by_" + solver_identifier(solver),
                               static_cast<double>(steps), "", std::nullopt, solver});
        }
        // What the steps cost: a factorisation of the tangent (a linear shell makes one and
        // keeps it) and a back-substitution per Newton iteration, in this process.
        results.push_back({"fem_factorisations", factorisations_, "", std::nullopt,
                           "factorisations of the tangent this process made"});
        results.push_back({"fem_back_substitutions", back_substitutions_, "", std::nullopt,
                           "solves with a factorisation this process made"});
    }
    // Every support's force on the structure, each node once: the parts' reactions on node sets
    // count a seam node shared by two parts in both.
    Vec3 total = Vec3::Zero();
    for (Eigen::Index n = 0; n + 5 < reactions_.size(); n += 6) {
        total += reactions_.segment<3>(n);
    }
    for (int a = 0; a < 3; ++a) {
        results.push_back({"support_reaction_" + std::string(1, static_cast<char>('x' + a)),
                           total[a], "N", std::nullopt, "all supports, each node once"});
    }
}

void ShellModel::write_logs() const {
    // Appends the steps since the last call (a restarted run's in-memory log begins at the
    // checkpoint, where its stream continues).
    if (output_ == nullptr) {
        return;
    }
    std::ostringstream csv;
    csv.precision(10);
    for (; logged_steps_ < log_.size(); ++logged_steps_) {
        const ShellStepLog& entry = log_[logged_steps_];
        std::size_t row = 0;
        for (std::size_t inc = 0; inc < entry.report.iterations.size(); ++inc) {
            for (int i = 0; i < entry.report.iterations[inc] && row < entry.report.log.size();
                 ++i, ++row) {
                const NewtonIteration& it = entry.report.log[row];
                csv << entry.time << ',' << inc + 1 << ',' << it.iteration << ','
                    << it.displacement_ratio << ',' << it.force_ratio << ',' << it.energy_ratio
                    << ',' << it.residual_norm << ",\"" << entry.report.solver << "\"\n";
            }
        }
    }
    output_
        ->open("fem_convergence.csv", "time,increment,iteration,displacement_ratio,force_ratio,"
                                      "energy_ratio,residual_norm,solver\n")
        .append(csv.str());
}

void ShellModel::write_checkpoint(std::ostream& out) const {
    analysis_->write_state(out);
    totals_.write(out);
    if (dynamic_) {
        const auto& v = newmark_->velocity();
        const auto& a = newmark_->acceleration();
        io::write_array(out, std::vector<double>(v.begin(), v.end()));
        io::write_array(out, std::vector<double>(a.begin(), a.end()));
    }
}

void ShellModel::read_checkpoint(std::istream& in) {
    analysis_->read_state(in);
    totals_.read(in);
    if (dynamic_) {
        std::vector<double> v, a;
        const auto dofs = static_cast<std::size_t>(newmark_->velocity().size());
        io::read_array(in, v, dofs, "shell velocities");
        io::read_array(in, a, dofs, "shell accelerations");
        const auto n = static_cast<Eigen::Index>(v.size());
        newmark_->restore(Eigen::Map<const Eigen::VectorXd>(v.data(), n),
                          Eigen::Map<const Eigen::VectorXd>(a.data(), n));
    }
    failure_.reset();
    reactions_ = analysis_->reactions();
}

} // namespace grainload::fem
