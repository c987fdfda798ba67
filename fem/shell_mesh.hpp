#pragma once
// The shell mid-surface mesh: nodes, quadrilaterals, thickness per element, named sets.

#include "io/types.hpp"

#include <array>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace grainload::fem {

/// A 4-node shell element; a triangle repeats its third node (nodes[3] == nodes[2]).
struct ShellElement {
    std::array<Index, 4> nodes{};
    double thickness = 0.0;
    int part = 0; ///< the shell part ([[fem.shell]] table) it belongs to
    bool is_triangle() const { return nodes[3] == nodes[2]; }
};

/// Shell mid-surface mesh: nodes, quadrilaterals (triangles as collapsed quads), thickness per
/// element, and named node and element sets. Node and element ids are 0-based indices.
class ShellMesh {
  public:
    Index add_node(const Vec3& x);
    Index add_element(const std::array<Index, 4>& nodes, double thickness, int part = 0);
    /// Append the nodes and elements of `part_mesh` as part `part`; a node within `tolerance`
    /// of a node already here (a seam between parts) is that node. Returns the index here of
    /// every node of `part_mesh`. Exact normals carry over except at merged seam nodes, which
    /// join differently oriented parts and get the average with fold detection.
    std::vector<Index> append(const ShellMesh& part_mesh, int part, double tolerance);

    Index node_count() const { return static_cast<Index>(nodes_.size()); }
    Index element_count() const { return static_cast<Index>(elements_.size()); }
    const Vec3& node(Index i) const { return nodes_[static_cast<std::size_t>(i)]; }
    const ShellElement& element(Index e) const { return elements_[static_cast<std::size_t>(e)]; }
    const std::vector<Vec3>& nodes() const { return nodes_; }
    const std::vector<ShellElement>& elements() const { return elements_; }

    void set_thickness(double thickness);
    /// Move every node by `offset`.
    void translate(const Vec3& offset);
    void add_node_set(const std::string& name, std::vector<Index> nodes);
    void add_element_set(const std::string& name, std::vector<Index> elements);
    bool has_node_set(const std::string& name) const { return node_sets_.contains(name); }
    bool has_element_set(const std::string& name) const { return element_sets_.contains(name); }
    /// Throws std::invalid_argument listing the known sets when `name` is unknown.
    const std::vector<Index>& node_set(const std::string& name) const;
    const std::vector<Index>& element_set(const std::string& name) const;
    const std::map<std::string, std::vector<Index>>& node_sets() const { return node_sets_; }
    const std::map<std::string, std::vector<Index>>& element_sets() const { return element_sets_; }

    /// Node closest to `x` (for point loads and monitored points).
    Index nearest_node(const Vec3& x) const;
    /// Unit normal per node: the exact surface normal where a generator supplied one, else the
    /// average of the normals of the elements around it. It is the initial director of the
    /// MITC4 element (Dvorkin & Bathe 1984, "V_n^k") except at fold nodes, where each element
    /// has its own (fem/shell_directors.hpp). On a curved edge the average leans by
    /// half an element angle, which would make a symmetry plane's rotation constraints act
    /// on a tilted drilling axis; the exact normal avoids that.
    std::vector<Vec3> nodal_normals() const;
    void set_nodal_normals(std::vector<Vec3> normals) { normals_ = std::move(normals); }
    /// True when a generator supplied the exact normal of a smooth surface at node n (no fold
    /// can pass through it).
    bool has_exact_normal(Index n) const {
        return static_cast<std::size_t>(n) < normals_.size() &&
               normals_[static_cast<std::size_t>(n)].squaredNorm() > 0.0;
    }
    /// Elements of part `part`.
    std::vector<Index> part_elements(int part) const;

    /// Fold-line threshold [rad]: a node at which some element normal deviates from the
    /// average of the normals around it by more than this angle is a fold node, where every
    /// element keeps its own director (fem/shell_directors.hpp). 20 deg by default, the
    /// threshold Abaqus uses (pairwise there); pi switches fold detection off. Meshes with
    /// exact normals (smooth generated surfaces) have no fold nodes.
    double fold_angle() const { return fold_angle_; }
    void set_fold_angle(double angle) { fold_angle_ = angle; }
    static constexpr double kDefaultFoldAngle = 20.0 * std::numbers::pi / 180.0;

    /// Throws std::invalid_argument naming the first bad element: unknown node ids, zero
    /// thickness, zero area, or a normal opposite to its neighbours' (inverted orientation).
    void validate() const;

  private:
    std::vector<Vec3> nodes_;
    std::vector<ShellElement> elements_;
    std::vector<Vec3> normals_;
    double fold_angle_ = kDefaultFoldAngle;
    std::map<std::string, std::vector<Index>> node_sets_;
    std::map<std::string, std::vector<Index>> element_sets_;
};

/// Area of an element from its diagonals (exact for a planar quadrangle or a triangle).
double element_area(const ShellMesh& mesh, const ShellElement& element);

/// Unit normal of an element from its diagonals (zero vector for a degenerate element).
Vec3 element_normal(const ShellMesh& mesh, const ShellElement& element);

} // namespace grainload::fem
