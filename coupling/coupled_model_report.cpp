// CoupledModel's io::Reporter side: the model statement and hints, the frames' blocks, the
// figures of summary.json, the logs. Its stepping is in coupled_model.cpp.
#include "coupling/coupled_model.hpp"
#include "coupling/window_limits.hpp"

#include <cmath>
#include <sstream>

namespace grainload::coupling {

void CoupledModel::describe_model(std::vector<io::ModelChoice>& choices) const {
    sph_->describe_model(choices);
    for (const CoupledPart& part : parts_) {
        for (io::ModelChoice& choice : choices) {
            if (choice.item == "wall " + part.name) {
                choice.choice = "elastic shell, coupled";
            }
        }
    }
    for (const fem::ShellPart& part : fem_->analysis().parts()) {
        choices.push_back(
            {"shell " + part.name,
             std::string(part.material->model()) +
                 (parts_.empty() ? ", not loaded by the sand (rigid interfaces)" : "")});
    }
    choices.push_back({"coupling", settings_.max_iterations > 1 ? "iterated" : "staggered"});
}

void CoupledModel::append_hints(std::vector<std::string>& hints) const {
    sph_->append_hints(hints);
    if (!parts_.empty()) {
        std::string names;
        for (const CoupledPart& part : parts_) {
            names += (names.empty() ? "" : ", ") + part.name;
        }
        append_shell_hints(extremes_, *fem_, names, sph_->spacing(), hints);
    }
    append_rigid_interface_hints(rigid_interfaces_, parts_.empty(), *fem_, hints);
}

void CoupledModel::append_blocks(io::Frame& frame) const {
    sph_->append_blocks(frame);
    if (parts_.empty()) {
        // Every interface rigid: the shell carries its own loads only, and the sand's pressure
        // is on the rigid walls ([[sph.wall_map]]), not on it.
        fem_->append_blocks(frame, {}, {}, "without_sand_");
        return;
    }
    pressure_.append_blocks(*fem_, load_, frame);
}

void CoupledModel::append_results(double t, std::vector<io::ResultFigure>& results) const {
    sph_->append_results(t, results);
    fem_->append_results(t, results);
    const double scale = sph_->solver()->energy_ledger().throughput();
    results.push_back({"coupling_windows",
                       static_cast<double>(monitor_.windows().size() + windows_before_restart_), "",
                       std::nullopt, ""});
    // A shell that no interface loads has no result stress or deflection to report: its own
    // loads' are in the frames, labelled (append_blocks), and the hints say so.
    if (!parts_.empty()) {
        results.push_back(
            {"shell_largest_deflection", extremes_.deflection, "m", std::nullopt, ""});
        results.push_back({"shell_largest_von_mises", extremes_.von_mises, "Pa", std::nullopt, ""});
    }
    results.push_back({"coupling_sand_work", monitor_.sand_work(), "J", std::nullopt, ""});
    results.push_back({"coupling_shell_work", monitor_.shell_work(), "J", std::nullopt, ""});
    results.push_back(
        {"coupling_energy_error", monitor_.relative_energy_error(scale), "", std::nullopt, ""});
    results.push_back({"coupling_energy_created", monitor_.relative_created_energy(scale), "",
                       std::nullopt,
                       "energy the interface created since its error was largest, relative "
                       "(the watchdog's measure)"});
    results.push_back({"coupling_window_limit", window_limit(), "s", std::nullopt,
                       fem_->dynamic()
                           ? "staggered, dynamic shell: longest stable window (estimate)"
                           : "staggered, static shell: shortest stable window (estimate)"});
    if (added_mass_lag_ > 0.0) {
        results.push_back({"coupling_added_mass_lag", added_mass_lag_, "s", std::nullopt,
                           "static shell with the added mass: time to follow a load change"});
    }
    results.push_back({"coupling_largest_subcycles",
                       static_cast<double>(monitor_.largest_subcycles()), "", std::nullopt, ""});
    // The run's `steps` count windows; the SPH steps behind them (every pass of an iterated
    // window) are these.
    results.push_back(
        {"coupling_sph_steps", static_cast<double>(monitor_.subcycles()), "", std::nullopt, ""});
    const Vec3 load = load_resultant(load_);
    const Vec3 momentum = sph_->solver()->linear_momentum();
    for (int a = 0; a < 3; ++a) {
        // The impulse balance of the exchange: what the sand put into the coupled walls (SPH
        // side, trapezoidal like the leapfrog's own momentum update) and what the shell
        // received (the applied loads times the windows), with the sand's momentum.
        append_interface_figures(a, load, monitor_, results);
        const std::string axis(1, static_cast<char>('x' + a));
        results.push_back({"sand_momentum_" + axis, momentum[a], "kg m/s", std::nullopt, ""});
    }
    results.push_back({"shell_kinetic_energy", fem_->kinetic_energy(), "J", std::nullopt, ""});
    results.push_back({"shell_strain_energy", fem_->strain_energy(), "J", std::nullopt, ""});
}

void CoupledModel::write_logs() const {
    sph_->write_logs();
    fem_->write_logs();
    if (output_ != nullptr) {
        monitor_.write_csv(*output_);
    }
}

void CoupledModel::set_output(io::OutputStreams& output) {
    output_ = &output;
    sph_->set_output(output);
    fem_->set_output(output);
}

} // namespace grainload::coupling
