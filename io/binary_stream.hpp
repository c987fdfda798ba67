#pragma once

#include <cstdint>
#include <istream>
#include <ostream>
#include <stdexcept>
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

template <class T> void read_array(std::istream& in, std::vector<T>& values) {
    static_assert(kRawDumpable<T>);
    std::uint64_t count = 0;
    in.read(reinterpret_cast<char*>(&count), sizeof count);
    if (!in || count > (std::uint64_t{1} << 40)) {
        throw std::runtime_error("checkpoint is truncated or corrupt");
    }
    values.resize(static_cast<std::size_t>(count));
    in.read(reinterpret_cast<char*>(values.data()),
            static_cast<std::streamsize>(count * sizeof(T)));
    if (!in) {
        throw std::runtime_error("checkpoint is truncated");
    }
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
