#include "sph/sph_model.hpp"

#include "io/binary_stream.hpp"
#include "io/case_table.hpp"
#include "sph/body_generator.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace grainload::sph {

namespace dim = io::dimension;

std::unique_ptr<SphModel> SphModel::from_case(const io::CaseTable& root,
                                              const materials::MaterialLibrary& materials) {
    std::unique_ptr<SphModel> model(new SphModel(materials));
    const io::CaseTable sph = root.table("sph");
    model->gravity_ =
        root.table("case").vector_or("gravity", dim::kAcceleration, Vec3(0.0, 0.0, -9.81));
    model->time_step_ = sph.positive_quantity_or("time_step", dim::kTime, 0.0);
    model->interactions_ = sph.boolean_or("interactions", true);
    if (model->interactions_) {
        sph.fail("interactions", "particle interactions are not in this build yet; "
                                 "expected interactions = false");
    }
    if (!model->interactions_ && model->time_step_ == 0.0) {
        sph.fail("time_step", "free flight (interactions = false) has no CFL limit: expected a "
                              "fixed time_step, e.g. \"1 ms\"");
    }
    const auto bodies = sph.array_of_tables("body");
    if (bodies.empty()) {
        sph.fail("", "expected at least one [[sph.body]]");
    }
    for (const auto& body : bodies) {
        model->add_body(body, root.spatial_dimension());
    }
    model->initial_position_ = model->particles_.position;
    model->initial_velocity_ = model->particles_.velocity;
    model->compute_accelerations();
    return model;
}

void SphModel::add_body(const io::CaseTable& body, int dimension) {
    std::string name = body.string("name");
    for (const auto& existing : body_names_) {
        if (existing == name) {
            body.fail("name", "a body called \"" + name + "\" is already defined");
        }
    }
    const int material = materials_->index_of(body, "material");
    const double spacing = body.positive_quantity("spacing", dim::kLength);
    const Vec3 velocity = body.vector_or("velocity", dim::kVelocity, Vec3::Zero());
    const auto points = generate_body_points(body.table("shape"), spacing, dimension);
    const auto& law = (*materials_)[material];
    const double particle_mass = law.density() * std::pow(spacing, dimension);
    const int body_index = static_cast<int>(body_names_.size());
    for (const Vec3& x : points) {
        particles_.add(x, velocity, particle_mass, law.density(), body_index, material,
                       law.state_size());
        const Index i = particles_.size() - 1;
        auto state = std::span(particles_.state)
                         .subspan(static_cast<std::size_t>(
                                      particles_.state_offset[static_cast<std::size_t>(i)]),
                                  static_cast<std::size_t>(law.state_size()));
        law.initialise_state(state);
    }
    body_names_.push_back(std::move(name));
}

double SphModel::stable_time_step() const {
    return time_step_ > 0.0 ? time_step_ : std::numeric_limits<double>::infinity();
}

void SphModel::compute_accelerations() {
    const auto n = static_cast<std::size_t>(particles_.size());
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        particles_.acceleration[i] = gravity_;
    }
}

void SphModel::advance(double, double dt) {
    // Velocity Verlet (kick-drift-kick): second order, and exact for a constant acceleration,
    // which the free-fall case checks to round-off.
    const auto n = static_cast<std::size_t>(particles_.size());
    auto& p = particles_;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        p.velocity[i] += 0.5 * dt * p.acceleration[i];
        p.position[i] += dt * p.velocity[i];
    }
    compute_accelerations();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        p.velocity[i] += 0.5 * dt * p.acceleration[i];
    }
}

std::optional<std::string> SphModel::diagnose() const {
    const auto& p = particles_;
    for (std::size_t i = 0; i < p.position.size(); ++i) {
        const char* bad = !p.position[i].allFinite()                            ? "position"
                          : !p.velocity[i].allFinite()                          ? "velocity"
                          : !p.stress[i].allFinite()                            ? "stress"
                          : !std::isfinite(p.density[i]) || p.density[i] <= 0.0 ? "density"
                                                                                : nullptr;
        if (bad != nullptr) {
            std::ostringstream out;
            out << "particle " << i << " (body "
                << body_names_[static_cast<std::size_t>(p.body_id[i])]
                << ") has a non-finite or non-physical " << bad;
            return out.str();
        }
    }
    return std::nullopt;
}

