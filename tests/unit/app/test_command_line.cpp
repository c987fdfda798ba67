// The CLI's help, and input it must refuse before doing anything.

#include "support/cli_runner.hpp"
#include "support/test_folder.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <thread>

namespace {

using namespace grainload::testing;

const std::string kFreeFall = "'" + source_path("cases/free_fall/free_fall_small.toml") + "'";

/// One log per test: ctest runs the tests of this file side by side.
std::string log_file() {
    return grainload::testing::process_folder() + "command_line_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".log";
}

// Every way of asking for help prints a usage and exits with 0, whatever else is on the line.
TEST(CommandLine, HelpPrintsTheUsageAndExitsWithZero) {
    for (const char* line : {"--help", "-h", "help", ""}) {
        const auto result = run_cli(line, log_file());
        EXPECT_EQ(result.exit_code, 0) << line << "\n" << result.output;
        EXPECT_NE(result.output.find("grainload run CASE.toml"), std::string::npos) << line;
        EXPECT_NE(result.output.find("exit codes: 0 done"), std::string::npos) << line;
    }
    for (const char* command : {"run", "check", "matpoint", "version", "help"}) {
        for (const std::string& line :
             {std::string("help ") + command, std::string(command) + " --help"}) {
            const auto result = run_cli(line, log_file());
            EXPECT_EQ(result.exit_code, 0) << line << "\n" << result.output;
            EXPECT_EQ(result.output.rfind("usage: grainload", 0), 0u) << line << result.output;
        }
    }
    const auto run_help = run_cli("run " + kFreeFall + " --threads 2 -h", log_file());
    EXPECT_EQ(run_help.exit_code, 0) << run_help.output;
    EXPECT_NE(run_help.output.find("--restart FILE"), std::string::npos) << run_help.output;
}

// --threads auto runs on the cores other work leaves free (at least one, at most all): which
// count depends on the machine's load, so the test bounds it; a word other than "auto" is
// refused naming both forms.
TEST(CommandLine, ThreadsAutoRunsOnTheFreeCoresAndOtherWordsAreRefused) {
    const std::string out = test_folder("threads_auto");
    const auto result =
        run_cli("run " + kFreeFall + " --threads auto --out '" + out + "'", log_file());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::ifstream log(out + "/log.txt");
    std::string first;
    std::getline(log, first);
    const std::smatch threads = [&] {
        std::smatch m;
        std::regex_search(first, m,
                          std::regex(R"(, (\d+) threads? \(auto: the cores free at start\))"));
        return m;
    }();
    ASSERT_FALSE(threads.empty()) << first;
    const int count = std::stoi(threads[1].str());
    EXPECT_GE(count, 1);
    EXPECT_LE(count, static_cast<int>(std::thread::hardware_concurrency()));
    const auto bad = run_cli("run " + kFreeFall + " --threads many", log_file());
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("--threads expects a positive integer or 'auto', got 'many'"),
              std::string::npos)
        << bad.output;
    std::filesystem::remove_all(out);
}

// `help keys` lists the tables; `help keys TABLE` (with or without its brackets) prints the
// declared keys of that table with their defaults; a table nobody declares is a bad line.
TEST(CommandLine, HelpKeysPrintsTheDeclaredTablesAndTheirKeys) {
    const auto tables = run_cli("help keys", log_file());
    EXPECT_EQ(tables.exit_code, 0) << tables.output;
    EXPECT_NE(tables.output.find("[[sph.source]]"), std::string::npos) << tables.output;
    EXPECT_NE(tables.output.find("[case]"), std::string::npos) << tables.output;
    const auto source = run_cli("help keys '[[sph.source]]'", log_file());
    EXPECT_EQ(source.exit_code, 0) << source.output;
    EXPECT_NE(source.output.find("mass_rate  (mass rate; default: required)"), std::string::npos)
        << source.output;
    EXPECT_NE(source.output.find("velocity  (velocity vector; default: 0 m/s)"), std::string::npos)
        << source.output;
    const auto unknown = run_cli("help keys sph.sauce", log_file());
    EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("no table 'sph.sauce'"), std::string::npos) << unknown.output;
}

