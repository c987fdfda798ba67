// Fuzz harness: the LS-DYNA keyword readers: the deck (io/keyword_deck.cpp; *INCLUDE resolves
// in a directory that does not exist), its mesh cards (io/keyword_mesh.cpp,
// io/keyword_fields.cpp), the shell mesh made from them (fem/keyword_shell_reader.cpp) and the
// unit system named on the first line (io/keyword_units.cpp). Bad input must end in
// std::invalid_argument (io::KeywordError is one), which the case readers turn into exit code
// 2, and nothing else. See
// tests/fuzz/README.md.

#include "fem/keyword_shell_reader.hpp"
#include "io/keyword_deck.hpp"
#include "io/keyword_mesh.hpp"
#include "io/keyword_units.hpp"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace grainload;
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::string error;
    const auto units =
        io::parse_keyword_units(std::string_view(text).substr(0, text.find('\n')), &error);
    try {
        std::istringstream in(text);
        const io::KeywordDeck deck =
            io::read_keyword_deck(in, "fuzz.k", "/nonexistent-grainload-fuzz-directory");
        const io::KeywordMesh mesh =
            io::read_keyword_mesh(deck, units.value_or(io::KeywordUnits{}));
        if (!mesh.shells.empty()) {
            (void)fem::make_keyword_shell_mesh(mesh, {});
        }
    } catch (const std::invalid_argument&) { // KeywordError, and what the mesh checks throw
    }
    return 0;
}
