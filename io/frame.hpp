#pragma once
// What a run writes at one output instant: blocks of fields, figures, model choices, phases.

#include "io/types.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace grainload::io {

/// One named array on points or cells. components: 1 (scalar), 3 (vector) or 6 (symmetric
/// tensor in the Voigt order of io/types.hpp, written to VTK as a 3x3 tensor).
struct FieldArray {
    std::string name;
    int components = 1;
    std::vector<double> values; ///< size = components * count
};

/// One block of an output frame: an SPH body or DEM grains (points only), a shell mesh
/// (quads/triangles), or lines between points (a DEM scene's contacts, one line per contact).
/// The writers know nothing of sph/, dem/ or fem/: each module fills blocks of its own.
struct Block {
    enum class Kind { particles, shell, lines };
    std::string name;
    Kind kind = Kind::particles;
    std::vector<Vec3> points;
    /// Shell cells (a triangle repeats no node and has cell[3] == -1), or lines (cell[0] to
    /// cell[1], cell[2] == cell[3] == -1).
    std::vector<std::array<Index, 4>> cells;
    std::vector<FieldArray> point_arrays;
    std::vector<FieldArray> cell_arrays;
};

/// Everything written at one output instant.
struct Frame {
    double time = 0.0;
    std::vector<Block> blocks;
};

/// A figure a case reports in summary.json, optionally beside an independent reference.
struct ResultFigure {
    std::string name;
    double value = 0.0;
    std::string unit;
    std::optional<double> reference;
    std::string source; ///< paper or formula of the reference
};

/// One modelling choice of a scene, for summary.json's "model": what was
/// modelled ("material sand", "wall floor") and how ("generalized_cap", "rigid").
struct ModelChoice {
    std::string item;
    std::string choice;
};

/// One phase of a run ([[phase]]), for summary.json's "phases": when it started and ended
/// (NaN: not reached, not ended) and what ended it ("time", "settled", "discharged"; empty
/// while it runs).
struct PhaseRecord {
    std::string name;
    double start = 0.0;
    double end = 0.0;
    std::string ended_by;
};

} // namespace grainload::io
