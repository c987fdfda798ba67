// Fuzz harness: the Gmsh 4.1 ASCII readers, io's (io/gmsh_file.cpp, surfaces for walls and
// bodies: io/gmsh_surface_reader.cpp) and the shell FEM's (fem/gmsh_reader.cpp, physical
// groups to node and element sets). Bad input must end in std::invalid_argument (which the
// case readers turn into exit code 2) and nothing else. See tests/fuzz/README.md.

#include "fem/gmsh_reader.hpp"
#include "io/gmsh_file.hpp"
#include "io/gmsh_surface_reader.hpp"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        std::istringstream in(text);
        (void)grainload::io::read_gmsh_file_content(in, "fuzz.msh");
    } catch (const std::invalid_argument&) {
    }
    try {
        (void)grainload::io::read_gmsh_surface(text, "fuzz.msh");
    } catch (const std::invalid_argument&) {
    }
    try {
        std::istringstream in(text);
        (void)grainload::fem::read_gmsh(in, 0.001);
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
