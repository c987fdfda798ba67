#include "coupling/model_hints.hpp"

#include "materials/von_mises.hpp"

#include <algorithm>
#include <cstdio>

namespace grainload::coupling {

namespace {

/// Below this share of the spacing a wall's deflection cannot change which particles touch it
/// or how far they are: the contact force changes over a spacing (thesis eq. 5.3.12), so a
/// hundredth of it is a percent-level change of the wall's position as the sand sees it.
constexpr double kNegligibleDeflection = 0.01;

template <class... Numbers> std::string format(const char* pattern, Numbers... numbers) {
    char text[200];
    std::snprintf(text, sizeof text, pattern, numbers...);
    return text;
}

} // namespace

void ShellExtremes::add_deflection(const fem::ShellAnalysis& analysis,
                                   const std::vector<Index>& elements) {
    const fem::ShellMesh& mesh = analysis.mesh();
    for (const Index e : elements) {
        for (const Index node : mesh.elements()[static_cast<std::size_t>(e)].nodes) {
            deflection = std::max(deflection, analysis.displacement(node).norm());
        }
    }
}

void ShellExtremes::add_stress(const fem::ShellAnalysis& analysis) {
    // Every element, not only the coupled ones: the frames, posts and beams that carry the
    // walls' load (a wagon's door posts) are where the structure's peak stress may sit.
    for (const fem::Mitc4Shell& element : analysis.elements()) {
        const fem::ShellResultants r = element.resultants();
        von_mises = std::max({von_mises, r.von_mises_top, r.von_mises_middle, r.von_mises_bottom});
    }
}

void append_shell_hints(const ShellExtremes& extremes, const fem::ShellModel& fem,
                        const std::string& names, double spacing, std::vector<std::string>& hints) {
    const fem::ShellAnalysis& analysis = fem.analysis();
    if (analysis.prescribes_motion()) {
        hints.push_back("shell (" + names +
                        "): its supports prescribe a motion, so its deflection is not compared "
                        "with the particle spacing");
    } else {
        const double ratio = extremes.deflection / spacing;
        hints.push_back(format(ratio < kNegligibleDeflection
                                   ? "shell (%s): largest deflection %.3g m, %.3g of the particle "
                                     "spacing %.3g m: rigid walls would give the same loads"
                                   : "shell (%s): largest deflection %.3g m, %.3g of the particle "
                                     "spacing %.3g m: the wall's compliance matters",
                               names.c_str(), extremes.deflection, ratio, spacing));
    }
    double yield = 0.0;
    for (const fem::ShellPart& part : analysis.parts()) {
        if (const auto* plastic = dynamic_cast<const materials::VonMises*>(part.material)) {
            yield =
                yield == 0.0 ? plastic->yield_stress() : std::min(yield, plastic->yield_stress());
        }
    }
    if (yield > 0.0) {
        const double ratio = extremes.von_mises / yield;
        hints.push_back(
            format(ratio < 1.0 ? "shell (%s): largest von Mises stress %.3g Pa, %.3g of the lowest "
                                 "yield stress %.3g Pa: linear elastic parts would do"
                               : "shell (%s): largest von Mises stress %.3g Pa, %.3g of the lowest "
                                 "yield stress %.3g Pa: the shell yields",
                   names.c_str(), extremes.von_mises, ratio, yield));
    } else {
        hints.push_back(
            format("shell (%s): largest von Mises stress %.3g Pa (linear elastic parts: "
                   "compare it with the material's yield stress)",
                   names.c_str(), extremes.von_mises));
    }
}

void append_rigid_interface_hints(const std::vector<std::string>& rigid, bool all_rigid,
                                  const fem::ShellModel& fem, std::vector<std::string>& hints) {
    if (rigid.empty()) {
        return;
    }
    std::string names;
    std::string forces;
    for (const std::string& name : rigid) {
        names += (names.empty() ? "" : ", ") + name;
        forces += (forces.empty() ? "wall_" : ", wall_") + name + "_force_*";
    }
    if (all_rigid) {
        std::string parts;
        for (const std::string& part : fem.part_names()) {
            parts += (parts.empty() ? "" : ", ") + part;
        }
        hints.push_back("shell (" + parts + "): rigid: self-weight only: every interface (" +
                        names +
                        ") is a rigid wall, so the sand's load is not in the shell's stresses "
                        "and deflections; the frames carry its own loads' as without_sand_*, "
                        "summary.json no shell stress or deflection; the sand's load on the "
                        "walls is " +
                        forces + " (rigid = false couples them)");
        return;
    }
    hints.push_back("interface (" + names + "): rigid: the sand's load on it is " + forces +
                    ", not in the shell's stresses and deflections");
}

} // namespace grainload::coupling