// `check` states what it will model, and with it the sound speed of the artificial viscosity's
// linear term, which sets how much it dissipates: the 2D collapse's material (E = 5.84 MPa,
// nu = 0.3, rho = 2040 kg/m^3) has the P-wave speed sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu)) / rho)
// = 62.1 m/s; a pinned sound_speed is stated as given.
TEST(CommandLine, CheckStatesTheModelAndTheViscositysSoundSpeed) {
    const std::string collapse =
        "'" + source_path("cases/column_collapse_2d/column_collapse_2d_small.toml") + "'";
    const auto own = run_cli("check " + collapse, log_file());
    ASSERT_EQ(own.exit_code, 0) << own.output;
    const double e = 5.84e6, nu = 0.3, rho = 2040.0;
    const double c = std::sqrt(e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)) / rho);
    char expected[64];
    std::snprintf(expected, sizeof expected, "aluminium_bars %.3g m/s", c);
    EXPECT_NE(own.output.find("model: dimension: plane strain;"), std::string::npos) << own.output;
    EXPECT_NE(own.output.find("artificial viscosity: alpha 0.1, beta 0.1, c = each material's "
                              "P-wave speed before its stiffness_scale: " +
                              std::string(expected)),
              std::string::npos)
        << own.output;
    const auto pinned =
        run_cli("check " + collapse + " --set 'sph.artificial_viscosity.sound_speed=\"50 m/s\"'",
                log_file());
    ASSERT_EQ(pinned.exit_code, 0) << pinned.output;
    EXPECT_NE(pinned.output.find("alpha 0.1, beta 0.1, c = 50 m/s (sound_speed)"),
              std::string::npos)
        << pinned.output;
}

TEST(CommandLine, HelpOnAnUnknownCommandIsABadCommandLine) {
    const auto result = run_cli("help simulate", log_file());
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("no help on 'simulate'"), std::string::npos) << result.output;
}

TEST(CommandLine, ADirectoryAsTheCaseIsRefusedByName) {
    const std::string directory = source_path("cases/free_fall");
    for (const char* command : {"run", "check"}) {
        const auto result = run_cli(std::string(command) + " '" + directory + "'", log_file());
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_NE(result.output.find(directory + ": is a directory; expected a case file"),
                  std::string::npos)
            << result.output;
    }
    const auto missing = run_cli("check /nonexistent/case.toml", log_file());
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.output.find("cannot open the case file (No such file or directory)"),
              std::string::npos)
        << missing.output;
}

// A new user's mistake: a spacing of 1e-7 m in the 0.1 x 0.1 x 0.2 m free-fall
// block is (1e6)^2 x 2e6 = 2e18 particles, which no machine holds. It must be refused at once
// (before the lattice is made: the test would otherwise end in std::bad_alloc or run out of
// time) with exit code 2, naming the key, the estimate and a spacing that fits.
TEST(CommandLine, ASceneBeyondTheMachinesMemoryIsRefusedBeforeAllocating) {
    for (const char* command : {"run", "check"}) {
        const auto result = run_cli(std::string(command) + " " + kFreeFall +
                                        " --set 'sph.body[0].spacing=1e-7 m' --out '" +
                                        grainload::testing::process_folder() + "refused'",
                                    log_file());
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_NE(result.output.find("key 'sph.body[0].spacing'"), std::string::npos)
            << result.output;
        EXPECT_NE(result.output.find("about 2e+18 SPH particles"), std::string::npos)
            << result.output;
        EXPECT_NE(result.output.find("MemAvailable"), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("expected a spacing of at least about"), std::string::npos)
            << result.output;
    }
    EXPECT_FALSE(
        std::filesystem::exists(grainload::testing::process_folder() + "refused/checkpoint.bin"));
}

