// Fuzz harness: the checkpoint reader (io/checkpoint_file.cpp: framing and checksum;
// app/checkpoint.cpp: the clock; each module's read_checkpoint) on the scene of
// tests/fuzz/checkpoint_scene.toml, which holds every module that keeps state. The first byte
// of an input picks what the rest is:
//   even: a payload, framed here with the right length and checksum, so that the modules'
//         readers see the mutations (a checksum would stop nearly all of them at the door);
//   odd:  a whole checkpoint file as it lies on disk (framing, checksum, truncation).
// Bad input must end in io::CaseError (exit code 2) and nothing else; an accepted checkpoint
// must leave a scene whose every array the frame writer and the diagnosis can walk. The scene is
// built once per process; every input starts from the same pristine state (the scene as built,
// with its own checkpoint read back), so that what an input does depends on it alone and not on
// the inputs before it. See tests/fuzz/README.md.

#include "app/checkpoint.hpp"
#include "io/case_error.hpp"
#include "io/checkpoint_file.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>

namespace {

struct FuzzScene {
    std::unique_ptr<grainload::app::Scene> scene;
    std::string pristine; ///< a whole checkpoint file of the scene as built
};

/// Inputs run, and those after which the scene was built anew (see restore()) because the
/// pristine checkpoint was refused or was read but did not restore every byte; printed at exit.
long long inputs_run = 0;
long long refused_pristine = 0;
long long differed_from_pristine = 0;

void print_rebuilds() {
    std::fprintf(stderr,
                 "fuzz_checkpoint: %lld inputs; a new scene after %lld (the pristine checkpoint "
                 "refused) and %lld (read, but the scene's checkpoint differed from it)\n",
                 inputs_run, refused_pristine, differed_from_pristine);
}

/// The scene as built, with its own checkpoint read back: the state every input starts from.
/// (Reading a checkpoint sets the solver's neighbour list from the checkpoint's reference
/// positions, so a scene only built would differ from a restored one.)
std::unique_ptr<grainload::app::Scene> pristine_scene(const std::string& pristine) {
    auto scene =
        grainload::app::Scene::load(GRAINLOAD_SOURCE_DIR "/tests/fuzz/checkpoint_scene.toml", {});
    if (!pristine.empty()) {
        (void)grainload::app::read_checkpoint_bytes(*scene, pristine);
    }
    return scene;
}

FuzzScene& fuzz_scene() {
    static FuzzScene state = [] {
        FuzzScene s;
        s.scene = pristine_scene({});
        grainload::app::RunClock clock;
        clock.frame_times = {0.0};
        s.pristine = grainload::app::checkpoint_bytes(*s.scene, clock);
        s.scene = pristine_scene(s.pristine);
        return s;
    }();
    return state;
}

/// Back to the pristine state after an input: the pristine checkpoint read back, which must
/// then write itself out byte for byte. A checkpoint refused halfway may have left arrays of
/// another length or created and removed particles, from which the scene cannot go back (the
/// CLI exits then); only that costs a new scene.
void restore(FuzzScene& state) {
    try {
        const grainload::app::RunClock clock =
            grainload::app::read_checkpoint_bytes(*state.scene, state.pristine);
        if (grainload::app::checkpoint_bytes(*state.scene, clock) == state.pristine) {
            return;
        }
        ++differed_from_pristine;
    } catch (const grainload::io::CaseError&) {
        ++refused_pristine;
    }
    state.scene = pristine_scene(state.pristine);
}

void touch_every_array(const grainload::app::Scene& scene) {
    grainload::io::Frame frame;
    for (const auto& stepper : scene.steppers) {
        (void)stepper->stable_time_step();
        (void)stepper->diagnose();
    }
    for (const grainload::io::Reporter* reporter : scene.reporters) {
        reporter->append_blocks(frame);
        std::vector<grainload::io::ResultFigure> results;
        reporter->append_results(0.0, results);
    }
}

} // namespace

/// The seed inputs: the pristine checkpoint as a payload (first byte 0) and as a file (1).
std::string grainload_fuzz_checkpoint_seed(bool whole_file) {
    const std::string& file = fuzz_scene().pristine;
    if (whole_file) {
        return '\1' + file;
    }
    // Magic (8 bytes) in front, length and checksum (16) behind.
    return '\0' + file.substr(8, file.size() - 24);
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::atexit(print_rebuilds);
    if (const char* path = std::getenv("GRAINLOAD_FUZZ_WRITE_SEEDS")) {
        std::ofstream(std::string(path) + "/payload", std::ios::binary)
            << grainload_fuzz_checkpoint_seed(false);
        std::ofstream(std::string(path) + "/file", std::ios::binary)
            << grainload_fuzz_checkpoint_seed(true);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    FuzzScene& state = fuzz_scene();
    ++inputs_run;
    const std::string_view rest(reinterpret_cast<const char*>(data) + 1, size - 1);
    const std::string bytes =
        (data[0] & 1) != 0 ? std::string(rest) : grainload::io::frame_checkpoint(rest);
    try {
        (void)grainload::app::read_checkpoint_bytes(*state.scene, bytes);
        touch_every_array(*state.scene);
    } catch (const grainload::io::CaseError&) {
    }
    restore(state);
    return 0;
}
