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

} // namespace grainload::coupling