// The same for shells: a generated plate of 100000 x 100000 elements has (1e5 + 1)^2 = 1.00002e10
// nodes, 6 DOFs each at 4.4e3 bytes per DOF (app/cost_estimate.hpp), 2.64e14 bytes = 2.46e5
// GiB. Before the guard counted shells, `check` went on to make the mesh (a hang, then
// std::bad_alloc); the fuzz harness of the case reader keeps the input
// (tests/fuzz/regressions/case/shell_elements_beyond_memory).
TEST(CommandLine, AShellBeyondTheMachinesMemoryIsRefusedBeforeAllocating) {
    const std::string scene = "'" + source_path("tests/fuzz/checkpoint_scene.toml") + "'";
    const auto result = run_cli("check " + scene +
                                    " --set 'fem.shell[0].elements_x=100000'"
                                    " --set 'fem.shell[0].elements_y=100000'",
                                log_file());
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("key 'fem.shell[0].elements_x'"), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("about 2.46e+05 GiB (the largest, fem.shell[0], about 1e+10 "
                                 "nodes)"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("MemAvailable"), std::string::npos) << result.output;
}

// And for the wall particles a [[coupling.interface]] lays on its shell, which the guard above
// cannot count without the mesh: the one-element plate stretched to 80 mm x 300 km under sand at
// 10 mm is a single quadrangle sampled at ceil(80/10) + 1 = 9 by ceil(3e8/10) + 1 = 3e7 + 1
// points, 2.7e8 particles at 903 bytes (sph/particle_estimate.hpp), about 230 GiB. Before the
// coupling reader counted them, `check` sampled the plate (the fuzz harness kept a hang at
// 1.6 GiB; tests/fuzz/regressions/case/interface_wall_beyond_memory).
TEST(CommandLine, AnInterfaceWallBeyondTheMachinesMemoryIsRefusedBeforeAllocating) {
    const std::string scene = "'" + source_path("tests/fuzz/checkpoint_scene.toml") + "'";
    const auto result = run_cli("check " + scene +
                                    " --set 'fem.shell[0].length_y=300 km'"
                                    " --set 'sph.body[0].spacing=10 mm'",
                                log_file());
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("key 'coupling.interface[0].part'"), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("about 2.7e+08 wall particles on its 1 elements (1 layers at "
                                 "0.01 m)"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("MemAvailable"), std::string::npos) << result.output;
}

// The plane-strain strip under sand went unstable with relaxation 0.5 and its 10 ms windows
// (the interface energy watchdog stopped it at 0.31 s, docs/validation/coupling.md) and is at
// rest with 0.3, the case's setting. The estimate puts the shortest stable window at 9.53 ms for
// 0.5 and 6.9 ms for 0.3: the first run is warned about before it starts, the case is not. The
// warning says what clears it: a window of 1.25 x 9.53 ms = 11.9 ms (rounded up: 0.012 s), or
// the relaxation whose estimate is 10 ms / 1.25; the estimate goes as 1 / sqrt(2 / omega - 1)
// (coupling/window_limits.hpp), so 2 / omega - 1 = 3 x (1.25 x 9.53 / 10)^2 = 4.257 and omega =
// 0.380 (rounded down: 0.38).
TEST(CommandLine, AStaticWindowWithinTheEstimatesUncertaintyIsWarnedAbout) {
    const std::string strip =
        "'" + source_path("cases/sand_on_plate/sand_on_strip_small.toml") + "'";
    const auto unstable = run_cli("check " + strip + " --set coupling.relaxation=0.5", log_file());
    EXPECT_EQ(unstable.exit_code, 0) << unstable.output;
    EXPECT_NE(unstable.output.find("grainload: warning: the coupling window 0.01 s is 1.05 times "
                                   "the shortest stable staggered window"),
              std::string::npos)
        << unstable.output;
    EXPECT_NE(unstable.output.find("window = \"0.012 s\" or longer, relaxation = 0.38 or less, "
                                   "added_mass = 4 or max_iterations = 2"),
              std::string::npos)
        << unstable.output;
    const auto stable = run_cli("check " + strip, log_file());
    EXPECT_EQ(stable.exit_code, 0) << stable.output;
    EXPECT_EQ(stable.output.find("warning"), std::string::npos) << stable.output;
}

