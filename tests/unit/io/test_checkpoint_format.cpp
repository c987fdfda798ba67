#include "io/case_error.hpp"
#include "io/checkpoint_file.hpp"

#include <gtest/gtest.h>
#include <string>
#include <utility>

namespace grainload::io {
namespace {

// A checkpoint of an earlier format is refused with what to do, before a byte of its payload
// is read as the present one: each format changed what the payload holds.
TEST(CheckpointFormat, EachEarlierFormatIsRefusedNamingIt) {
    const std::string current = frame_checkpoint("payload");
    EXPECT_EQ(current.substr(0, 8), "GLCKPT06");
    for (const auto& [magic, words] :
         {std::pair<std::string, std::string>{"GLCKPT05", "fifth checkpoint format"},
          {"GLCKPT04", "fourth checkpoint format"},
          {"GLCKPT03", "third checkpoint format"},
          {"GLCKPT02", "second checkpoint format"}}) {
        std::string old = current;
        old.replace(0, 8, magic);
        bool read = false;
        try {
            read_checkpoint_bytes(old, "run/checkpoint.bin",
                                  [&read](std::istream&) { read = true; });
            ADD_FAILURE() << magic << " was accepted";
        } catch (const CaseError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(words), std::string::npos) << message;
            EXPECT_NE(message.find("rerun the case from the start"), std::string::npos) << message;
        }
        EXPECT_FALSE(read) << magic;
    }
}

} // namespace
} // namespace grainload::io
