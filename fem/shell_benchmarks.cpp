#include "fem/shell_benchmarks.hpp"

#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"

#include <numbers>

namespace grainload::fem {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
enum Dof { ux, uy, uz, rx, ry, rz };

/// Common node of two node sets (the corner where a load or a monitor point sits).
Index corner(const ShellMesh& mesh, const std::string& a, const std::string& b) {
    for (const Index i : mesh.node_set(a)) {
        for (const Index j : mesh.node_set(b)) {
            if (i == j) {
                return i;
            }
        }
    }
    return -1;
}

/// A benchmark from the literature: a linear analysis of `mesh` in an elastic material (the
/// density does not enter a static solve), 2 points through the thickness.
ShellBenchmark linear_benchmark(std::string name, std::string source, double reference,
                                double young, double poisson, ShellMesh mesh) {
    ShellBenchmark b;
    b.name = std::move(name);
    b.source = std::move(source);
    b.reference = reference;
    b.material = std::make_unique<materials::LinearElastic>(
        materials::ElasticConstants::from_young(1.0, young, poisson));
    b.analysis =
        std::make_unique<ShellAnalysis>(std::move(mesh), *b.material, Kinematics::linear, 2);
    return b;
}

/// Symmetry about a plane with unit normal along `axis`: the normal translation and the two
/// rotation components lying in the plane vanish (a rotation vector is an axial vector, so
/// its in-plane components change sign under the reflection); the rotation about the plane
/// normal stays free.
void symmetry(ShellAnalysis& analysis, const std::vector<Index>& nodes, int axis) {
    analysis.prescribe(nodes, {axis, 3 + (axis + 1) % 3, 3 + (axis + 2) % 3});
}

} // namespace

ShellBenchmark scordelis_lo_roof(int n) {
    ShellBenchmark b = linear_benchmark(
        "Scordelis-Lo roof", "MacNeal & Harder 1985, Finite Elem. Anal. Des. 1:3-20", 0.3024,
        4.32e8, 0.0, make_cylinder(25.0, 25.0, 0.0, 40.0 * kDegree, n, n, 0.25));
    ShellAnalysis& a = *b.analysis;
    const ShellMesh& m = a.mesh();
    a.prescribe(m.node_set("y0"), {ux, uz}); // rigid diaphragm: no motion in its own plane
    symmetry(a, m.node_set("y1"), 1);        // mid-span
    symmetry(a, m.node_set("phi0"), 0);      // crown
    a.add_area_load(Vec3(0.0, 0.0, -90.0));
    b.monitor_node = corner(m, "phi1", "y1");
    b.monitor_dof = uz;
    return b;
}

ShellBenchmark pinched_cylinder(int n) {
    ShellBenchmark b = linear_benchmark(
        "pinched cylinder", "Belytschko et al. 1985, Comput. Methods Appl. Mech. Eng. 51:221-258",
        1.8248e-5, 3e6, 0.3, make_cylinder(300.0, 300.0, 0.0, 90.0 * kDegree, n, n, 3.0));
    ShellAnalysis& a = *b.analysis;
    const ShellMesh& m = a.mesh();
    a.prescribe(m.node_set("y1"), {ux, uz}); // rigid diaphragm at the end
    symmetry(a, m.node_set("y0"), 1);        // mid-length
    symmetry(a, m.node_set("phi0"), 0);      // plane x = 0
    symmetry(a, m.node_set("phi1"), 2);      // plane z = 0
    b.monitor_node = corner(m, "phi0", "y0");
    b.monitor_dof = uz;
    a.add_nodal_load(b.monitor_node, uz, -0.25); // a quarter of P lies in the octant
    return b;
}

ShellBenchmark pinched_hemisphere(int n) {
    ShellBenchmark b = linear_benchmark(
        "pinched hemisphere", "MacNeal & Harder 1985, Finite Elem. Anal. Des. 1:3-20", 0.094,
        6.825e7, 0.3,
        make_sphere_zone(10.0, 18.0 * kDegree, 90.0 * kDegree, 90.0 * kDegree, n, n, 0.04));
    ShellAnalysis& a = *b.analysis;
    const ShellMesh& m = a.mesh();
    symmetry(a, m.node_set("azimuth0"), 1); // plane y = 0
    symmetry(a, m.node_set("azimuth1"), 0); // plane x = 0
    b.monitor_node = corner(m, "polar1", "azimuth0");
    b.monitor_dof = ux;
    const Index inward = corner(m, "polar1", "azimuth1");
    // Each load point lies on one symmetry plane, so the quarter carries half of each load.
    a.add_nodal_load(b.monitor_node, ux, 1.0);
    a.add_nodal_load(inward, uy, -1.0);
    a.prescribe(b.monitor_node, uz); // the loads are self-equilibrated: removes rigid z motion
    return b;
}

} // namespace grainload::fem