// A coupled shell's own loads ramped over the run (load_time defaults to end_time) are warned
// about: the tipping cone's plate takes its weight over 10 ms (two windows of its 1 s run), no
// warning; over 1 s, the warning names load_time and proposes one window (5 ms).
TEST(CommandLine, ACoupledShellsWeightRampedOverTheRunIsWarnedAbout) {
    const std::string cone = "'" + source_path("cases/tipping_cone/tipping_cone.toml") + "'";
    const auto at_once = run_cli("check " + cone, log_file());
    EXPECT_EQ(at_once.exit_code, 0) << at_once.output;
    EXPECT_EQ(at_once.output.find("load_time"), std::string::npos) << at_once.output;
    const auto ramped = run_cli("check " + cone + " --set 'fem.load_time=\"1 s\"'", log_file());
    EXPECT_EQ(ramped.exit_code, 0) << ramped.output;
    EXPECT_NE(ramped.output.find("grow linearly until [fem] load_time = 1 s"), std::string::npos)
        << ramped.output;
    EXPECT_NE(ramped.output.find("set load_time to one window (0.005 s)"), std::string::npos)
        << ramped.output;
}

// The added mass lifts the static window's lower limit: with beta (2 / omega - 1) >= 1 the
// estimate has none (coupling/window_limits.hpp). The flexible silo of the bad cases, refused
// at its 5 ms window (shortest stable window 20.6 ms at relaxation 0.5), passes the check with
// added_mass = 4 (beta T = 12), and the check says the window has no lower limit; at 0.25
// (beta T = 0.75) the limit is sqrt(1 - 0.75) = half of it, 10.3 ms, and 5 ms is still refused.
TEST(CommandLine, TheAddedMassLetsAStaticWindowOfAnyLengthPass) {
    const std::string silo =
        "'" + source_path("tests/data/bad_cases/coupling_window_flexible_silo.toml") + "'";
    const auto refused = run_cli("check " + silo, log_file());
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_NE(refused.output.find("added_mass = 4"), std::string::npos) << refused.output;
    const auto held = run_cli("check " + silo + " --set coupling.added_mass=4", log_file());
    EXPECT_EQ(held.exit_code, 0) << held.output;
    EXPECT_NE(held.output.find("has no shortest stable window"), std::string::npos) << held.output;
    // The springs' lag, window + beta m_s C / window, from the areal mass and compliance the
    // refusal names (5 ms, beta 4: 1.024 s, beyond a tenth of the 1 s run, so warned about
    // with its shortest value 2 sqrt(beta m_s C) at the window sqrt(beta m_s C)); to the
    // printed digits (1e-5).
    std::smatch named;
    ASSERT_TRUE(std::regex_search(refused.output, named,
                                  std::regex("areal mass ([0-9.e+-]+) kg/m\\^2 against the "
                                             "shell's compliance ([0-9.e+-]+) m/Pa")))
        << refused.output;
    const double mass_compliance = std::stod(named[1]) * std::stod(named[2]);
    const double lag = 0.005 + 4.0 * mass_compliance / 0.005;
    std::smatch printed;
    ASSERT_TRUE(std::regex_search(held.output, printed,
                                  std::regex("within about ([0-9.e+-]+) s \\(window \\+")))
        << held.output;
    EXPECT_NEAR(std::stod(printed[1]) / lag, 1.0, 1e-5) << held.output;
    ASSERT_TRUE(std::regex_search(held.output, printed,
                                  std::regex("shortest, ([0-9.e+-]+) s, at a window of "
                                             "([0-9.e+-]+) s")))
        << held.output;
    EXPECT_NEAR(std::stod(printed[1]) / (2.0 * std::sqrt(4.0 * mass_compliance)), 1.0, 1e-5);
    EXPECT_NEAR(std::stod(printed[2]) / std::sqrt(4.0 * mass_compliance), 1.0, 1e-5);
    EXPECT_NE(held.output.find("added mass: the shell follows a change of the load within about"),
              std::string::npos)
        << held.output;
    const auto weak = run_cli("check " + silo + " --set coupling.added_mass=0.25", log_file());
    EXPECT_EQ(weak.exit_code, 2) << weak.output;
    EXPECT_NE(weak.output.find("about 0.0103"), std::string::npos) << weak.output;
}

} // namespace
