#pragma once
// The run's output directory and the tables and logs it appends to, cut back on restart.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {

/// Where a streamed file stood when a checkpoint was written: its length and the 64-bit FNV-1a
/// hash of those bytes (io/checkpoint_file.hpp), so that a restart can tell the file it finds
/// from the one the run wrote.
struct StreamMark {
    std::string name; ///< path relative to the output directory
    std::uint64_t length = 0;
    std::uint64_t hash = 0;
};

/// The system call a streamed file writes through (POSIX write(2) by default; a test records
/// the calls). Returns the bytes written, or -1 with errno set.
using WriteCall = std::function<long(int descriptor, const char* data, std::size_t count)>;

/// A table or log the run appends to as it goes (wall_forces.csv, probes.csv, discharge.csv,
/// coupling.csv, fem_convergence.csv, log.txt).
///
/// Each append is whole lines handed to the file in one write(2) call (a buffered stream would
/// pass a block longer than its buffer in pieces cut anywhere, and keep a tail in memory). A
/// process killed between two appends therefore leaves whole lines. Linux copies one call into
/// the file page by page and lets a fatal signal stop it only before a page (mm/filemap.c,
/// generic_perform_write), so only a SIGKILL landing while one call copies across a 4096-byte
/// page boundary, microseconds an output instant, can leave the start of a line; the restart
/// cuts every stream back to its checkpoint, which removes that too.
class StreamedFile {
  public:
    StreamedFile(const StreamedFile&) = delete;
    StreamedFile& operator=(const StreamedFile&) = delete;
    ~StreamedFile();

    /// Appends `lines`, whole lines each ending in '\n'. A write error (disk full) throws
    /// std::runtime_error naming the file.
    void append(std::string_view lines);
    StreamMark mark() const { return {name_, length_, hash_}; }
    const std::string& path() const { return path_; }

  private:
    friend class OutputStreams;
    StreamedFile(std::string path, const StreamMark& start, bool fresh, WriteCall write);
    void write_all(std::string_view bytes);

    std::string name_;
    std::string path_;
    int descriptor_ = -1;
    std::uint64_t length_ = 0;
    std::uint64_t hash_ = 0;
    WriteCall write_;
};

/// The run's output directory and the files it streams into it. A fresh run starts each stream
/// afresh with its header; a restarted run first cuts each stream back to the mark its
/// checkpoint recorded (resume), so that the rows a killed process wrote after that checkpoint
/// are dropped rather than repeated, and the writers then continue every file as the
/// uninterrupted run writes it.
class OutputStreams {
  public:
    explicit OutputStreams(std::string directory, WriteCall write = {});
    const std::string& directory() const { return directory_; }

    /// The stream `name` (a path relative to the directory): the one already open, or the one
    /// a resumed checkpoint left, continued; otherwise a new file with `header` as its start.
    StreamedFile& open(const std::string& name, std::string_view header = {});

    /// Every stream's mark now, in name order, for the checkpoint.
    std::vector<StreamMark> marks() const;

    /// A restart from a checkpoint that recorded `marks`: each file must begin with exactly the
    /// bytes of its mark; it is then cut back to the mark and reopened there. Every file is
    /// checked before any is touched: one that is missing, shorter or different throws
    /// std::runtime_error naming it, and then nothing has changed.
    void resume(const std::vector<StreamMark>& marks);

  private:
    std::string directory_;
    WriteCall write_;
    std::map<std::string, std::unique_ptr<StreamedFile>> files_;
};

} // namespace grainload::io
