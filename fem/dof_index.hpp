#pragma once
// The degrees of freedom of a shell node (three translations, three rotations) and indexing.

#include "io/types.hpp"

#include <cstddef>

namespace grainload::fem {

/// DOFs of a shell node: three translations and three rotations (MITC4 with a drilling DOF).
inline constexpr int kDofs = 6;

/// An Index (signed, as Eigen and the mesh count) as a std::vector subscript.
inline std::size_t at(Index i) {
    return static_cast<std::size_t>(i);
}

} // namespace grainload::fem
