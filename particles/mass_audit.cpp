#include "particles/mass_audit.hpp"

#include "io/binary_stream.hpp"

#include <stdexcept>

namespace grainload::particles {

double MassAudit::error(double scene_mass, double discharged, double initial, double created) {
    const double total = initial + created;
    return total > 0.0 ? (scene_mass + discharged - initial - created) / total : 0.0;
}

void MassAudit::append_results(std::vector<io::ResultFigure>& results) const {
    const std::string unit = dimension_ == 2 ? "kg/m" : "kg";
    const double scene = books_.scene_mass();
    const double discharged = books_.discharged();
    const double created = books_.created();
    results.push_back({"scene_mass", scene, unit, std::nullopt, "material in the scene"});
    results.push_back({"discharged_mass", discharged, unit, std::nullopt, ""});
    results.push_back({"initial_mass", initial_mass_, unit, std::nullopt, ""});
    results.push_back({"created_mass", created, unit, std::nullopt, ""});
    results.push_back({"mass_audit_error", error(scene, discharged, initial_mass_, created), "",
                       0.0, "mass in the scene + mass discharged = initial mass + mass created"});
}

void MassAudit::write_checkpoint(std::ostream& out) const {
    io::write_value(out, initial_mass_);
}

void MassAudit::read_checkpoint(std::istream& in) {
    initial_mass_ = io::read_value<double>(in);
}

} // namespace grainload::particles
