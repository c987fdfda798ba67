// Replays a fuzz harness (FUZZ_NAME; its tests are FUZZ_SUITE.*) without libFuzzer, in the ordinary
// test suite: over the regression inputs of tests/fuzz/regressions/<name>/ (each an input that once
// crashed a reader, kept after the fix), over the repository's own files the fuzzer is seeded with
// (FUZZ_SEED_EXTENSION under cases/, tests/data/ and tests/fuzz/: the checkpoint scene is the
// smallest case with every module), and over deterministic damage to each
// seed: 16 truncations and 16 flipped bytes. The harness aborts (and the test fails) on any
// exception but the reader's own error, a crash or, in a sanitizer build, a sanitizer report.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
extern "C" __attribute__((weak)) int LLVMFuzzerInitialize(int* argc, char*** argv);
/// Defined by the checkpoint harness only: its seeds, which it makes from its own scene.
__attribute__((weak)) std::string grainload_fuzz_checkpoint_seed(bool whole_file);

namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void run(const std::string& input) {
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
}

std::vector<std::string> seeds() {
    std::vector<std::string> found;
    if (grainload_fuzz_checkpoint_seed != nullptr) {
        return {grainload_fuzz_checkpoint_seed(false), grainload_fuzz_checkpoint_seed(true)};
    }
    for (const char* root : {"cases", "tests/data", "tests/fuzz"}) {
        for (const auto& entry :
             fs::recursive_directory_iterator(fs::path(GRAINLOAD_SOURCE_DIR) / root)) {
            if (entry.is_regular_file() && entry.path().extension() == FUZZ_SEED_EXTENSION) {
                found.push_back(read_bytes(entry.path()));
            }
        }
    }
    return found;
}

TEST(FUZZ_SUITE, RegressionInputsSeedsAndDamagedSeedsRunClean) {
    if (LLVMFuzzerInitialize != nullptr) {
        int argc = 0;
        char** argv = nullptr;
        LLVMFuzzerInitialize(&argc, &argv);
    }
    int inputs = 0;
    const fs::path regressions =
        fs::path(GRAINLOAD_SOURCE_DIR) / "tests/fuzz/regressions" / FUZZ_NAME;
    if (fs::exists(regressions)) {
        for (const auto& entry : fs::directory_iterator(regressions)) {
            SCOPED_TRACE(entry.path().string());
            run(read_bytes(entry.path()));
            ++inputs;
        }
    }
    const auto all = seeds();
    for (const std::string& seed : all) {
        run(seed);
        constexpr std::size_t kCuts = 16;
        for (std::size_t k = 1; k <= kCuts && !seed.empty(); ++k) {
            run(seed.substr(0, seed.size() * k / (kCuts + 1)));
            std::string flipped = seed;
            // Keep byte 0 (the checkpoint harness's mode) and spread the others over the seed.
            const std::size_t at = 1 + (seed.size() - 1) * k / (kCuts + 1);
            if (at < flipped.size()) {
                flipped[at] = static_cast<char>(flipped[at] ^ 0x5a);
            }
            run(flipped);
            inputs += 2;
        }
        ++inputs;
    }
    std::cout << FUZZ_NAME << ": " << inputs << " inputs from " << all.size() << " seeds\n";
    // Every harness has seeds in the repository (or, for checkpoints, makes its own two).
    EXPECT_GE(all.size(), 2u);
}

} // namespace
