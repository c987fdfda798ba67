// Fuzz harness: the checkpoint reader (io/checkpoint_file.cpp: framing and checksum;
// app/checkpoint.cpp: the clock; each module's read_checkpoint) on the scene of
// tests/fuzz/checkpoint_scene.toml, which holds every module that keeps state. The first byte
// of an input picks what the rest is:
//   even: a payload, framed here with the right length and checksum, so that the modules'
//         readers see the mutations (a checksum would stop nearly all of them at the door);
//   odd:  a whole checkpoint file as it lies on disk (framing, checksum, truncation).
// Bad input must end in io::CaseError (exit code 2) and nothing else; an accepted checkpoint
// must leave a scene whose every array the frame writer and the diagnosis can walk. After each
// input the scene is restored from the checkpoint of its pristine state. See
// tests/fuzz/README.md.

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
    std::string pristine; ///< a whole checkpoint file of the scene as loaded
};

std::unique_ptr<grainload::app::Scene> load_scene() {
    return grainload::app::Scene::load(GRAINLOAD_SOURCE_DIR "/tests/fuzz/checkpoint_scene.toml",
                                       {});
}

FuzzScene& fuzz_scene() {
    static FuzzScene state = [] {
        FuzzScene s;
        s.scene = load_scene();
        grainload::app::RunClock clock;
        clock.frame_times = {0.0};
        s.pristine = grainload::app::checkpoint_bytes(*s.scene, clock);
        return s;
    }();
    return state;
}

void touch_every_array(const grainload::app::Scene& scene) {
    grainload::io::Frame frame;
    for (const auto& stepper : scene.steppers) {
        (void)stepper->stable_time_step();
        (void)stepper->diagnose();
        stepper->append_blocks(frame);
        std::vector<grainload::io::ResultFigure> results;
        stepper->append_results(0.0, results);
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
    const std::string_view rest(reinterpret_cast<const char*>(data) + 1, size - 1);
    const std::string bytes =
        (data[0] & 1) != 0 ? std::string(rest) : grainload::io::frame_checkpoint(rest);
    try {
        (void)grainload::app::read_checkpoint_bytes(*state.scene, bytes);
        touch_every_array(*state.scene);
    } catch (const grainload::io::CaseError&) {
    }
    // Back to the pristine state. A refused checkpoint may have left arrays of another length
    // (the CLI exits then; here the scene is built anew), but the pristine one must then be
    // accepted.
    try {
        (void)grainload::app::read_checkpoint_bytes(*state.scene, state.pristine);
    } catch (const grainload::io::CaseError&) {
        state.scene = load_scene();
        (void)grainload::app::read_checkpoint_bytes(*state.scene, state.pristine);
    }
    return 0;
}
