#include "coupling/interface_pressure.hpp"

namespace grainload::coupling {

InterfacePressure::InterfacePressure(const fem::ShellMesh& mesh)
    : node_area_(static_cast<std::size_t>(mesh.node_count()), 0.0),
      node_normal_(static_cast<std::size_t>(mesh.node_count()), Vec3::Zero()) {}

void InterfacePressure::add_part(const fem::ShellMesh& mesh, const std::vector<Index>& elements,
                                 ContactSide side) {
    for (const Index e : elements) {
        const fem::ShellElement& element = mesh.element(e);
        const auto& n = element.nodes;
        const int corners = element.is_triangle() ? 3 : 4;
        const double area = fem::element_area(mesh, element);
        // Both sides: the element normals' side counts as compression.
        const Vec3 normal = normal_sign(side) * fem::element_normal(mesh, element);
        for (int a = 0; a < corners; ++a) {
            const auto node = static_cast<std::size_t>(n[static_cast<std::size_t>(a)]);
            node_area_[node] += area / corners;
            node_normal_[node] += area * normal;
        }
    }
}

void InterfacePressure::finish() {
    for (Vec3& normal : node_normal_) {
        if (normal.squaredNorm() > 0.0) {
            normal.normalize();
        }
    }
}

std::vector<io::FieldArray> InterfacePressure::node_fields(const Eigen::VectorXd& load) const {
    io::FieldArray pressure{"contact_pressure", 1, {}}, traction{"friction_traction", 3, {}};
    for (std::size_t n = 0; n < node_area_.size(); ++n) {
        Vec3 tangential = Vec3::Zero();
        double normal_stress = 0.0;
        if (node_area_[n] > 0.0) {
            const Vec3 force = load.segment<3>(static_cast<Eigen::Index>(6 * n));
            // The sand pushes against its own side's normal: compression is -f . n.
            normal_stress = -force.dot(node_normal_[n]) / node_area_[n];
            tangential = (force - force.dot(node_normal_[n]) * node_normal_[n]) / node_area_[n];
        }
        pressure.values.push_back(normal_stress);
        traction.values.insert(traction.values.end(), tangential.begin(), tangential.end());
    }
    return {pressure, traction};
}

void InterfacePressure::append_blocks(const fem::ShellModel& fem, const Eigen::VectorXd& load,
                                      io::Frame& frame) const {
    const std::vector<io::FieldArray> nodes = node_fields(load);
    std::vector<io::FieldArray> elements;
    const fem::ShellMesh& mesh = fem.analysis().mesh();
    for (const io::FieldArray& field : nodes) {
        io::FieldArray cell{field.name, field.components, {}};
        const auto c = static_cast<std::size_t>(field.components);
        for (const fem::ShellElement& element : mesh.elements()) {
            const int corners = element.is_triangle() ? 3 : 4;
            for (std::size_t k = 0; k < c; ++k) {
                double sum = 0.0;
                for (int a = 0; a < corners; ++a) {
                    sum += field.values[c * static_cast<std::size_t>(
                                                element.nodes[static_cast<std::size_t>(a)]) +
                                        k];
                }
                cell.values.push_back(sum / corners);
            }
        }
        elements.push_back(std::move(cell));
    }
    fem.append_blocks(frame, nodes, elements);
}

} // namespace grainload::coupling
