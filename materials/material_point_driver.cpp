#include "materials/material_point_driver.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace grainload::materials {

namespace {

constexpr const char* kRegionNames[] = {"elastic", "failure_surface", "cap", "corner", "apex"};

/// Indices of the stress-controlled (unknown strain) components and of the others.
struct Partition {
    std::vector<int> unknown;
    std::vector<int> known;
};

Partition partition(const PathSegment& segment) {
    Partition p;
    for (int i = 0; i < 6; ++i) {
        (segment.stress_controlled[static_cast<std::size_t>(i)] ? p.unknown : p.known).push_back(i);
    }
    return p;
}

Eigen::MatrixXd block(const Matrix6& m, const std::vector<int>& rows,
                      const std::vector<int>& cols) {
    Eigen::MatrixXd b(rows.size(), cols.size());
    for (std::size_t r = 0; r < rows.size(); ++r) {
        for (std::size_t c = 0; c < cols.size(); ++c) {
            b(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = m(rows[r], cols[c]);
        }
    }
    return b;
}

Eigen::VectorXd pick(const Voigt6& v, const std::vector<int>& indices) {
    Eigen::VectorXd out(indices.size());
    for (std::size_t i = 0; i < indices.size(); ++i) {
        out(static_cast<Eigen::Index>(i)) = v(indices[i]);
    }
    return out;
}

/// Solve D_uu x = rhs, or nothing when the block is singular (e.g. a perfectly plastic limit).
std::optional<Eigen::VectorXd> solve_block(const Matrix6& tangent, const std::vector<int>& u,
                                           const Eigen::VectorXd& rhs) {
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(block(tangent, u, u));
    if (!lu.isInvertible()) {
        return std::nullopt;
    }
    return lu.solve(rhs);
}

struct StepResult {
    Voigt6 strain_increment;
    Voigt6 stress;
    std::vector<double> state;
    Matrix6 tangent;
    PlasticRegion region;
};

/// One step of mixed control: Newton on the unknown strain components, each iteration a fresh
/// update from the converged state of the previous step (so the answer is the exact solution of
/// the algorithmic problem, not an accumulation of iterates).
StepResult solve_step(const Material& material, const MaterialPointPath& path,
                      const MaterialPointRecord& start, const Partition& part,
                      const Voigt6& known_increment, const Voigt6& target,
                      const Matrix6& predictor_tangent, int step) {
    StepResult r{known_increment, start.stress, start.state, predictor_tangent,
                 PlasticRegion::elastic};
    const Eigen::VectorXd rhs =
        pick(target - start.stress, part.unknown) -
        block(predictor_tangent, part.unknown, part.known) * pick(known_increment, part.known);
    if (!part.unknown.empty()) {
        const auto guess = solve_block(predictor_tangent, part.unknown, rhs);
        for (std::size_t i = 0; i < part.unknown.size() && guess; ++i) {
            r.strain_increment(part.unknown[i]) = (*guess)(static_cast<Eigen::Index>(i));
        }
    }
    const double floor = 1e-6 * material.elastic().bulk_modulus;
    for (int iteration = 0; iteration <= path.max_iterations; ++iteration) {
        r.stress = start.stress;
        r.state = start.state;
        r.region = material.update(r.strain_increment, r.stress, r.state, &r.tangent);
        const Eigen::VectorXd residual = pick(r.stress - target, part.unknown);
        const double scale =
            std::max({r.stress.cwiseAbs().maxCoeff(), target.cwiseAbs().maxCoeff(), floor});
        if (residual.size() == 0 || residual.cwiseAbs().maxCoeff() <= path.tolerance * scale) {
            return r;
        }
        const auto correction = solve_block(r.tangent, part.unknown, residual);
        if (!correction) {
            throw std::runtime_error("step " + std::to_string(step) +
                                     ": the tangent is singular in the stress-controlled "
                                     "components (the prescribed stress is beyond the limit "
                                     "the material can carry)");
        }
        for (std::size_t i = 0; i < part.unknown.size(); ++i) {
            r.strain_increment(part.unknown[i]) -= (*correction)(static_cast<Eigen::Index>(i));
        }
    }
    throw std::runtime_error("step " + std::to_string(step) + ": Newton did not reach the " +
                             "prescribed stress in " + std::to_string(path.max_iterations) +
                             " iterations (the path may exceed the material's strength)");
}

} // namespace

void drive_material_point(const Material& material, const MaterialPointPath& path,
                          std::vector<MaterialPointRecord>& records) {
    MaterialPointRecord current;
    current.stress = path.initial_stress;
    current.state.assign(static_cast<std::size_t>(material.state_size()), 0.0);
    material.initialise_state(current.state);
    records.push_back(current);
    Matrix6 tangent = material.elastic().stiffness();
    for (const PathSegment& segment : path.segments) {
        const Partition part = partition(segment);
        const Voigt6 segment_start = current.stress;
        for (int i = 1; i <= segment.steps; ++i) {
            const double fraction = static_cast<double>(i) / segment.steps;
            Voigt6 target = current.stress;
            for (int u : part.unknown) {
                target(u) =
                    segment_start(u) + fraction * (segment.stress_target(u) - segment_start(u));
            }
            const Voigt6 known_increment = segment.strain_increment / segment.steps;
            const StepResult r = solve_step(material, path, current, part, known_increment, target,
                                            tangent, current.step + 1);
            current.step += 1;
            current.strain += r.strain_increment;
            current.stress = r.stress;
            current.state = r.state;
            current.region = r.region;
            tangent = r.tangent;
            records.push_back(current);
        }
    }
}

void write_material_point_csv(const Material& material,
                              const std::vector<MaterialPointRecord>& records, std::ostream& out) {
    const std::vector<std::string> names = material.state_names();
    const auto index_of = [&](const std::string& name) {
        const auto it = std::find(names.begin(), names.end(), name);
        return it == names.end() ? -1 : static_cast<int>(it - names.begin());
    };
    const int volumetric = index_of("plastic_volumetric_strain");
    const int cap = index_of("cap_position");
    out << "step";
    for (const char* prefix : {"strain_", "stress_"}) {
        for (const char* c : kVoigtComponents) {
            out << ',' << prefix << c;
        }
    }
    out << ",equivalent_plastic_strain,plastic_volumetric_strain,cap_position,region\n";
    out.precision(12);
    for (const MaterialPointRecord& r : records) {
        out << r.step;
        for (int i = 0; i < 6; ++i) {
            out << ',' << r.strain(i);
        }
        for (int i = 0; i < 6; ++i) {
            out << ',' << r.stress(i);
        }
        out << ',' << material.equivalent_plastic_strain(r.state) << ',';
        if (volumetric >= 0) {
            out << r.state[static_cast<std::size_t>(volumetric)];
        }
        out << ',';
        if (cap >= 0) {
            out << r.state[static_cast<std::size_t>(cap)];
        }
        out << ',' << kRegionNames[static_cast<int>(r.region)] << '\n';
    }
}

} // namespace grainload::materials
