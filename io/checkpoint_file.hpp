#pragma once
// The checkpoint file's framing: magic, payload, and a trailer of length and FNV-1a hash.

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>

namespace grainload::io {

/// A checkpoint file: the 8-byte magic "GLCKPT06", the payload the modules write, and a
/// trailer of the payload's length and its 64-bit FNV-1a hash (Fowler, Noll & Vo; the
/// 64-bit offset basis 0xcbf29ce484222325 and prime 0x100000001b3). The hash makes a
/// truncated or corrupted file fail before a single value of it is used: a flipped bit in a
/// position would otherwise restart the run from a wrong state without any sign.
inline constexpr std::uint64_t kCheckpointMagic = 0x363054504b434c47; // "GLCKPT06" on disk

/// FNV-1a over `bytes`, continuing from `hash`.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = 0xcbf29ce484222325ULL);

/// Write `path` atomically (io/atomic_file.hpp): magic, what `write_payload` writes, trailer.
/// A failure throws std::runtime_error and leaves the previous file in place.
void write_checkpoint_file(const std::string& path,
                           const std::function<void(std::ostream&)>& write_payload);

/// Check the framing of `path` (magic, length, hash), then let `read_payload` parse the
/// payload, which must consume it exactly. Every failure, of the framing or of
/// `read_payload` (std::runtime_error, std::length_error, std::out_of_range), throws
/// io::CaseError "PATH: checkpoint refused: WHY" (exit code 2).
void read_checkpoint_file(const std::string& path,
                          const std::function<void(std::istream&)>& read_payload);

/// Same, for a checkpoint held in memory (`name` stands for the file in messages).
void read_checkpoint_bytes(std::string_view bytes, const std::string& name,
                           const std::function<void(std::istream&)>& read_payload);

/// The checkpoint framing of `payload` (for tests and the fuzz harness's seeds).
std::string frame_checkpoint(std::string_view payload);

} // namespace grainload::io
