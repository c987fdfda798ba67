#include "sph/particle_removal.hpp"
#include "sph/particle_set.hpp"
#include "sph/symmetry.hpp"

#include <gtest/gtest.h>
#include <set>
#include <string>
#include <type_traits>

// The per-particle field registry (sph/particle_set.hpp): every array of ParticleSet with one
// entry per particle is listed once, and appending, reserving, removing and mirroring visit
// that list. These tests fill every registered field through the registry with a value no
// other field or particle holds, then check against a plain copy of the set that every field
// of every particle went where the particle went. Values are small integers plus binary
// fractions, so each comparison is exact.

namespace grainload::sph {
namespace {

constexpr int kParticles = 12;

/// The value field `f` of particle `i` is filled with: distinct over fields and particles.
double tag(std::size_t f, int i) {
    return 1000.0 * static_cast<double>(f + 1) + i;
}

template <class T> T tagged(std::size_t f, int i) {
    const double t = tag(f, i);
    if constexpr (std::is_same_v<T, Vec3>) {
        return Vec3(t, t + 0.25, t + 0.5);
    } else if constexpr (std::is_same_v<T, Voigt6>) {
        Voigt6 v;
        for (int k = 0; k < 6; ++k) {
            v[k] = t + 0.125 * k;
        }
        return v;
    } else if constexpr (std::is_same_v<T, char>) {
        return static_cast<char>(1 + i); // one char field: distinct over particles suffices
    } else {
        return static_cast<T>(t);
    }
}

/// Particles with state blocks of 0 to 3 values (distinct values), every registered field
/// except state_offset (which must keep pointing into `state`) overwritten with tagged values.
ParticleSet tagged_set() {
    ParticleSet p;
    for (int i = 0; i < kParticles; ++i) {
        const int state_size = i % 4;
        p.add(Vec3::Zero(), Vec3::Zero(), 1.0, 1.0, 0, 0, state_size);
        for (int k = 0; k < state_size; ++k) {
            p.state[static_cast<std::size_t>(p.state_offset.back() + k)] = 100.0 * i + k;
        }
    }
    std::size_t f = 0;
    p.for_each_field([&f](const auto& field, auto& values) {
        using T = typename std::remove_cvref_t<decltype(field)>::value_type;
        if (std::string(field.name) != "state_offset") {
            for (int i = 0; i < kParticles; ++i) {
                values[static_cast<std::size_t>(i)] = tagged<T>(f, i);
            }
        }
        ++f;
    });
    return p;
}

/// The state block of particle i.
std::vector<double> state_of(const ParticleSet& p, Index i) {
    const auto begin = p.state_offset[static_cast<std::size_t>(i)];
    const auto end = i + 1 < p.size() ? p.state_offset[static_cast<std::size_t>(i + 1)]
                                      : static_cast<Index>(p.state.size());
    return {p.state.begin() + begin, p.state.begin() + end};
}

// The registry names every array of ParticleSet but `state` exactly once: its entries are
// distinct members under distinct names, and with the static_assert next to the registry
// (sizeof(ParticleSet) == (fields + 1) vectors) no member is left out.
TEST(ParticleFields, RegistryListsEveryPerParticleArrayOnce) {
    ParticleSet p;
    std::set<const void*> arrays;
    std::set<std::string> names;
    p.for_each_field([&](const auto& field, const auto& values) {
        arrays.insert(&values);
        names.insert(field.name);
    });
    EXPECT_EQ(arrays.size(), particle_field_count);
    EXPECT_EQ(names.size(), particle_field_count);
    EXPECT_EQ(arrays.count(&p.state), 0U);
    EXPECT_EQ(sizeof(ParticleSet), (particle_field_count + 1) * sizeof(std::vector<char>));
}

// add() and add_wall_particle() give every field one entry (zero where the particle does not
// set it); reserve() reserves every field.
TEST(ParticleFields, AddAndReserveReachEveryField) {
    ParticleSet p;
    p.reserve(40);
    p.add(Vec3(1, 2, 3), Vec3(4, 5, 6), 0.5, 1500.0, 2, 1, 3);
    p.add_wall_particle(Vec3(7, 8, 9), Vec3::Zero(), 0.25, 2000.0, 3, 0);
    p.for_each_field([&](const auto& field, const auto& values) {
        EXPECT_EQ(values.size(), 2U) << field.name;
        EXPECT_GE(values.capacity(), 40U) << field.name;
    });
    EXPECT_EQ(p.position[1], Vec3(7, 8, 9));
    EXPECT_EQ(p.wall_id[0], -1);
    EXPECT_EQ(p.wall_id[1], 0);
    EXPECT_EQ(p.material_id[1], -1);
    EXPECT_EQ(p.state_offset[1], 3);
    EXPECT_EQ(p.state.size(), 3U);
    EXPECT_EQ(p.stress[0], Voigt6::Zero());
    EXPECT_EQ(p.spin[1], Vec3::Zero());
    EXPECT_EQ(p.plastic_region[0], 0);
    EXPECT_EQ(p.clamped[1], 0);
}

// Removing particles keeps, for every surviving particle, every registered field's value and
// its state block together, and leaves every field size()-long.
TEST(ParticleFields, RemovalMovesEveryFieldOfAParticleTogether) {
    ParticleSet p = tagged_set();
    const ParticleSet before = p; // a plain member-wise copy, made without the registry
    std::vector<char> gone(kParticles, 0);
    for (int i : {0, 3, 4, 9, 11}) {
        gone[static_cast<std::size_t>(i)] = 1;
    }
    std::vector<Wall> no_walls;
    const auto new_index = remove_particles(p, gone, no_walls);
    ASSERT_EQ(p.size(), kParticles - 5);
    p.for_each_field([&](const auto& field, const auto& values) {
        ASSERT_EQ(static_cast<Index>(values.size()), p.size()) << field.name;
        if (std::string(field.name) == "state_offset") {
            return; // offsets move with their blocks: checked through state_of below
        }
        const auto& old_values = before.*field.values;
        for (Index old = 0; old < kParticles; ++old) {
            const Index now = new_index[static_cast<std::size_t>(old)];
            if (now >= 0) {
                EXPECT_EQ(values[static_cast<std::size_t>(now)],
                          old_values[static_cast<std::size_t>(old)])
                    << field.name << " of particle " << old;
            }
        }
    });
    for (Index old = 0; old < kParticles; ++old) {
        const Index now = new_index[static_cast<std::size_t>(old)];
        EXPECT_EQ(now < 0, gone[static_cast<std::size_t>(old)] != 0) << old;
        if (now >= 0) {
            EXPECT_EQ(state_of(p, now), state_of(before, old)) << "state of particle " << old;
        }
    }
}

/// The image in the plane x = 0.5 of a value under `rule`, written out component by component
/// (independently of sph/symmetry.cpp's mirror functions).
template <class T> T expected_x_image(Mirror rule, const T& v) {
    if constexpr (std::is_same_v<T, Vec3>) {
        switch (rule) {
        case Mirror::point:
            return Vec3(1.0 - v.x(), v.y(), v.z());
        case Mirror::polar:
            return Vec3(-v.x(), v.y(), v.z());
        case Mirror::axial:
            return Vec3(v.x(), -v.y(), -v.z());
        default:
            return v;
        }
    } else if constexpr (std::is_same_v<T, Voigt6>) {
        T w = v;
        if (rule == Mirror::tensor) {
            w[3] = -v[3]; // xy
            w[5] = -v[5]; // zx
        }
        return w;
    } else {
        return rule == Mirror::cleared ? T{0} : v;
    }
}

// Images of particles 2, 5 and 7 in the plane x = 0.5: every registered field gets an entry
// per image, holding its source's value under the field's rule; dropping them leaves every
// field size()-long with the real particles' values untouched.
TEST(ParticleFields, ImagesWriteAndDropEveryField) {
    ParticleSet p = tagged_set();
    const ParticleSet before = p;
    const std::vector<GhostImage> images{{2, 1}, {5, 1}, {7, 1}};
    write_images(p, kParticles, images, ImageFrame{Vec3(0.5, 0.0, 0.0), Vec3::Zero()});
    ASSERT_EQ(p.size(), kParticles + 3);
    p.for_each_field([&](const auto& field, const auto& values) {
        using Field = std::remove_cvref_t<decltype(field)>;
        ASSERT_EQ(static_cast<Index>(values.size()), p.size()) << field.name;
        for (std::size_t k = 0; k < images.size(); ++k) {
            const auto& source = values[static_cast<std::size_t>(images[k].source)];
            EXPECT_EQ(values[kParticles + k], expected_x_image(Field::mirror, source))
                << field.name << " of image " << k;
        }
    });
    drop_images(p, kParticles);
    p.for_each_field([&](const auto& field, const auto& values) {
        ASSERT_EQ(static_cast<Index>(values.size()), p.size()) << field.name;
        EXPECT_EQ(values, before.*field.values) << field.name;
    });
    EXPECT_EQ(p.size(), kParticles);
}

} // namespace
} // namespace grainload::sph
