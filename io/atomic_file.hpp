#pragma once
// Files written whole or not at all: written under a temporary name, then renamed.

#include <functional>
#include <iosfwd>
#include <string>

namespace grainload::io {

/// Write `path` by writing `path.tmp` and renaming it, so a reader (or a crash) never sees a
/// half-written file. `write` fills the stream; a failure throws std::runtime_error.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

/// Rename a finished temporary file onto its final name (same directory, atomic on POSIX).
void commit_file(const std::string& temporary, const std::string& path);

} // namespace grainload::io
