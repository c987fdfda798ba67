#include "io/output_streams.hpp"

#include "io/checkpoint_file.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace grainload::io {

namespace fs = std::filesystem;

namespace {

long posix_write(int descriptor, const char* data, std::size_t count) {
    return static_cast<long>(::write(descriptor, data, count));
}

/// Length and FNV-1a hash of the first `most` bytes of `path` (fewer when it is shorter);
/// length 0 when it cannot be read.
StreamMark prefix_of(const std::string& path, std::uint64_t most) {
    StreamMark mark;
    mark.hash = fnv1a({});
    std::ifstream in(path, std::ios::binary);
    std::array<char, 1 << 16> chunk{};
    while (in && mark.length < most) {
        const auto want =
            static_cast<std::streamsize>(std::min<std::uint64_t>(chunk.size(), most - mark.length));
        in.read(chunk.data(), want);
        const auto got = static_cast<std::size_t>(in.gcount());
        mark.hash = fnv1a(std::string_view(chunk.data(), got), mark.hash);
        mark.length += got;
    }
    return mark;
}

/// Refuses `path` unless it begins with exactly the bytes of `mark`.
void check_marked(const StreamMark& mark, const std::string& path) {
    const StreamMark found = prefix_of(path, mark.length);
    if (found.length == mark.length && found.hash == mark.hash) {
        return;
    }
    const std::string why = !fs::exists(path) ? "it does not exist"
                            : found.length < mark.length
                                ? "it holds " + std::to_string(found.length) + " bytes"
                                : "it differs from what the run wrote (edited?) within them";
    throw std::runtime_error(path + ": the checkpoint was written after its first " +
                             std::to_string(mark.length) + " bytes, but " + why +
                             "; its history up to the checkpoint is not there");
}

} // namespace

StreamedFile::StreamedFile(std::string path, const StreamMark& start, bool fresh, WriteCall write)
    : name_(start.name), path_(std::move(path)), length_(start.length), hash_(start.hash),
      write_(std::move(write)) {
    fs::create_directories(fs::path(path_).parent_path());
    const int flags = O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (fresh ? O_TRUNC : 0);
    descriptor_ = ::open(path_.c_str(), flags, 0644);
    if (descriptor_ < 0) {
        throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
    }
    if (!fresh && ::ftruncate(descriptor_, static_cast<off_t>(length_)) != 0) {
        const std::string error = std::strerror(errno);
        ::close(descriptor_);
        throw std::runtime_error("cannot cut " + path_ + " back to the checkpoint: " + error);
    }
}

StreamedFile::~StreamedFile() {
    if (descriptor_ >= 0) {
        ::close(descriptor_);
    }
}

void StreamedFile::write_all(std::string_view bytes) {
    while (!bytes.empty()) {
        const long written = write_(descriptor_, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR) {
            continue;
        }
        if (written <= 0) {
            throw std::runtime_error("error while writing " + path_ + ": " +
                                     (written < 0 ? std::strerror(errno) : "nothing written"));
        }
        const auto count = static_cast<std::size_t>(written);
        hash_ = fnv1a(bytes.substr(0, count), hash_);
        length_ += count;
        bytes.remove_prefix(count);
    }
}

void StreamedFile::append(std::string_view lines) {
    if (!lines.empty() && lines.back() != '\n') {
        throw std::logic_error(path_ + ": a streamed file takes whole lines");
    }
    write_all(lines);
}

OutputStreams::OutputStreams(std::string directory, WriteCall write)
    : directory_(std::move(directory)), write_(write ? std::move(write) : WriteCall(posix_write)) {}

StreamedFile& OutputStreams::open(const std::string& name, std::string_view header) {
    auto found = files_.find(name);
    if (found == files_.end()) {
        StreamMark start{name, 0, fnv1a({})};
        auto file = std::unique_ptr<StreamedFile>(
            new StreamedFile((fs::path(directory_) / name).string(), start, true, write_));
        found = files_.emplace(name, std::move(file)).first;
        if (!header.empty()) {
            found->second->append(header);
        }
    }
    return *found->second;
}

std::vector<StreamMark> OutputStreams::marks() const {
    std::vector<StreamMark> marks;
    for (const auto& [name, file] : files_) {
        marks.push_back(file->mark());
    }
    return marks;
}

void OutputStreams::resume(const std::vector<StreamMark>& marks) {
    for (const StreamMark& mark : marks) {
        check_marked(mark, (fs::path(directory_) / mark.name).string());
    }
    files_.clear();
    for (const StreamMark& mark : marks) {
        const std::string path = (fs::path(directory_) / mark.name).string();
        files_.emplace(mark.name,
                       std::unique_ptr<StreamedFile>(new StreamedFile(path, mark, false, write_)));
    }
}

} // namespace grainload::io
