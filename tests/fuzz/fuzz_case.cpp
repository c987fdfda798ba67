// Fuzz harness: a case file read the way `grainload check` reads it (app/scene.cpp
// Scene::from_document, app/cost_estimate.cpp): the parser with units (io/case_document.cpp,
// io/case_table.cpp, io/units.cpp), the [case] settings, the material library, the memory
// guard, the module readers ([sph] with its bodies, walls, sources, sinks and settle watch;
// [fem]; [coupling]), the figure references and the cost estimate. Nothing steps in time. The
// input is a case file; a line "--set KEY=VALUE" in it is also applied as a command-line
// override, and every line is also read as a quantity, a quantity list and a unit. Bad input
// must end in io::CaseError (exit code 2) and nothing else: any other exception, a crash or a
// sanitizer report is a finding. See tests/fuzz/README.md.

#include "app/cost_estimate.hpp"
#include "app/scene.hpp"
#include "io/case_table.hpp"
#include "io/units.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

/// The memory the harness lets a scene take, in place of the machine's (MemAvailable): the
/// memory guard refuses, with io::CaseError, a scene of more than about 18 000 SPH particles
/// (sph/particle_estimate.hpp: 903 bytes each), so that every input builds in milliseconds and
/// a mutated spacing cannot ask for gigabytes. The seeds' own small cases fit.
constexpr double kSceneBudgetBytes = 16.0 * 1024.0 * 1024.0;

/// The case's directory, which does not exist: a mesh or geometry file the input names is
/// "not found" (io::CaseError), so the harness reads no file and runs no Gmsh. The mesh readers
/// have harnesses of their own (fuzz_gmsh, fuzz_stl, fuzz_keyword).
constexpr const char* kCaseFile = "/nonexistent-grainload-fuzz/fuzz.toml";

void read_lines_as_quantities(std::string_view text) {
    std::string error;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, end - start);
        (void)grainload::io::parse_quantity(line, &error);
        (void)grainload::io::parse_quantity_list(line, &error);
        (void)grainload::io::parse_unit(line, &error);
        start = end + 1;
    }
}

void read_case(std::string_view text) {
    using namespace grainload;
    auto document = io::CaseDocument::from_string(text, kCaseFile);
    for (std::size_t at = text.find("--set "); at != std::string_view::npos;
         at = text.find("--set ", at + 1)) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        document->set(text.substr(at + 6, end - at - 6));
    }
    const auto scene = app::Scene::from_document(std::move(document), "fuzz", kSceneBudgetBytes);
    const app::Calibration calibration;
    (void)app::describe_cost(app::estimate_cost(*scene, 1, calibration));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    read_lines_as_quantities(text);
    try {
        read_case(text);
    } catch (const grainload::io::CaseError&) {
    }
    return 0;
}
