#include "coupling/dem_shell_wall.hpp"

#include "io/binary_stream.hpp"

#include <Eigen/Geometry>
#include <map>
#include <utility>

namespace grainload::coupling {

DemShellWall::DemShellWall(const fem::ShellAnalysis& analysis, const std::vector<Index>& elements) {
    const fem::ShellMesh& mesh = analysis.mesh();
    // The part's nodes in the order its elements first name them: the wall's vertices.
    std::map<Index, Index> vertex;
    const auto vertex_of = [&](Index node) {
        const auto [at, added] = vertex.try_emplace(node, static_cast<Index>(nodes_.size()));
        if (added) {
            nodes_.push_back(node);
        }
        return at->second;
    };
    for (const Index e : elements) {
        const fem::ShellElement& element = mesh.element(e);
        const auto& n = element.nodes;
        const int count = element.is_triangle() ? 3 : 4;
        for (int a = 0; a < count; ++a) {
            corners_.push_back({e, a, vertex_of(n[static_cast<std::size_t>(a)])});
        }
        if (element.is_triangle()) {
            surface_.triangles.push_back({vertex_of(n[0]), vertex_of(n[1]), vertex_of(n[2])});
        } else {
            surface_.quads.push_back(
                {vertex_of(n[0]), vertex_of(n[1]), vertex_of(n[2]), vertex_of(n[3])});
        }
        half_thickness_ = 0.5 * element.thickness;
    }
    surface_.vertices = positions(analysis);
    const std::size_t n = nodes_.size();
    last_force_.assign(n, Vec3::Zero());
    last_moment_.assign(n, Vec3::Zero());
    impulse_.assign(n, Vec3::Zero());
    moment_impulse_.assign(n, Vec3::Zero());
}

std::vector<Vec3> DemShellWall::positions(const fem::ShellAnalysis& analysis) const {
    std::vector<Vec3> at;
    at.reserve(nodes_.size());
    for (const Index node : nodes_) {
        at.push_back(analysis.mesh().node(node) + analysis.displacement(node));
    }
    return at;
}

dem::PlaneWall DemShellWall::make_wall(const fem::ShellAnalysis& analysis, const std::string& name,
                                       bool follows) const {
    dem::PlaneWall wall;
    wall.name = name;
    io::SurfaceMesh surface = surface_;
    surface.vertices = positions(analysis);
    wall.set_mesh(surface);
    wall.half_thickness = half_thickness_;
    if (follows) {
        wall.set_interval(surface.vertices, 0.0, 0.0);
    }
    return wall;
}

void DemShellWall::begin_window(const fem::ShellAnalysis& analysis, dem::PlaneWall& wall, double t0,
                                double t1) const {
    wall.set_interval(positions(analysis), t0, t1);
}

void DemShellWall::accumulate(const dem::PlaneWall& wall, double dt) {
    const dem::PlaneWall::VertexMotion& v = wall.vertices;
    const double length = v.end_time - v.start_time;
    Vec3 total = Vec3::Zero();
    double work = 0.0;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Vec3 impulse = 0.5 * dt * (last_force_[k] + v.force[k]);
        impulse_[k] += impulse;
        moment_impulse_[k] += 0.5 * dt * (last_moment_[k] + v.moment[k]);
        total += impulse;
        if (length > 0.0) {
            work += impulse.dot(v.end[k] - v.start[k]) / length;
        }
        last_force_[k] = v.force[k];
        last_moment_[k] = v.moment[k];
    }
    impulse_total_ += total;
    work_ += work;
}

void DemShellWall::add_nodal_loads(const fem::ShellAnalysis& analysis, double window,
                                   Eigen::VectorXd& loads) {
    // The directors the shell's rotations turn: the initial ones under linear kinematics (its
    // drilling spring acts about them), the current ones under large rotations.
    const bool linear = analysis.kinematics() == fem::Kinematics::linear;
    std::vector<Vec3> director(nodes_.size(), Vec3::Zero());
    for (const auto& [element, corner, vertex] : corners_) {
        const int a = static_cast<int>(corner);
        director[static_cast<std::size_t>(vertex)] +=
            (linear ? analysis.initial_director(element, a) : analysis.director(element, a))
                .normalized();
    }
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const auto node = static_cast<Eigen::Index>(nodes_[k]);
        const Vec3 d = director[k].normalized();
        const Vec3 moment = moment_impulse_[k] / window;
        loads.segment<3>(6 * node) += impulse_[k] / window;
        loads.segment<3>(6 * node + 3) += moment - moment.dot(d) * d;
        impulse_[k].setZero();
        moment_impulse_[k].setZero();
    }
}

void DemShellWall::write_state(std::ostream& out, const dem::PlaneWall& wall) const {
    io::write_array(out, wall.vertices.start);
    io::write_array(out, wall.vertices.end);
    io::write_array(out, last_force_);
    io::write_array(out, last_moment_);
    io::write_array(out, impulse_);
    io::write_array(out, moment_impulse_);
    io::write_array(out, std::vector<double>{wall.vertices.start_time, wall.vertices.end_time,
                                             work_, impulse_total_.x(), impulse_total_.y(),
                                             impulse_total_.z()});
}

void DemShellWall::read_state(std::istream& in, dem::PlaneWall& wall) {
    const std::size_t n = nodes_.size();
    std::vector<Vec3> start, end;
    io::read_array(in, start, n, "a coupled shell wall's vertices");
    io::read_array(in, end, n, "a coupled shell wall's vertices");
    io::read_array(in, last_force_, n, "a coupled shell wall's forces");
    io::read_array(in, last_moment_, n, "a coupled shell wall's moments");
    io::read_array(in, impulse_, n, "a coupled shell wall's impulses");
    io::read_array(in, moment_impulse_, n, "a coupled shell wall's impulses");
    std::vector<double> scalars;
    io::read_array(in, scalars, 6, "a coupled shell wall's window");
    // The wall's vertices as the window left them; its faces follow at the next evaluation.
    dem::PlaneWall::VertexMotion& v = wall.vertices;
    v.start = std::move(start);
    v.end = std::move(end);
    v.start_time = scalars[0];
    v.end_time = scalars[1];
    v.force = last_force_;
    v.moment = last_moment_;
    wall.grid = dem::FaceGrid{};
    work_ = scalars[2];
    impulse_total_ = Vec3(scalars[3], scalars[4], scalars[5]);
}

} // namespace grainload::coupling
