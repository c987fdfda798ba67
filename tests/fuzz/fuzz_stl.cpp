// Fuzz harness: the STL reader, ASCII and binary (io/stl_reader.cpp). Bad input must end in
// std::invalid_argument (which the case readers turn into exit code 2) and nothing else. See
// tests/fuzz/README.md.

#include "io/stl_reader.hpp"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        (void)grainload::io::read_stl(std::string(reinterpret_cast<const char*>(data), size),
                                      "fuzz.stl");
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
