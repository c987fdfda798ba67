#include "coupling/shell_wall.hpp"

#include "io/binary_stream.hpp"
#include "sph/surface_mesh_wall.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

namespace grainload::coupling {

namespace {

std::size_t at(Index i) {
    return static_cast<std::size_t>(i);
}

/// The part's mid-surface as a surface mesh, for the SPH walls' own sampler
/// (sph/surface_mesh_wall.hpp): faces are its triangles first, then its quadrangles, and
/// `face_element` the element of each face.
io::SurfaceMesh part_surface(const fem::ShellMesh& mesh, const std::vector<Index>& elements,
                             std::vector<Index>& face_element) {
    io::SurfaceMesh surface;
    surface.vertices = mesh.nodes();
    for (const Index e : elements) {
        if (mesh.element(e).is_triangle()) {
            const auto& n = mesh.element(e).nodes;
            surface.triangles.push_back({n[0], n[1], n[2]});
            face_element.push_back(e);
        }
    }
    for (const Index e : elements) {
        if (!mesh.element(e).is_triangle()) {
            surface.quads.push_back(mesh.element(e).nodes);
            face_element.push_back(e);
        }
    }
    return surface;
}

} // namespace

double ShellWall::particle_bound(const fem::ShellMesh& mesh, const std::vector<Index>& elements,
                                 const ShellWallLayout& layout) {
    std::vector<Index> face_element;
    return sph::mesh_wall_sample_bound(part_surface(mesh, elements, face_element), layout.spacing,
                                       layout.layers, 3);
}

ShellWall::ShellWall(const fem::ShellAnalysis& analysis, const std::vector<Index>& elements,
                     const ShellWallLayout& layout)
    : side_(layout.side) {
    if (!(layout.spacing > 0.0) || layout.layers < 1 ||
        (side_ == ContactSide::both && layout.layers != 1)) {
        throw std::invalid_argument("ShellWall: expected a positive spacing and >= 1 layer "
                                    "(exactly 1 for both sides)");
    }
    std::vector<Index> face_element;
    const io::SurfaceMesh surface = part_surface(analysis.mesh(), elements, face_element);
    const fem::ShellMesh& mesh = analysis.mesh();
    const sph::MeshWallSamples sampled = sph::mesh_wall_points(
        surface, layout.spacing, layout.layers, 3, side_ == ContactSide::negative);
    for (const sph::WallSample& origin : sampled.samples) {
        Sample sample;
        sample.element = face_element[at(origin.face)];
        const fem::ShellElement& element = mesh.element(sample.element);
        const int corners = element.is_triangle() ? 3 : 4;
        sample.nodes = element.nodes;
        sample.weights = sph::face_weights(origin, corners);
        // Layer k behind the contact face at side * t/2, like a plane wall's layers; with sand
        // on both sides, the one layer on the mid-surface.
        sample.offset =
            static_cast<double>(side_) *
            (0.5 * element.thickness - (static_cast<double>(origin.layer) + 0.5) * layout.spacing);
        layout_.push_back(sample);
        sph::WallSample record = origin;
        record.face = sample.element;
        record.offset = sample.offset;
        samples_.push_back(record);
    }
    const std::size_t n = layout_.size();
    mid_end_.resize(n);
    director_end_.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
        current_frame(analysis, layout_[j], mid_end_[j], director_end_[j]);
        points_.push_back(mid_end_[j] + layout_[j].offset * director_end_[j]);
        normals_.push_back(normal_sign(side_) * director_end_[j].normalized());
    }
    mid_start_ = mid_end_;
    director_start_ = director_end_;
    last_force_.assign(n, Vec3::Zero());
    impulse_.assign(n, Vec3::Zero());
}

void ShellWall::current_frame(const fem::ShellAnalysis& analysis, const Sample& sample, Vec3& mid,
                              Vec3& director) const {
    mid.setZero();
    director.setZero();
    for (int a = 0; a < 4; ++a) {
        const double w = sample.weights[at(a)];
        if (w == 0.0) {
            continue;
        }
        const Index node = sample.nodes[at(a)];
        mid += w * (analysis.mesh().node(node) + analysis.displacement(node));
        director += w * analysis.director(sample.element, a);
    }
}

void ShellWall::begin_window(const fem::ShellAnalysis& analysis, double t0, double t1) {
    mid_start_.swap(mid_end_);
    director_start_.swap(director_end_);
    for (std::size_t j = 0; j < layout_.size(); ++j) {
        current_frame(analysis, layout_[j], mid_end_[j], director_end_[j]);
    }
    window_start_ = t0;
    window_end_ = t1;
}

