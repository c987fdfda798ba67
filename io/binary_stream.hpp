#pragma once
// Raw dumps of arrays and checked counts for checkpoints that restore a run bit for bit.

#include <cmath>
#include <cstdint>
#include <istream>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace grainload::io {

// Raw dumps of arrays of plain values, for checkpoints that must restore a run bit for bit on the
// same machine. Eigen's fixed-size vectors are not trivially copyable by the standard's rules
// (they declare copy constructors) but are standard-layout arrays of doubles, which suffices.
template <class T>
inline constexpr bool kRawDumpable =
    std::is_trivially_copyable_v<T> || std::is_standard_layout_v<T>;

template <class T> void write_array(std::ostream& out, const std::vector<T>& values) {
    static_assert(kRawDumpable<T>);
    const auto count = static_cast<std::uint64_t>(values.size());
    out.write(reinterpret_cast<const char*>(&count), sizeof count);
    out.write(reinterpret_cast<const char*>(values.data()),
              static_cast<std::streamsize>(count * sizeof(T)));
}

/// Bytes left between the read position and the end of a seekable stream; the largest value
/// when the stream cannot tell (a pipe).
inline std::uint64_t remaining_bytes(std::istream& in) {
    const std::streampos here = in.tellg();
    if (here < 0) {
        return std::numeric_limits<std::uint64_t>::max();
    }
    in.seekg(0, std::ios::end);
    const std::streampos end = in.tellg();
    in.seekg(here);
    return end >= here ? static_cast<std::uint64_t>(end - here) : 0;
}

/// A count kept as a double in a module's state vector (a cursor, rows, windows): a whole
/// number from 0 to `most`, else std::runtime_error naming `what`. A corrupt checkpoint can
/// hold any double there, and casting one beyond the integer's range is undefined behaviour.
inline std::uint64_t state_count(double value, double most, const std::string& what) {
    if (!(value >= 0.0 && value <= most && value == std::floor(value))) {
        throw std::runtime_error("checkpoint: " + what + " is " + std::to_string(value) +
                                 ", expected a whole number from 0 to " + std::to_string(most));
    }
    return static_cast<std::uint64_t>(value);
}

/// The element count in front of an array of `element_size`-byte values. A count larger than
/// the bytes left in the stream is refused before anything is allocated, so a corrupt count
/// cannot ask for terabytes.
inline std::uint64_t read_count(std::istream& in, std::size_t element_size) {
    std::uint64_t count = 0;
    in.read(reinterpret_cast<char*>(&count), sizeof count);
    if (!in) {
        throw std::runtime_error("checkpoint is truncated");
    }
    if (count > remaining_bytes(in) / element_size) {
        throw std::runtime_error("checkpoint is truncated or corrupt: an array of " +
                                 std::to_string(count) + " values of " +
                                 std::to_string(element_size) + " bytes is longer than the file");
    }
    return count;
}

template <class T> void read_values(std::istream& in, std::vector<T>& values, std::uint64_t count) {
    values.resize(static_cast<std::size_t>(count));
    in.read(reinterpret_cast<char*>(values.data()),
            static_cast<std::streamsize>(count * sizeof(T)));
    if (!in) {
        throw std::runtime_error("checkpoint is truncated");
    }
}

/// Reads what write_array wrote.
template <class T> void read_array(std::istream& in, std::vector<T>& values) {
    static_assert(kRawDumpable<T>);
    read_values(in, values, read_count(in, sizeof(T)));
}

/// Same, and the array must hold `expected` values (`what` names them in the message): a
/// checkpoint of another case must not leave arrays of the wrong length behind. A count that
/// differs is refused before `values` is touched.
template <class T>
void read_array(std::istream& in, std::vector<T>& values, std::size_t expected, const char* what) {
    static_assert(kRawDumpable<T>);
    const std::uint64_t count = read_count(in, sizeof(T));
    if (count != expected) {
        throw std::runtime_error("checkpoint holds " + std::to_string(count) + " " + what +
                                 ", the case makes " + std::to_string(expected));
    }
    read_values(in, values, count);
}

/// A string as its byte count and bytes.
inline void write_string(std::ostream& out, const std::string& text) {
    const auto count = static_cast<std::uint64_t>(text.size());
    out.write(reinterpret_cast<const char*>(&count), sizeof count);
    out.write(text.data(), static_cast<std::streamsize>(count));
}

/// Reads what write_string wrote; a count beyond the bytes left is refused before allocating.
inline std::string read_string(std::istream& in) {
    std::string text(static_cast<std::size_t>(read_count(in, 1)), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (!in) {
        throw std::runtime_error("checkpoint is truncated");
    }
    return text;
}

template <class T> void write_value(std::ostream& out, const T& value) {
    static_assert(kRawDumpable<T>);
    out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T> T read_value(std::istream& in) {
    T value{};
    in.read(reinterpret_cast<char*>(&value), sizeof value);
    if (!in) {
        throw std::runtime_error("checkpoint is truncated");
    }
    return value;
}

} // namespace grainload::io
