// A key's declared default read as a reader takes it: a number, a word, a vector.

#include "io/key_spec.hpp"

#include <array>
#include <gtest/gtest.h>
#include <stdexcept>

namespace {

using namespace grainload;
using io::KeySpec;

constexpr std::array<KeySpec, 5> kKeys{{
    {"velocity", "velocity vector", "0 m/s", "a zero vector written as one zero"},
    {"axis", "vector", "1 0 0", "three components"},
    {"point", "length vector", "`\"0 0.5 -2 mm\"`",
     "three components with a unit, as the guide "
     "quotes it"},
    {"centre", "length vector", "the particles' centroid", "a default computed by the reader"},
    {"speed", "velocity", "2 m/s", "a number", 2.0},
}};

// The vector a reader falls back to is parsed from the same text the guide shows, in SI; a
// default that is no vector (words, or one non-zero number) is a programming error.
TEST(KeySpec, AVectorDefaultIsParsedFromItsDeclaredText) {
    EXPECT_EQ(io::default_vector(kKeys, "velocity"), Vec3::Zero());
    EXPECT_EQ(io::default_vector(kKeys, "axis"), Vec3::UnitX());
    EXPECT_EQ(io::default_vector(kKeys, "point"), Vec3(0.0, 0.5e-3, -2e-3));
    EXPECT_THROW(io::default_vector(kKeys, "centre"), std::logic_error);
    EXPECT_THROW(io::default_vector(kKeys, "speed"), std::logic_error);
    EXPECT_THROW(io::default_vector(kKeys, "missing"), std::logic_error);
    EXPECT_EQ(io::default_value(kKeys, "speed"), 2.0);
}

} // namespace
