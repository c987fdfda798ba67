#include "fem/shell_case_reader.hpp"
#include "io/case_table.hpp"
#include "support/case_runner.hpp"
#include "support/frame_reader.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <map>
#include <numbers>
#include <set>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkXMLMultiBlockDataReader.h>

namespace {

using namespace grainload;
using namespace grainload::testing;
namespace fs = std::filesystem;

/// The case folder's geometry and case files, copied to a fresh folder, so that Gmsh's mesh,
/// the exported deck and the runs land outside the source tree.
std::string case_copy(const std::string& name) {
    const std::string dir = test_folder("hopper_wagon_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const char* file : {"hopper_wagon.geo", "wagon_gravity.toml", "wagon_gravity_k.toml",
                             "wagon_pressure.toml"}) {
        fs::copy_file(source_path(std::string("cases/hopper_wagon/") + file), dir + "/" + file);
    }
    return dir;
}

/// Runs the case folder's export script: the Gmsh mesh as an LS-DYNA deck, mm-t-s.
void export_deck(const std::string& dir) {
    const std::string command = "python3 '" + source_path("cases/hopper_wagon/export_k.py") +
                                "' --case '" + dir + "/wagon_gravity.toml' > '" + dir +
                                "/export.log' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << read_file(dir + "/export.log");
}

fem::ShellMesh shell_mesh(const std::string& case_file) {
    auto document = io::CaseDocument::from_file(case_file);
    return fem::read_shell_mesh(document->root().table("fem").array_of_tables("shell").front());
}

// The deck writes coordinates in mm with 10 significant digits (E16.9): below 6.33 m the
// rounding is at most 0.5e-9 * 6330 mm = 3.2e-9 m.
constexpr double kPrintedPosition = 1e-8;

TEST(HopperWagon, ExportedDeckMatchesTheGmshMesh) {
    const std::string dir = case_copy("export");
    const fem::ShellMesh gmsh = shell_mesh(dir + "/wagon_gravity.toml"); // meshes the .geo
    ASSERT_TRUE(fs::exists(dir + "/hopper_wagon.msh"));
    export_deck(dir);
    const fem::ShellMesh deck = shell_mesh(dir + "/wagon_gravity_k.toml");
    ASSERT_EQ(deck.node_count(), gmsh.node_count());
    ASSERT_EQ(deck.element_count(), gmsh.element_count());
    std::printf("wagon mesh: %lld nodes, %lld elements\n",
                static_cast<long long>(gmsh.node_count()),
                static_cast<long long>(gmsh.element_count()));
    double worst = 0.0;
    for (Index n = 0; n < gmsh.node_count(); ++n) {
        worst = std::max(worst, (deck.node(n) - gmsh.node(n)).norm());
    }
    EXPECT_LT(worst, kPrintedPosition);
    for (Index e = 0; e < gmsh.element_count(); ++e) {
        EXPECT_EQ(deck.element(e).nodes, gmsh.element(e).nodes) << "element " << e;
        // Thicknesses are whole mm in both: exact after one conversion each.
        EXPECT_NEAR(deck.element(e).thickness, gmsh.element(e).thickness, 1e-15) << e;
    }
    EXPECT_EQ(deck.node_sets(), gmsh.node_sets()); // physical groups = parts + node sets
    for (const char* part :
         {"side_wall", "end_wall", "slope_sheet", "middle_slope_sheet", "end_slope_sheet", "ridge",
          "door", "bolster", "top_chord", "tie", "rib", "stanchion", "hinge_beam"}) {
        EXPECT_EQ(deck.element_set(part), gmsh.element_set(part)) << part;
    }
}

// Coordinates of the Gmsh nodes on a weld line are computed from the same points as the
// line: exact to round-off of numbers of order 10 m.
constexpr double kOnWeldLine = 1e-9;

