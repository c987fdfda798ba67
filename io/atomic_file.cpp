#include "io/atomic_file.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace grainload::io {

void commit_file(const std::string& temporary, const std::string& path) {
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        throw std::runtime_error("cannot rename " + temporary + " to " + path + ": " +
                                 error.message());
    }
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, binary ? std::ios::binary : std::ios::out);
        if (!out) {
            throw std::runtime_error("cannot write " + temporary);
        }
        write(out);
        out.flush();
        if (!out) {
            throw std::runtime_error("error while writing " + temporary + " (disk full?)");
        }
    }
    commit_file(temporary, path);
}

} // namespace grainload::io
