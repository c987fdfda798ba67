// Fuzz harness: the case-file parser with units (io/case_document.cpp, io/case_table.cpp,
// io/units.cpp), the [case] settings and the material library. The input is a case file; a
// line "--set KEY=VALUE" in it is also applied as a command-line override, and every line is
// also read as a quantity, a quantity list and a unit. Bad input must end in io::CaseError
// (exit code 2) and nothing else: any other exception, a crash or a sanitizer report is a
// finding. See tests/fuzz/README.md.

#include "io/case_table.hpp"
#include "io/scene_settings.hpp"
#include "io/units.hpp"
#include "materials/material_library.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

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
    auto document = io::CaseDocument::from_string(text, "fuzz.toml");
    for (std::size_t at = text.find("--set "); at != std::string_view::npos;
         at = text.find("--set ", at + 1)) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        document->set(text.substr(at + 6, end - at - 6));
    }
    const io::SceneSettings settings = io::read_scene_settings(*document, "fuzz");
    (void)settings;
    const auto materials = materials::MaterialLibrary::from_case(document->root());
    (void)materials;
    document->reject_unknown_keys();
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
