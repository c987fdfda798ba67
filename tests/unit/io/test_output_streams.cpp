// The run's streamed files (io/output_streams.hpp): what a checkpoint records of them, how a
// restart cuts them back to it, when it must refuse, and how rows reach the file.

#include "io/checkpoint_file.hpp"
#include "io/output_streams.hpp"
#include "support/cli_runner.hpp"
#include "support/test_folder.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace grainload::io {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
    return grainload::testing::read_file(path.string());
}

std::string fresh_folder(const std::string& name) {
    const std::string folder = grainload::testing::test_folder(name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

/// Rows "t,k\n" for k = first .. last - 1 at time t.
std::string rows(int t, int first, int last) {
    std::string text;
    for (int k = first; k < last; ++k) {
        text += std::to_string(t) + "," + std::to_string(k) + "\n";
    }
    return text;
}

// The mark is the file's own length and FNV-1a hash, whatever was appended in how many calls:
// a restart compares it with the bytes it finds.
TEST(OutputStreams, AMarkIsTheLengthAndHashOfTheBytesOnDisk) {
    const std::string folder = fresh_folder("streams_mark");
    OutputStreams streams(folder);
    StreamedFile& table = streams.open("table.csv", "time,row\n");
    table.append(rows(1, 0, 3));
    table.append(rows(2, 0, 5));
    streams.open("maps/log.txt").append("one line\n");
    const std::vector<StreamMark> marks = streams.marks();
    ASSERT_EQ(marks.size(), 2u);
    EXPECT_EQ(marks[0].name, "maps/log.txt");
    EXPECT_EQ(marks[1].name, "table.csv");
    for (const StreamMark& mark : marks) {
        const std::string bytes = read_file(fs::path(folder) / mark.name);
        EXPECT_EQ(mark.length, bytes.size()) << mark.name;
        EXPECT_EQ(mark.hash, fnv1a(bytes)) << mark.name;
    }
    EXPECT_EQ(read_file(fs::path(folder) / "table.csv"),
              "time,row\n" + rows(1, 0, 3) + rows(2, 0, 5));
}

// A run killed after its checkpoint wrote more rows; the restart drops them and the file then
// holds exactly what an uninterrupted run writes. A file opened by name again continues, and
// does not repeat its header.
TEST(OutputStreams, AResumedStreamDropsTheRowsAfterTheMarkAndContinues) {
    const std::string whole = fresh_folder("streams_whole");
    {
        OutputStreams streams(whole);
        for (int t = 0; t < 4; ++t) {
            streams.open("table.csv", "time,row\n").append(rows(t, 0, 3));
        }
    }
    const std::string killed = fresh_folder("streams_killed");
    std::vector<StreamMark> at_checkpoint;
    {
        OutputStreams streams(killed);
        for (int t = 0; t < 2; ++t) {
            streams.open("table.csv", "time,row\n").append(rows(t, 0, 3));
        }
        at_checkpoint = streams.marks();
        streams.open("table.csv").append(rows(2, 0, 2)); // the kill came after two rows
    }
    OutputStreams restarted(killed);
    restarted.resume(at_checkpoint);
    EXPECT_EQ(restarted.marks()[0].length, at_checkpoint[0].length);
    for (int t = 2; t < 4; ++t) {
        restarted.open("table.csv", "time,row\n").append(rows(t, 0, 3));
    }
    EXPECT_EQ(read_file(fs::path(killed) / "table.csv"), read_file(fs::path(whole) / "table.csv"));
}

// Files that no longer hold what the run wrote up to the checkpoint (deleted, shortened,
// edited) are refused, naming the file, and no file is touched: the restart is all or nothing.
TEST(OutputStreams, AResumeRefusesFilesThatLostTheirHistoryAndTouchesNothing) {
    struct Damage {
        const char* what;
        void (*apply)(const fs::path&);
        const char* message;
    };
    const std::vector<Damage> damages = {
        {"deleted", [](const fs::path& p) { fs::remove(p); }, "it does not exist"},
        {"shortened", [](const fs::path& p) { fs::resize_file(p, 10); }, "it holds 10 bytes"},
        {"edited",
         [](const fs::path& p) {
             std::fstream f(p, std::ios::in | std::ios::out | std::ios::binary);
             f.seekp(12);
             f.put('X');
         },
         "differs from what the run wrote"},
    };
    for (const Damage& damage : damages) {
        const std::string folder = fresh_folder("streams_damaged");
        std::vector<StreamMark> marks;
        {
            OutputStreams streams(folder);
            streams.open("a.csv", "a\n").append(rows(0, 0, 3));
            streams.open("b.csv", "b\n").append(rows(0, 0, 3));
            marks = streams.marks();
            streams.open("a.csv").append(rows(1, 0, 3)); // after the checkpoint: a restart cuts it
        }
        damage.apply(fs::path(folder) / "b.csv");
        const std::string a_before = read_file(fs::path(folder) / "a.csv");
        OutputStreams streams(folder);
        try {
            streams.resume(marks);
            ADD_FAILURE() << damage.what << ": resumed";
        } catch (const std::runtime_error& error) {
            EXPECT_NE(std::string(error.what()).find("b.csv"), std::string::npos) << error.what();
            EXPECT_NE(std::string(error.what()).find(damage.message), std::string::npos)
                << damage.what << ": " << error.what();
        }
        EXPECT_EQ(read_file(fs::path(folder) / "a.csv"), a_before) << damage.what;
    }
}

// Rows reach the file in one write(2) call an append, whole lines, however long the block: a
// buffered stream passes a block longer than its buffer (8 KiB in libstdc++) in pieces cut at
// the buffer's edge, mid-line, and a kill between two pieces leaves a torn last line.
TEST(OutputStreams, EachAppendIsOneWriteOfWholeLines) {
    std::vector<std::string> calls;
    const WriteCall record = [&](int descriptor, const char* data, std::size_t count) -> long {
        calls.emplace_back(data, count);
        return static_cast<long>(::write(descriptor, data, count));
    };
    const std::string folder = fresh_folder("streams_writes");
    OutputStreams streams(folder, record);
    StreamedFile& table = streams.open("table.csv", "time,row\n");
    const std::string block = rows(7, 0, 3000); // about 20 KB
    ASSERT_GT(block.size(), 16384u);
    table.append(block);
    table.append(rows(8, 0, 1));
    ASSERT_EQ(calls.size(), 3u); // header, block, row
    EXPECT_EQ(calls[1], block);
    for (const std::string& call : calls) {
        EXPECT_EQ(call.back(), '\n');
    }
    EXPECT_THROW(table.append("8,1"), std::logic_error);
    EXPECT_EQ(read_file(fs::path(folder) / "table.csv"), "time,row\n" + block + rows(8, 0, 1));
}

// A short write (a signal, a full pipe) is continued, not lost; an error names the file.
TEST(OutputStreams, ShortWritesAreContinuedAndErrorsNameTheFile) {
    int calls = 0;
    const WriteCall short_writes = [&](int descriptor, const char* data, std::size_t count) {
        ++calls;
        return static_cast<long>(::write(descriptor, data, count < 5 ? count : 5));
    };
    const std::string folder = fresh_folder("streams_short");
    OutputStreams streams(folder, short_writes);
    streams.open("t.csv").append(rows(1, 0, 4)); // 16 bytes in 5-byte pieces
    EXPECT_EQ(calls, 4);
    EXPECT_EQ(read_file(fs::path(folder) / "t.csv"), rows(1, 0, 4));
    EXPECT_EQ(streams.marks()[0].length, 16u);

    const WriteCall full = [](int, const char*, std::size_t) -> long {
        errno = ENOSPC;
        return -1;
    };
    OutputStreams disk_full(fresh_folder("streams_full"), full);
    try {
        disk_full.open("t.csv").append("1,2\n");
        ADD_FAILURE() << "a failed write passed";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("t.csv"), std::string::npos) << error.what();
    }
}

} // namespace
} // namespace grainload::io