/// Nodes of the elements of element set `part`.
std::set<Index> part_nodes(const fem::ShellMesh& mesh, const std::string& part) {
    std::set<Index> nodes;
    for (const Index e : mesh.element_set(part)) {
        nodes.insert(mesh.element(e).nodes.begin(), mesh.element(e).nodes.end());
    }
    return nodes;
}

/// How many nodes of `stiffener` lie where `on_weld` says and are nodes of one of the
/// `sheets` too; `missing` counts those that are not (a weld line not embedded in the sheet).
struct WeldCount {
    int shared = 0;
    int missing = 0;
};

template <class OnWeld>
WeldCount weld_nodes(const fem::ShellMesh& mesh, const std::string& stiffener,
                     std::initializer_list<const char*> sheets, OnWeld on_weld) {
    std::set<Index> sheet_nodes;
    for (const char* sheet : sheets) {
        sheet_nodes.merge(part_nodes(mesh, sheet));
    }
    WeldCount count;
    for (const Index n : part_nodes(mesh, stiffener)) {
        if (on_weld(mesh.node(n))) {
            ++(sheet_nodes.count(n) != 0 ? count.shared : count.missing);
        }
    }
    return count;
}

// The stiffeners are welded to the sheets along lines embedded in them: every stiffener node
// on a weld line is a node of the sheet as well (Gmsh meshes a sheet without an embedded line
// independently of the stiffener, whose weld nodes would then lie on the sheet but not be its
// nodes). And the mesh is all quadrangles (hopper_wagon.geo subdivides every element).
TEST(HopperWagon, StiffenersShareTheirWeldNodesWithTheSheets) {
    const std::string dir = case_copy("welds");
    const fem::ShellMesh mesh = shell_mesh(dir + "/wagon_gravity.toml");
    for (Index e = 0; e < mesh.element_count(); ++e) {
        EXPECT_FALSE(mesh.element(e).is_triangle()) << "element " << e;
    }
    const double b = 1.5, z_sill = 0.9, z_hinge = 1.6, w_hinge = 0.3, z_top = 3.5;
    const double t = std::tan(49.0 * std::numbers::pi / 180.0), z_ridge = z_sill + b * t;
    const auto near = [](double u, double v) { return std::abs(u - v) < kOnWeldLine; };
    const auto on_saddle = [&](const Vec3& x) { return near(x.z(), z_ridge - x.y() * t); };
    const auto on_side_wall = [&](const Vec3& x) { return near(x.y(), b) && x.z() > z_sill; };
    const auto on_box = [&](const Vec3& x) {
        return x.y() > b + kOnWeldLine && (near(x.z(), z_hinge) || near(x.z(), z_hinge + w_hinge));
    };
    const auto on_chord = [&](const Vec3& x) { return near(x.z(), z_top); };
    const struct {
        const char* what;
        WeldCount count;
        int at_least; // nodes on the weld lines: ten frames of at least two mesh edges each
    } welds[] = {
        {"ribs on the saddle", weld_nodes(mesh, "rib", {"ridge", "slope_sheet"}, on_saddle), 30},
        {"stanchions on the side wall", weld_nodes(mesh, "stanchion", {"side_wall"}, on_side_wall),
         30},
        {"stanchions on the hinge beam", weld_nodes(mesh, "stanchion", {"hinge_beam"}, on_box), 30},
        {"stanchions on the top chord", weld_nodes(mesh, "stanchion", {"top_chord"}, on_chord), 30},
        {"hinge beam on the side wall", weld_nodes(mesh, "hinge_beam", {"side_wall"}, on_side_wall),
         60},
        {"ties on the side wall", weld_nodes(mesh, "tie", {"side_wall"}, on_side_wall), 10},
    };
    for (const auto& weld : welds) {
        std::printf("%s: %d nodes shared, %d not\n", weld.what, weld.count.shared,
                    weld.count.missing);
        EXPECT_EQ(weld.count.missing, 0) << weld.what;
        EXPECT_GE(weld.count.shared, weld.at_least) << weld.what;
    }
}

