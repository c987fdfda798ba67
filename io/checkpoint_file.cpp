#include "io/checkpoint_file.hpp"

#include "io/atomic_file.hpp"
#include "io/binary_stream.hpp"
#include "io/case_error.hpp"

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <streambuf>

namespace grainload::io {

namespace {

constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;
constexpr std::uint64_t kFirstFormatMagic = 0x474c434b50543031; // grainload 0.1's format
/// The format before the streamed files' marks (io/output_streams.hpp) joined the clock.
constexpr std::uint64_t kSecondFormatMagic = 0x323054504b434c47; // "GLCKPT02"
/// The format before each scene part's state carried its part's name
/// (particles/scene_part_list.hpp).
constexpr std::uint64_t kThirdFormatMagic = 0x333054504b434c47; // "GLCKPT03"
/// The format before the SPH energy books split the dissipation by mechanism.
constexpr std::uint64_t kFourthFormatMagic = 0x343054504b434c47; // "GLCKPT04"
/// The format before the run's phases kept their state as a scene part of their own.
constexpr std::uint64_t kFifthFormatMagic = 0x353054504b434c47; // "GLCKPT05"
constexpr std::streamoff kMagicBytes = 8;
constexpr std::streamoff kTrailerBytes = 16; // payload length, hash

/// Passes every byte on to `target` and hashes it on the way.
class HashingBuffer : public std::streambuf {
  public:
    explicit HashingBuffer(std::streambuf* target) : target_(target) {}
    std::uint64_t hash() const { return hash_; }
    std::uint64_t length() const { return length_; }

  protected:
    int_type overflow(int_type c) override {
        if (traits_type::eq_int_type(c, traits_type::eof())) {
            return traits_type::not_eof(c);
        }
        const char byte = traits_type::to_char_type(c);
        return xsputn(&byte, 1) == 1 ? c : traits_type::eof();
    }
    std::streamsize xsputn(const char* data, std::streamsize count) override {
        const std::streamsize written = target_->sputn(data, count);
        hash_ = fnv1a(std::string_view(data, static_cast<std::size_t>(written)), hash_);
        length_ += static_cast<std::uint64_t>(written);
        return written;
    }

  private:
    std::streambuf* target_;
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
    std::uint64_t length_ = 0;
};

/// The framing of a stream of `size` bytes; on success `in` stands at the payload.
void check_framing(std::istream& in, std::uint64_t size) {
    if (size < static_cast<std::uint64_t>(kMagicBytes + kTrailerBytes)) {
        throw std::runtime_error("the file holds " + std::to_string(size) +
                                 " bytes, too few for a checkpoint (truncated?)");
    }
    const auto magic = read_value<std::uint64_t>(in);
    if (magic != kCheckpointMagic) {
        throw std::runtime_error(
            magic == kFirstFormatMagic
                ? "written in the first checkpoint format, which had no checksum; rerun the case "
                  "from the start"
            : magic == kSecondFormatMagic
                ? "written in the second checkpoint format, which did not record where the "
                  "streamed tables (wall_forces.csv, ...) stood; rerun the case from the start"
            : magic == kThirdFormatMagic
                ? "written in the third checkpoint format, whose monitors' states (heap, wall "
                  "maps) were not named by their parts; rerun the case from the start"
            : magic == kFourthFormatMagic
                ? "written in the fourth checkpoint format, whose energy books did not split "
                  "the dissipation by mechanism; rerun the case from the start"
            : magic == kFifthFormatMagic
                ? "written in the fifth checkpoint format, whose phases' state was not a scene "
                  "part of its own; rerun the case from the start"
                : "not a grainload checkpoint (wrong magic number)");
    }
    const std::uint64_t payload = size - static_cast<std::uint64_t>(kMagicBytes + kTrailerBytes);
    in.seekg(static_cast<std::streamoff>(size) - kTrailerBytes);
    const auto length = read_value<std::uint64_t>(in);
    const auto stored = read_value<std::uint64_t>(in);
    if (length != payload) {
        throw std::runtime_error("the file holds " + std::to_string(payload) +
                                 " bytes of state, its trailer says " + std::to_string(length) +
                                 " (truncated or appended to)");
    }
    in.seekg(kMagicBytes);
    std::array<char, 1 << 16> chunk{};
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (std::uint64_t left = payload; left > 0;) {
        const auto count =
            static_cast<std::streamsize>(std::min<std::uint64_t>(left, chunk.size()));
        if (!in.read(chunk.data(), count)) {
            throw std::runtime_error("read error");
        }
        hash = fnv1a(std::string_view(chunk.data(), static_cast<std::size_t>(count)), hash);
        left -= static_cast<std::uint64_t>(count);
    }
    if (hash != stored) {
        throw std::runtime_error("the state's checksum does not match (the file is corrupted)");
    }
    in.seekg(kMagicBytes);
}

void read_framed(std::istream& in, std::uint64_t size, const std::string& name,
                 const std::function<void(std::istream&)>& read_payload) {
    try {
        check_framing(in, size);
        read_payload(in);
        const auto end = static_cast<std::streamoff>(size) - kTrailerBytes;
        const std::streamoff at = in ? std::streamoff(in.tellg()) : -1;
        if (at != end) {
            throw std::runtime_error(
                "the state does not match the case: it holds " + std::to_string(end - kMagicBytes) +
                " bytes, the case's modules read " +
                (at < 0 ? std::string("past its end") : std::to_string(at - kMagicBytes)));
        }
    } catch (const CaseError&) {
        throw;
    } catch (const std::runtime_error& error) {
        throw CaseError(name + ": checkpoint refused: " + error.what());
    } catch (const std::length_error& error) {
        throw CaseError(name + ": checkpoint refused: " + error.what());
    } catch (const std::out_of_range& error) {
        throw CaseError(name + ": checkpoint refused: " + error.what());
    }
}

} // namespace

std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash) {
    for (const char c : bytes) {
        hash ^= static_cast<unsigned char>(c);
        hash *= kFnvPrime;
    }
    return hash;
}

void write_checkpoint_file(const std::string& path,
                           const std::function<void(std::ostream&)>& write_payload) {
    write_file_atomically(
        path,
        [&](std::ostream& out) {
            write_value(out, kCheckpointMagic);
            HashingBuffer buffer(out.rdbuf());
            std::ostream hashed(&buffer);
            write_payload(hashed);
            hashed.flush();
            if (!hashed) {
                out.setstate(std::ios::failbit);
                return;
            }
            write_value(out, buffer.length());
            write_value(out, buffer.hash());
        },
        true);
}

void read_checkpoint_file(const std::string& path,
                          const std::function<void(std::istream&)>& read_payload) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        throw CaseError(path + ": is a directory; expected a checkpoint file (checkpoint.bin)");
    }
    std::ifstream in(path, std::ios::binary);
    const auto size = std::filesystem::file_size(path, error);
    if (!in || error) {
        throw CaseError(path + ": cannot open the checkpoint");
    }
    read_framed(in, size, path, read_payload);
}

void read_checkpoint_bytes(std::string_view bytes, const std::string& name,
                           const std::function<void(std::istream&)>& read_payload) {
    std::istringstream in{std::string(bytes), std::ios::binary};
    read_framed(in, bytes.size(), name, read_payload);
}

std::string frame_checkpoint(std::string_view payload) {
    std::ostringstream out(std::ios::binary);
    write_value(out, kCheckpointMagic);
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    write_value(out, static_cast<std::uint64_t>(payload.size()));
    write_value(out, fnv1a(payload));
    return out.str();
}

} // namespace grainload::io
