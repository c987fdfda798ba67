#pragma once
// A coupled shell part: the shell part whose walls the sand pushes, as the coupling holds it.

#include "coupling/shell_wall.hpp"

#include <memory>
#include <string>
#include <vector>

namespace grainload::coupling {

/// A coupled shell part: the walls' driver and where its particles are in the SPH model.
struct CoupledPart {
    std::string name;    ///< the shell part's name (the SPH wall has the same)
    int wall_index = -1; ///< in the SPH solver's wall list
    std::shared_ptr<ShellWall> wall;
    std::vector<Index> elements; ///< the part's shell elements
    ContactSide side = ContactSide::positive;
};

} // namespace grainload::coupling