namespace {

double pressure_of(const Voigt6& s) {
    return -(s[0] + s[1] + s[2]) / 3.0;
}

double von_mises_of(const Voigt6& s) {
    const double p = (s[0] + s[1] + s[2]) / 3.0;
    const double dev = (s[0] - p) * (s[0] - p) + (s[1] - p) * (s[1] - p) + (s[2] - p) * (s[2] - p) +
                       2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    return std::sqrt(1.5 * dev);
}

} // namespace

void SphModel::append_blocks(io::Frame& frame) const {
    const auto& p = particles_;
    for (std::size_t b = 0; b < body_names_.size(); ++b) {
        io::Block block;
        block.name = body_names_[b];
        io::FieldArray velocity{"velocity", 3, {}}, displacement{"displacement", 3, {}};
        io::FieldArray stress{"stress", 6, {}}, pressure{"pressure", 1, {}};
        io::FieldArray von_mises{"von_mises", 1, {}}, plastic{"plastic_strain", 1, {}};
        io::FieldArray density{"density", 1, {}}, body{"body_id", 1, {}};
        io::FieldArray material{"material_id", 1, {}};
        for (std::size_t i = 0; i < p.position.size(); ++i) {
            if (p.body_id[i] != static_cast<int>(b)) {
                continue;
            }
            block.points.push_back(p.position[i]);
            const Vec3 u = p.position[i] - initial_position_[i];
            velocity.values.insert(velocity.values.end(), p.velocity[i].begin(),
                                   p.velocity[i].end());
            displacement.values.insert(displacement.values.end(), u.begin(), u.end());
            stress.values.insert(stress.values.end(), p.stress[i].begin(), p.stress[i].end());
            pressure.values.push_back(pressure_of(p.stress[i]));
            von_mises.values.push_back(von_mises_of(p.stress[i]));
            plastic.values.push_back(p.plastic_strain[i]);
            density.values.push_back(p.density[i]);
            body.values.push_back(p.body_id[i]);
            material.values.push_back(p.material_id[i]);
        }
        block.point_arrays = {velocity, displacement, stress, pressure, von_mises,
                              plastic,  density,      body,   material};
        frame.blocks.push_back(std::move(block));
    }
}

void SphModel::append_results(double t, std::vector<io::ResultFigure>& results) const {
    if (interactions_) {
        return;
    }
    // Without interactions every particle is a point mass in uniform gravity: its exact path is
    // x0 + v0 t + g t^2 / 2, the reference for the whole pipeline (case free_fall).
    double max_error = 0.0;
    double mean_z = 0.0;
    double mean_z_exact = 0.0;
    const auto n = particles_.position.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 exact = initial_position_[i] + t * initial_velocity_[i] + 0.5 * t * t * gravity_;
        max_error = std::max(max_error, (particles_.position[i] - exact).norm());
        mean_z += particles_.position[i].z() / static_cast<double>(n);
        mean_z_exact += exact.z() / static_cast<double>(n);
    }
    results.push_back({"centre_height", mean_z, "m", mean_z_exact, "z0 + v0 t + g t^2/2"});
    results.push_back({"max_position_error", max_error, "m", std::nullopt, ""});
}

void SphModel::write_checkpoint(std::ostream& out) const {
    const auto& p = particles_;
    io::write_array(out, p.position);
    io::write_array(out, p.velocity);
    io::write_array(out, p.acceleration);
    io::write_array(out, p.density);
    io::write_array(out, p.internal_energy);
    io::write_array(out, p.stress);
    io::write_array(out, p.plastic_strain);
    io::write_array(out, p.state);
}

void SphModel::read_checkpoint(std::istream& in) {
    auto& p = particles_;
    const auto n = p.position.size();
    io::read_array(in, p.position);
    io::read_array(in, p.velocity);
    io::read_array(in, p.acceleration);
    io::read_array(in, p.density);
    io::read_array(in, p.internal_energy);
    io::read_array(in, p.stress);
    io::read_array(in, p.plastic_strain);
    io::read_array(in, p.state);
    if (p.position.size() != n) {
        throw std::runtime_error("checkpoint holds " + std::to_string(p.position.size()) +
                                 " particles, the case makes " + std::to_string(n));
    }
}

} // namespace grainload::sph