void ShellWall::move(sph::ParticleSet& particles, sph::Wall& wall, double t, double dt) {
    const double length = window_end_ - window_start_;
    const double theta = length > 0.0 ? (t + dt - window_start_) / length : 1.0;
    const auto n = static_cast<Index>(layout_.size());
    wall.angular_velocities.resize(at(n));
#pragma omp parallel for schedule(static)
    for (Index j = 0; j < n; ++j) {
        const double o = layout_[at(j)].offset;
        const Vec3 mid = (1.0 - theta) * mid_start_[at(j)] + theta * mid_end_[at(j)];
        const Vec3 director = (1.0 - theta) * director_start_[at(j)] + theta * director_end_[at(j)];
        const Index k = wall.first + j;
        particles.position[at(k)] = mid + o * director;
        if (length > 0.0) {
            const Vec3 director_rate = (director_end_[at(j)] - director_start_[at(j)]) / length;
            particles.velocity[at(k)] =
                (mid_end_[at(j)] - mid_start_[at(j)]) / length + o * director_rate;
            // The rotation rate that turns the director at its rate (its spin about itself,
            // which moves no point of the normal, is left out).
            wall.angular_velocities[at(j)] = director.cross(director_rate) / director.squaredNorm();
        }
        wall.normals[at(j)] = normal_sign(side_) * director.normalized();
    }
}

void ShellWall::accumulate(const sph::ParticleSet& particles, const sph::Wall& wall, double dt) {
    double work = 0.0;
    Vec3 total = Vec3::Zero();
    for (std::size_t j = 0; j < layout_.size(); ++j) {
        const Index k = wall.first + static_cast<Index>(j);
        const Vec3 force = particles.mass[at(k)] * particles.acceleration[at(k)];
        const Vec3 impulse = 0.5 * dt * (last_force_[j] + force);
        impulse_[j] += impulse;
        total += impulse;
        work += impulse.dot(particles.velocity[at(k)]);
        last_force_[j] = force;
    }
    impulse_total_ += total;
    work_ += work;
}

void ShellWall::add_nodal_loads(const fem::ShellAnalysis& analysis, double window,
                                Eigen::VectorXd& loads) {
    for (std::size_t j = 0; j < layout_.size(); ++j) {
        const Sample& sample = layout_[j];
        const Vec3 force = impulse_[j] / window;
        for (int a = 0; a < 4; ++a) {
            const double w = sample.weights[at(a)];
            if (w == 0.0) {
                continue;
            }
            const Index node = sample.nodes[at(a)];
            // The moment arm is the director's derivative with respect to the node's rotation:
            // the initial director under linear kinematics (d = V + theta x V), the current one
            // under large rotations, so that the mapped loads do the particles' work.
            const Vec3 arm = sample.offset * (analysis.kinematics() == fem::Kinematics::linear
                                                  ? analysis.initial_director(sample.element, a)
                                                  : analysis.director(sample.element, a));
            loads.segment<3>(6 * node) += w * force;
            loads.segment<3>(6 * node + 3) += w * arm.cross(force);
        }
        impulse_[j].setZero();
    }
}

void ShellWall::write_state(std::ostream& out) const {
    io::write_array(out, mid_start_);
    io::write_array(out, mid_end_);
    io::write_array(out, director_start_);
    io::write_array(out, director_end_);
    io::write_array(out, last_force_);
    io::write_array(out, impulse_);
    io::write_array(out, std::vector<double>{window_start_, window_end_, work_, impulse_total_.x(),
                                             impulse_total_.y(), impulse_total_.z()});
}

void ShellWall::read_state(std::istream& in) {
    io::read_array(in, mid_start_);
    io::read_array(in, mid_end_);
    io::read_array(in, director_start_);
    io::read_array(in, director_end_);
    io::read_array(in, last_force_);
    io::read_array(in, impulse_);
    std::vector<double> scalars;
    io::read_array(in, scalars);
    if (scalars.size() != 6 || mid_start_.size() != layout_.size() ||
        impulse_.size() != layout_.size()) {
        throw std::runtime_error(
            "checkpoint: a coupled shell wall's state does not match the case");
    }
    window_start_ = scalars[0];
    window_end_ = scalars[1];
    work_ = scalars[2];
    impulse_total_ = Vec3(scalars[3], scalars[4], scalars[5]);
}

} // namespace grainload::coupling