/// Areas of the quarter body's plane parts from the dimensions of hopper_wagon.geo
/// (cases/hopper_wagon/README.md): the saddle and the hopper slope sheets are inclined at
/// alpha, so their area is their plan area / cos(alpha); the walls are the rectangles less the
/// parts below the slope sheets' edges. Ten frames: a rib (a parallelogram with vertical
/// ends, b wide in plan and d_rib / cos(alpha) high) and a stanchion from the hinge box to
/// the wall top at each; the two door posts continue from the box down to their ribs' lower
/// ends; the hinge beam is a box of three plates w_hinge wide over the length a.
std::map<std::string, double> part_areas() {
    const double a = 6.33, b = 1.5, z_top = 3.5, z_sill = 0.9, x_mid = 0.35, x_end = 5.78;
    const double z_hinge = 1.6, z_pivot = 1.0, y_bolster = 1.0, y_ridge = 0.2;
    const double w_chord = 0.2, d_tie = 0.2; // top chord flange width, tie depth (five ties)
    const double d_rib = 0.15, w_stanchion = 0.15, w_hinge = 0.3; // ten frames
    const double alpha = 49.0 * std::numbers::pi / 180.0;
    const double t = std::tan(alpha), c = std::cos(alpha);
    const double d = a - x_end;            // end slope sheet, plan leg
    const double z_ridge = z_sill + b * t; // saddle ridge height
    const double door = (x_end - x_mid) * (z_hinge - z_sill);
    return {
        {"ridge", a * y_ridge / c},
        {"slope_sheet", (a * b - x_mid * x_mid / 2 - d * d / 2 - a * y_ridge) / c},
        {"middle_slope_sheet", x_mid * x_mid / (2 * c)},
        {"end_slope_sheet", d * d / (2 * c)},
        {"door", door},
        {"side_wall", a * (z_top - z_sill) - t * (x_mid * x_mid + d * d) / 2 - door},
        {"end_wall", b * (z_top - z_sill) - t * (b * b - d * d) / 2 - t * d * d},
        {"bolster", (z_ridge - z_pivot) * y_bolster - t * y_bolster * y_bolster / 2},
        {"top_chord", a * w_chord + w_chord * (b + w_chord)},
        {"tie", 5 * b * d_tie},
        {"rib", 10 * b * d_rib / c},
        {"stanchion", 10 * w_stanchion * (z_top - z_hinge - w_hinge) +
                          2 * w_stanchion * (z_hinge - z_sill + d_rib / c)},
        {"hinge_beam", 3 * a * w_hinge},
    };
}

/// Sum of the reaction forces of the shell block in the last frame of a run.
Vec3 total_reaction(const std::string& vtm) {
    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(vtm.c_str());
    reader->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    auto* shell = vtkDataSet::SafeDownCast(blocks->GetBlock(0));
    vtkDataArray* reaction = shell->GetPointData()->GetArray("reaction_force");
    Vec3 sum = Vec3::Zero();
    for (vtkIdType k = 0; k < reaction->GetNumberOfTuples(); ++k) {
        for (int d = 0; d < 3; ++d) {
            sum(d) += reaction->GetComponent(k, d);
        }
    }
    return sum;
}

// Equilibrium of the quarter body under gravity: the bogie pivot carries the weight
// rho g sum(A t) (thicknesses of wagon_gravity.toml, areas of the plane parts), and the
// symmetry planes' horizontal reactions cancel. The consistent gravity load of a bilinear
// element integrates rho t g over its exact area, and the mesh tiles the plane polygons
// exactly, so the only difference is the direct solver's round-off and the deck's printed
// digits (1e-9): 1e-6 of the weight leaves margin without hiding a lost element (the
// smallest part, the middle slope sheet, is 0.4 % of the weight).
constexpr double kEquilibrium = 1e-6;

