#pragma once
// The interface load as the frames show it: contact pressure and friction traction on the shell.

#include "coupling/shell_wall.hpp"
#include "fem/shell_model.hpp"
#include "io/frame.hpp"

#include <Eigen/Core>
#include <vector>

namespace grainload::coupling {

/// The coupled parts' nodes as the interface load's pressure reads them: the lumped area of the
/// coupled elements around each node and its unit normal towards the sand (both sides: the
/// element normals' side counts as compression). Shared by the SPH and the DEM couplings.
class InterfacePressure {
  public:
    explicit InterfacePressure(const fem::ShellMesh& mesh);
    /// Adds the coupled elements of one part, the sand on `side`.
    void add_part(const fem::ShellMesh& mesh, const std::vector<Index>& elements, ContactSide side);
    /// Once every part is added: the normals made unit.
    void finish();
    /// Per node, the load of 6 entries per node as contact pressure (compression positive) and
    /// friction traction (tangential force per area); zero where no coupled element is.
    std::vector<io::FieldArray> node_fields(const Eigen::VectorXd& load) const;
    /// The shell's frame blocks with the pressure and traction of `load` on its nodes and, the
    /// mean of their corners', on its elements (for cell-based filters).
    void append_blocks(const fem::ShellModel& fem, const Eigen::VectorXd& load,
                       io::Frame& frame) const;

  private:
    std::vector<double> node_area_; ///< coupled area around each node (0: not coupled)
    std::vector<Vec3> node_normal_; ///< unit normal towards the sand at each coupled node
};

} // namespace grainload::coupling
