#include "fem/shell_mesh.hpp"

#include <Eigen/Geometry>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace grainload::fem {

Index ShellMesh::add_node(const Vec3& x) {
    nodes_.push_back(x);
    return node_count() - 1;
}

Index ShellMesh::add_element(const std::array<Index, 4>& nodes, double thickness, int part) {
    elements_.push_back({nodes, thickness, part});
    return element_count() - 1;
}

std::vector<Index> ShellMesh::append(const ShellMesh& part_mesh, int part, double tolerance) {
    const std::size_t existing = nodes_.size();
    const std::vector<Vec3> part_normals = part_mesh.normals_;
    normals_.resize(existing, Vec3::Zero());
    std::vector<Index> map(static_cast<std::size_t>(part_mesh.node_count()), -1);
    for (Index n = 0; n < part_mesh.node_count(); ++n) {
        const Vec3& x = part_mesh.node(n);
        // Seams are few: a linear search over the existing nodes is cheap next to the solve.
        Index found = -1;
        for (std::size_t m = 0; m < existing && found < 0; ++m) {
            if ((nodes_[m] - x).norm() <= tolerance) {
                found = static_cast<Index>(m);
            }
        }
        if (found >= 0) {
            normals_[static_cast<std::size_t>(found)] = Vec3::Zero();
        } else {
            found = add_node(x);
            normals_.push_back(part_mesh.has_exact_normal(n)
                                   ? part_normals[static_cast<std::size_t>(n)]
                                   : Vec3::Zero());
        }
        map[static_cast<std::size_t>(n)] = found;
    }
    for (const ShellElement& e : part_mesh.elements()) {
        std::array<Index, 4> nodes{};
        for (std::size_t k = 0; k < 4; ++k) {
            nodes[k] = map[static_cast<std::size_t>(e.nodes[k])];
        }
        add_element(nodes, e.thickness, part);
    }
    return map;
}

std::vector<Index> ShellMesh::part_elements(int part) const {
    std::vector<Index> selected;
    for (Index e = 0; e < element_count(); ++e) {
        if (element(e).part == part) {
            selected.push_back(e);
        }
    }
    return selected;
}

void ShellMesh::set_thickness(double thickness) {
    for (auto& e : elements_) {
        e.thickness = thickness;
    }
}

void ShellMesh::translate(const Vec3& offset) {
    for (Vec3& x : nodes_) {
        x += offset;
    }
}

void ShellMesh::add_node_set(const std::string& name, std::vector<Index> nodes) {
    node_sets_[name] = std::move(nodes);
}

void ShellMesh::add_element_set(const std::string& name, std::vector<Index> elements) {
    element_sets_[name] = std::move(elements);
}

namespace {

const std::vector<Index>& find_set(const std::map<std::string, std::vector<Index>>& sets,
                                   const std::string& name, const char* what) {
    const auto it = sets.find(name);
    if (it != sets.end()) {
        return it->second;
    }
    std::ostringstream message;
    message << "unknown " << what << " set '" << name << "'; known:";
    for (const auto& [known, members] : sets) {
        message << ' ' << known;
    }
    throw std::invalid_argument(message.str());
}

} // namespace

const std::vector<Index>& ShellMesh::node_set(const std::string& name) const {
    return find_set(node_sets_, name, "node");
}

const std::vector<Index>& ShellMesh::element_set(const std::string& name) const {
    return find_set(element_sets_, name, "element");
}

Index ShellMesh::nearest_node(const Vec3& x) const {
    Index best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    for (Index i = 0; i < node_count(); ++i) {
        const double d = (node(i) - x).squaredNorm();
        if (d < best_distance) {
            best_distance = d;
            best = i;
        }
    }
    return best;
}

double element_area(const ShellMesh& mesh, const ShellElement& element) {
    const auto& n = element.nodes;
    const Vec3 c =
        element.is_triangle()
            ? Vec3((mesh.node(n[1]) - mesh.node(n[0])).cross(mesh.node(n[2]) - mesh.node(n[0])))
            : Vec3((mesh.node(n[2]) - mesh.node(n[0])).cross(mesh.node(n[3]) - mesh.node(n[1])));
    return 0.5 * c.norm();
}

Vec3 element_normal(const ShellMesh& mesh, const ShellElement& element) {
    const auto& n = element.nodes;
    const Vec3 d1 = mesh.node(n[2]) - mesh.node(n[0]);
    const Vec3 d2 = element.is_triangle() ? Vec3(mesh.node(n[2]) - mesh.node(n[1]))
                                          : Vec3(mesh.node(n[3]) - mesh.node(n[1]));
    const Vec3 c =
        element.is_triangle()
            ? Vec3((mesh.node(n[1]) - mesh.node(n[0])).cross(mesh.node(n[2]) - mesh.node(n[0])))
            : Vec3(d1.cross(d2));
    const double length = c.norm();
    return length > 0.0 ? Vec3(c / length) : Vec3::Zero();
}

std::vector<Vec3> ShellMesh::nodal_normals() const {
    std::vector<Vec3> normals(nodes_.size(), Vec3::Zero());
    for (const auto& e : elements_) {
        const Vec3 n = element_normal(*this, e);
        for (int k = 0; k < (e.is_triangle() ? 3 : 4); ++k) {
            normals[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])] += n;
        }
    }
    for (std::size_t n = 0; n < normals.size(); ++n) {
        if (has_exact_normal(static_cast<Index>(n))) {
            normals[n] = normals_[n];
            continue;
        }
        const double length = normals[n].norm();
        if (length > 0.0) {
            normals[n] /= length;
        }
    }
    return normals;
}

void ShellMesh::validate() const {
    const auto fail = [](Index e, const std::string& why) {
        throw std::invalid_argument("shell element " + std::to_string(e) + ": " + why);
    };
    for (Index e = 0; e < element_count(); ++e) {
        const auto& el = element(e);
        for (const Index n : el.nodes) {
            if (n < 0 || n >= node_count()) {
                fail(e, "unknown node id " + std::to_string(n));
            }
        }
        if (!(el.thickness > 0.0)) {
            fail(e, "thickness must be positive");
        }
    }
    std::vector<Vec3> normals(nodes_.size(), Vec3::Zero());
    for (const auto& e : elements_) {
        for (const Index k : e.nodes) {
            normals[static_cast<std::size_t>(k)] += element_normal(*this, e);
        }
    }
    for (Index e = 0; e < element_count(); ++e) {
        const auto& el = element(e);
        const Vec3 n = element_normal(*this, el);
        if (n.isZero()) {
            fail(e, "zero area");
        }
        // A normal that opposes the average of its nodes' normals marks an element whose node
        // order is reversed with respect to its neighbours.
        Vec3 around = Vec3::Zero();
        for (const Index k : el.nodes) {
            around += normals[static_cast<std::size_t>(k)];
        }
        if (n.dot(around) <= 0.0) {
            fail(e, "inverted orientation (node order opposite to its neighbours)");
        }
    }
}

} // namespace grainload::fem
