// DemCoupledModel's io::Reporter side: the model statement and hints, the frames' blocks, the
// figures of summary.json, the logs. Its stepping is in dem_coupled_model.cpp.
#include "coupling/dem_coupled_model.hpp"

#include <string>

namespace grainload::coupling {

void DemCoupledModel::describe_model(std::vector<io::ModelChoice>& choices) const {
    dem_->describe_model(choices);
    for (const DemCoupledPart& part : parts_) {
        for (io::ModelChoice& choice : choices) {
            if (choice.item == "dem wall " + part.name) {
                choice.choice = "elastic shell, coupled: " + choice.choice;
            }
        }
    }
    for (const fem::ShellPart& part : fem_->analysis().parts()) {
        choices.push_back(
            {"shell " + part.name,
             std::string(part.material->model()) +
                 (parts_.empty() ? ", not loaded by the grains (rigid interfaces)" : "")});
    }
    choices.push_back(
        {"coupling", std::string(settings_.max_iterations > 1 ? "iterated" : "staggered") +
                         ", DEM sub-cycled"});
}

void DemCoupledModel::append_hints(std::vector<std::string>& hints) const {
    dem_->append_hints(hints);
    append_rigid_interface_hints(rigid_, parts_.empty(), *fem_, hints);
}

void DemCoupledModel::append_blocks(io::Frame& frame) const {
    dem_->append_blocks(frame);
    if (parts_.empty()) {
        fem_->append_blocks(frame, {}, {}, "without_sand_");
        return;
    }
    pressure_.append_blocks(*fem_, load_, frame);
}

void DemCoupledModel::append_results(double t, std::vector<io::ResultFigure>& results) const {
    dem_->append_results(t, results);
    fem_->append_results(t, results);
    results.push_back({"coupling_windows",
                       static_cast<double>(monitor_.windows().size() + windows_before_restart_), "",
                       std::nullopt, ""});
    if (!parts_.empty()) {
        results.push_back(
            {"shell_largest_deflection", extremes_.deflection, "m", std::nullopt, ""});
        results.push_back({"shell_largest_von_mises", extremes_.von_mises, "Pa", std::nullopt, ""});
    }
    results.push_back({"coupling_sand_work", monitor_.sand_work(), "J", std::nullopt,
                       "the grains' work on the coupled walls"});
    results.push_back({"coupling_shell_work", monitor_.shell_work(), "J", std::nullopt, ""});
    results.push_back({"coupling_energy_error", monitor_.relative_energy_error(energy_scale_), "",
                       std::nullopt, ""});
    results.push_back({"coupling_largest_subcycles",
                       static_cast<double>(monitor_.largest_subcycles()), "", std::nullopt, ""});
    // The run's `steps` count windows; the DEM steps behind them are these.
    results.push_back(
        {"coupling_dem_steps", static_cast<double>(monitor_.subcycles()), "", std::nullopt, ""});
    const Vec3 load = load_resultant(load_);
    for (int a = 0; a < 3; ++a) {
        append_interface_figures(a, load, monitor_, results);
    }
    results.push_back({"shell_kinetic_energy", fem_->kinetic_energy(), "J", std::nullopt, ""});
    results.push_back({"shell_strain_energy", fem_->strain_energy(), "J", std::nullopt, ""});
}

void DemCoupledModel::write_logs() const {
    dem_->write_logs();
    fem_->write_logs();
    if (output_ != nullptr) {
        monitor_.write_csv(*output_);
    }
}

void DemCoupledModel::set_output(io::OutputStreams& output) {
    output_ = &output;
    dem_->set_output(output);
    fem_->set_output(output);
}

} // namespace grainload::coupling
