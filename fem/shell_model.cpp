#include "fem/shell_model.hpp"

#include "fem/time_function.hpp"
#include "io/binary_stream.hpp"
#include "io/case_table.hpp"
#include "io/output_streams.hpp"

#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace grainload::fem {

namespace dim = io::dimension;

namespace {

/// The declared default of a [fem] key, at compile time.
constexpr double declared(std::string_view key) {
    for (const io::KeySpec& spec : kFemKeys) {
        if (spec.name == key) {
            return spec.value;
        }
    }
    throw std::logic_error("undeclared [fem] key");
}

// NewtonSettings' own defaults (for analyses built without a case) are the declared ones.
constexpr NewtonSettings kNewtonDefaults{};
static_assert(kNewtonDefaults.displacement_tolerance == declared("displacement_tolerance"));
static_assert(kNewtonDefaults.force_tolerance == declared("force_tolerance"));
static_assert(kNewtonDefaults.energy_tolerance == declared("energy_tolerance"));
static_assert(kNewtonDefaults.max_iterations == declared("max_iterations"));
static_assert(kNewtonDefaults.max_cutbacks == declared("max_cutbacks"));

/// The declared default of a [fem] key.
double fallback(std::string_view key) {
    return io::default_value(kFemKeys, key);
}

std::int64_t integer_fallback(std::string_view key) {
    return static_cast<std::int64_t>(fallback(key));
}

NewtonSettings read_settings(const io::CaseTable& fem) {
    NewtonSettings s;
    s.displacement_tolerance =
        fem.number_or("displacement_tolerance", fallback("displacement_tolerance"));
    s.force_tolerance = fem.number_or("force_tolerance", fallback("force_tolerance"));
    s.energy_tolerance = fem.number_or("energy_tolerance", fallback("energy_tolerance"));
    s.max_iterations =
        static_cast<int>(fem.integer_or("max_iterations", integer_fallback("max_iterations")));
    s.max_cutbacks =
        static_cast<int>(fem.integer_or("max_cutbacks", integer_fallback("max_cutbacks")));
    return s;
}

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

std::unique_ptr<ShellModel> ShellModel::from_case(const io::CaseTable& root,
                                                  const io::SceneSettings& scene,
                                                  const materials::MaterialLibrary& materials) {
    const io::CaseTable fem = root.table("fem");
    std::unique_ptr<ShellModel> model(new ShellModel());
    model->dynamic_ = fem.choice_or("analysis", {"static", "dynamic"}, "static") == "dynamic";
    if (model->dynamic_) {
        model->time_step_ = fem.positive_quantity("time_step", dim::kTime);
    }
    const std::string kinematics =
        fem.choice_or("kinematics", {"linear", "total_lagrangian"}, "linear");
    model->settings_ = read_settings(fem);
    model->load_time_ = fem.positive_quantity_or("load_time", dim::kTime, scene.end_time);
    model->increments_per_step_ = static_cast<int>(
        fem.integer_or("increments_per_step", integer_fallback("increments_per_step")));
    const std::vector<io::CaseTable> shells = fem.array_of_tables("shell");
    if (shells.empty()) {
        fem.fail("shell", "expected at least one [[fem.shell]] table");
    }
    auto [mesh, parts] = read_shell_parts(fem, shells, materials);
    for (const ShellPart& part : parts) {
        model->part_names_.push_back(part.name);
    }
    model->analysis_ = std::make_unique<ShellAnalysis>(
        std::move(mesh), std::move(parts),
        kinematics == "linear" ? Kinematics::linear : Kinematics::total_lagrangian);
    // Advanced step after step, a linear shell's stiffness is worth keeping: every later step's
    // internal forces come from it (a coupled window's cost was the element loop).
    model->analysis_->store_stiffness();
    // The analysis' load factor is the time: history 0 (loads without a time_function) ramps
    // to 1 at load_time and holds; every [[fem.time_function]] becomes a history of its own.
    const double load_time = model->load_time_;
    model->analysis_->set_history(0,
                                  [load_time](double t) { return std::min(t / load_time, 1.0); });
    std::map<std::string, int> histories;
    for (auto& [name, function] : read_time_functions(fem)) {
        histories[name] = model->analysis_->add_history(function);
    }
    for (std::size_t k = 0; k < shells.size(); ++k) {
        const PartScope scope{static_cast<int>(k), model->part_names_[k]};
        read_shell_boundaries(shells[k], histories, scope, *model->analysis_);
        read_shell_loads(shells[k], scene.gravity, histories, scope, *model->analysis_);
        for (ShellMonitor& monitor : read_shell_monitors(shells[k], model->analysis_->mesh())) {
            model->monitors_.push_back(std::move(monitor));
        }
        for (ShellReaction& reaction :
             read_shell_reactions(shells[k], model->analysis_->mesh(), scope)) {
            model->support_reactions_.push_back(std::move(reaction));
        }
    }
    model->reactions_ = Eigen::VectorXd::Zero(6 * model->analysis_->mesh().node_count());
    if (model->dynamic_) {
        const bool hht = fem.choice_or("integrator", {"newmark", "hht"}, "newmark") == "hht";
        double alpha = 0.0;
        double gamma = 0.5;
        if (hht) {
            alpha = fem.number_or("hht_alpha", fallback("hht_alpha"));
            if (alpha < -1.0 / 3.0 || alpha > 0.0) {
                fem.fail("hht_alpha", "expected -1/3 <= alpha <= 0");
            }
            gamma = 0.5 - alpha; // Hilber, Hughes & Taylor 1977: second order
        } else {
            gamma = fem.number_or("newmark_gamma", fallback("newmark_gamma"));
            if (gamma < 0.5) {
                fem.fail("newmark_gamma", "expected gamma >= 0.5 (unconditional stability)");
            }
        }
        // beta = (gamma + 1/2)^2 / 4: unconditionally stable, the trapezoidal rule at 1/2;
        // for HHT this is (1 - alpha)^2 / 4.
        const bool consistent =
            fem.choice_or("mass", {"lumped", "consistent"}, "lumped") == "consistent";
        model->newmark_ = std::make_unique<NewmarkIntegrator>(
            *model->analysis_, 0.25 * (gamma + 0.5) * (gamma + 0.5), gamma, alpha,
            consistent ? MassMatrix::consistent : MassMatrix::lumped);
        model->newmark_->initialise(
            Eigen::VectorXd::Zero(6 * model->analysis_->mesh().node_count()));
    }
    return model;
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