void expect_reactions_equal_weight(const std::string& dir, const std::string& case_name) {
    const std::string out = dir + "/" + case_name;
    const CliResult run = run_cli("run '" + out + ".toml' --out '" + out + "'", out + ".log");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const std::map<std::string, double> thickness = {{"side_wall", 5e-3},
                                                     {"end_wall", 5e-3},
                                                     {"slope_sheet", 6e-3},
                                                     {"middle_slope_sheet", 6e-3},
                                                     {"end_slope_sheet", 6e-3},
                                                     {"ridge", 8e-3},
                                                     {"door", 6e-3},
                                                     {"bolster", 12e-3},
                                                     {"top_chord", 10e-3},
                                                     {"tie", 10e-3},
                                                     {"rib", 8e-3},
                                                     {"stanchion", 8e-3},
                                                     {"hinge_beam", 10e-3}};
    double weight = 0.0;
    for (const auto& [part, area] : part_areas()) {
        weight += 7850.0 * 9.81 * area * thickness.at(part);
    }
    const Vec3 reaction = total_reaction(frame_path(out, case_name, 1));
    std::printf("%s: sum of reactions (%.3e, %.3e, %.6f) N, weight %.6f N, relative "
                "difference %.2e\n",
                case_name.c_str(), reaction.x(), reaction.y(), reaction.z(), weight,
                reaction.z() / weight - 1.0);
    EXPECT_NEAR(reaction.z(), weight, kEquilibrium * weight);
    EXPECT_NEAR(reaction.x(), 0.0, kEquilibrium * weight);
    EXPECT_NEAR(reaction.y(), 0.0, kEquilibrium * weight);
}

TEST(HopperWagon, SelfWeightReactionsEqualTheWeight) {
    const std::string dir = case_copy("gravity");
    expect_reactions_equal_weight(dir, "wagon_gravity"); // meshes hopper_wagon.geo first
    export_deck(dir);
    expect_reactions_equal_weight(dir, "wagon_gravity_k");
}

// The load's pressure on the stiffened body (wagon_pressure.toml, the deck in three parts):
// the supports carry the pressures' resultant, p A n over the two loaded parts, A the plane
// polygons' areas and n their unit normals (into the load: the slope sheets' (0, sin alpha,
// cos alpha), the side wall's (0, -1, 0)), so the reactions are -(p_s A_s n_s + p_w A_w n_w)
// with p the case's (negative) values. The consistent pressure load of a bilinear element
// integrates p n over its exact area and the mesh tiles the polygons exactly: the difference
// is round-off and the deck's printed digits, as for the weight (kEquilibrium).
TEST(HopperWagon, PressureReactionsEqualThePressureResultant) {
    const std::string dir = case_copy("pressure");
    shell_mesh(dir + "/wagon_gravity.toml"); // meshes the .geo
    export_deck(dir);
    const std::string out = dir + "/wagon_pressure";
    const CliResult run = run_cli("run '" + out + ".toml' --out '" + out + "'", out + ".log");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const std::string summary = read_file(out + "/summary.json");
    const double alpha = 49.0 * std::numbers::pi / 180.0;
    const double p_slope = -30e3, p_wall = -15e3; // Pa, wagon_pressure.toml
    const std::map<std::string, double> area = part_areas();
    const Vec3 load = p_slope * area.at("slope_sheet") * Vec3(0, std::sin(alpha), std::cos(alpha)) +
                      p_wall * area.at("side_wall") * Vec3(0, -1, 0);
    const Vec3 reaction(result_value(summary, "support_reaction_x"),
                        result_value(summary, "support_reaction_y"),
                        result_value(summary, "support_reaction_z"));
    std::printf("wagon_pressure: reactions (%.3e, %.6f, %.6f) N, pressure resultant (%.6f, "
                "%.6f) N\n",
                reaction.x(), reaction.y(), reaction.z(), -load.y(), -load.z());
    const double scale = load.norm();
    EXPECT_NEAR(reaction.x(), 0.0, kEquilibrium * scale);
    EXPECT_NEAR(reaction.y(), -load.y(), kEquilibrium * scale);
    EXPECT_NEAR(reaction.z(), -load.z(), kEquilibrium * scale);
}

} // namespace
