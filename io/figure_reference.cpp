#include "io/figure_reference.hpp"

#include "io/units.hpp"

#include <algorithm>
#include <set>

namespace grainload::io {

std::vector<FigureReference> read_figure_references(const CaseTable& root) {
    std::vector<FigureReference> references;
    if (!root.has("case")) {
        return references;
    }
    for (const CaseTable& table : root.table("case").array_of_tables("reference")) {
        references.push_back({table, table.string("figure"), table.string("source")});
        if (references.back().source.empty()) {
            table.fail("source", "expected where the reference comes from (paper, section)");
        }
    }
    return references;
}

namespace {

/// The dimension of a figure's unit text ("kg", "kg/s", "" for a ratio).
Dimension unit_dimension(const std::string& unit) {
    if (unit.empty()) {
        return dimension::kNone;
    }
    std::string error;
    const auto parsed = parse_unit(unit, &error);
    return parsed ? parsed->dimension : dimension::kNone;
}

const ResultFigure* find_figure(const std::vector<ResultFigure>& figures, const std::string& name) {
    const auto found = std::find_if(figures.begin(), figures.end(),
                                    [&](const ResultFigure& f) { return f.name == name; });
    return found == figures.end() ? nullptr : &*found;
}

std::string figure_names(const std::vector<ResultFigure>& figures) {
    std::string names;
    for (const ResultFigure& figure : figures) {
        names += (names.empty() ? "" : ", ") + figure.name;
    }
    return names;
}

} // namespace

void check_figure_references(const std::vector<FigureReference>& references,
                             const std::vector<ResultFigure>& figures) {
    std::set<std::string> seen;
    for (const FigureReference& reference : references) {
        const ResultFigure* figure = find_figure(figures, reference.figure);
        if (figure == nullptr) {
            reference.table.fail("figure", "expected a figure of this scene's summary.json: " +
                                               figure_names(figures));
        }
        if (!seen.insert(reference.figure).second) {
            reference.table.fail("figure", "expected one [[case.reference]] per figure: '" +
                                               reference.figure + "' has two");
        }
        if (figure->reference) {
            reference.table.fail("figure", "'" + reference.figure +
                                               "' has its own reference already (" +
                                               figure->source + ")");
        }
        if (reference.table.has("value")) {
            reference.table.quantity("value", unit_dimension(figure->unit));
        }
    }
}

void apply_figure_references(const std::vector<FigureReference>& references,
                             std::vector<ResultFigure>& figures) {
    for (const FigureReference& reference : references) {
        for (ResultFigure& figure : figures) {
            if (figure.name != reference.figure) {
                continue;
            }
            if (reference.table.has("value")) {
                figure.reference = reference.table.quantity("value", unit_dimension(figure.unit));
            }
            figure.source = reference.source;
        }
    }
}

} // namespace grainload::io
