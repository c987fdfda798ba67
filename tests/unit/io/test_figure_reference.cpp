#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "io/figure_reference.hpp"

#include <gtest/gtest.h>

namespace grainload::io {
namespace {

std::vector<ResultFigure> figures() {
    ResultFigure audit{"mass_audit_error", 1e-15, "", 0.0, "mass in = mass out"};
    return {{"scene_mass", 12.5, "kg", std::nullopt, ""},
            {"door_force", 3.0e4, "N", std::nullopt, ""},
            audit};
}

/// A case whose [case] table is followed by `reference_tables`.
std::unique_ptr<CaseDocument> case_with(const std::string& reference_tables) {
    return CaseDocument::from_string("[case]\nend_time = \"1 s\"\n" + reference_tables,
                                     "case.toml");
}

/// figures() with the references of `reference_tables` read, checked and applied.
std::vector<ResultFigure> referenced_figures(const std::string& reference_tables) {
    const auto document = case_with(reference_tables); // the references' tables point into it
    const auto references = read_figure_references(document->root());
    auto results = figures();
    check_figure_references(references, results);
    apply_figure_references(references, results);
    return results;
}

// A value in the figure's unit becomes the figure's reference, converted to SI, with the
// source; summary.json then writes the error against it (relative, or absolute for 0).
TEST(FigureReference, ValueAndSourceAttachToTheNamedFigure) {
    const auto results = referenced_figures(
        "[[case.reference]]\nfigure = \"scene_mass\"\nvalue = \"0 t\"\n"
        "source = \"thesis 7.4: empties\"\n"
        "[[case.reference]]\nfigure = \"door_force\"\nvalue = \"25 kN\"\nsource = \"hand\"\n");
    ASSERT_TRUE(results[0].reference.has_value());
    EXPECT_EQ(*results[0].reference, 0.0);
    EXPECT_EQ(results[0].source, "thesis 7.4: empties");
    ASSERT_TRUE(results[1].reference.has_value());
    EXPECT_DOUBLE_EQ(*results[1].reference, 25.0e3); // kN to N
}

// A statement without a number (the thesis: "material stays on the slopes") keeps the figure
// without a reference but with its source.
TEST(FigureReference, AStatementOnlyGivesTheSource) {
    const auto results = referenced_figures(
        "[[case.reference]]\nfigure = \"scene_mass\"\n"
        "source = \"thesis 7.4: material stays on the body edge and the slopes\"\n");
    EXPECT_FALSE(results[0].reference.has_value());
    EXPECT_EQ(results[0].source, "thesis 7.4: material stays on the body edge and the slopes");
}

std::string error_of(const std::string& reference_tables) {
    try {
        check_figure_references(read_figure_references(case_with(reference_tables)->root()),
                                figures());
    } catch (const CaseError& error) {
        return error.what();
    }
    return "";
}

// Strict input: a misspelt figure, a second reference for one figure, a figure that has its
// own reference, a value in another unit and a missing source are errors with file and key.
TEST(FigureReference, BadReferencesAreRefusedWithTheKey) {
    EXPECT_NE(error_of("[[case.reference]]\nfigure = \"scene_mas\"\nsource = \"x\"\n")
                  .find("expected a figure of this scene's summary.json: scene_mass"),
              std::string::npos);
    EXPECT_NE(error_of("[[case.reference]]\nfigure = \"scene_mass\"\nsource = \"x\"\n"
                       "[[case.reference]]\nfigure = \"scene_mass\"\nsource = \"y\"\n")
                  .find("has two"),
              std::string::npos);
    EXPECT_NE(error_of("[[case.reference]]\nfigure = \"mass_audit_error\"\nsource = \"x\"\n")
                  .find("its own reference"),
              std::string::npos);
    EXPECT_NE(error_of("[[case.reference]]\nfigure = \"door_force\"\nvalue = \"3 m\"\n"
                       "source = \"x\"\n")
                  .find("case.reference[0].value"),
              std::string::npos);
    EXPECT_NE(
        error_of("[[case.reference]]\nfigure = \"door_force\"\nsource = \"\"\n").find("source"),
        std::string::npos);
}

} // namespace
} // namespace grainload::io
