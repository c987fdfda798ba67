#pragma once
// The [[case.reference]] tables: independent references a case states for its figures.

#include "io/case_table.hpp"
#include "io/frame.hpp"
#include "io/key_spec.hpp"

#include <array>
#include <vector>

namespace grainload::io {

/// The keys of [[case.reference]] (docs/user-guide.md, "[[case.reference]]").
inline constexpr std::array<KeySpec, 3> kFigureReferenceKeys{{
    {"figure", "string", "", "the name of a figure of the run's summary.json `results`"},
    {"value", "quantity in the figure's unit", "none: a statement only",
     "the independent reference value; summary.json adds the figure's error against it"},
    {"source", "string", "", "where the reference comes from: paper, section, statement"},
}};

/// An independent reference a case states for one of its summary figures: an experiment, a
/// paper's statement ("the wagon empties completely", thesis section 7.4), a hand
/// calculation. `grainload trade` compares against it as against the modules' own references.
struct FigureReference {
    CaseTable table; ///< for errors with file, line and key
    std::string figure;
    std::string source;
};

/// Reads every [[case.reference]] of the document's [case] table (names and sources; values
/// are read by check_figure_references, which knows each figure's unit).
std::vector<FigureReference> read_figure_references(const CaseTable& root);

/// Fails (CaseError: file, line, key) when a reference names no figure of `figures` (the
/// scene's figures at t = 0, which name every figure the run will report), names one twice,
/// names one that carries its own reference, or gives a value not in the figure's unit.
void check_figure_references(const std::vector<FigureReference>& references,
                             const std::vector<ResultFigure>& figures);

/// Sets each referenced figure's reference (when a value is given) and source.
void apply_figure_references(const std::vector<FigureReference>& references,
                             std::vector<ResultFigure>& figures);

} // namespace grainload::io
