#include "coupling/coupling_schema.hpp"

#include "coupling/coupling_case_reader.hpp"

#include <array>

namespace grainload::coupling {

namespace {

constexpr std::string_view kGuide = "docs/user-guide/coupling.md";

const std::array<io::KeyTable, 3> kTables{{
    {"coupling", false, "how the sand and the shells exchange loads: window, iterations",
     kCouplingKeys, kGuide, "## `[coupling]`"},
    {"coupling.interface", true, "a shell part's face that the sand meets as a wall",
     kInterfaceKeys, kGuide, "## `[[coupling.interface]]`"},
    {"coupling.friction", true, "Coulomb friction between a body and a coupled part", kFrictionKeys,
     kGuide, "## `[[coupling.friction]]`"},
}};

} // namespace

std::span<const io::KeyTable> coupling_key_tables() {
    return kTables;
}

} // namespace grainload::coupling
