#include "sph/lattice_fill.hpp"
#include "sph/pair_lanes.hpp"
#include "sph/pair_parts.hpp"
#include "sph/rates.hpp"

#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <omp.h>
#include <random>
#include <sstream>
#include <string>
#include <utility>

namespace grainload::sph {
namespace {

/// A jittered lattice at 0.1 m (7 x 7 x 7, or 15 x 15 in plane strain) in two bodies (x below
/// 0.35 m and above) beside a wall row at x < 0.1 m, moving and stressed at random: same-body
/// pairs inside and outside the support (the list's skin), contact pairs between the bodies
/// and with the wall, interleaved in the rows.
struct Scene {
    explicit Scene(int dimension)
        : kernel(KernelType::cubic_spline, 0.13, dimension), neighbours(0.26, 0.05, dimension) {}
    ParticleSet particles;
    SmoothingKernel kernel;
    particles::NeighbourList neighbours;
};

void fill(Scene& s, int dimension) {
    LatticeBody body;
    body.upper = Vec3::Constant(dimension == 3 ? 0.7 : 1.5);
    body.spacing = 0.1;
    body.density = 1500.0;
    ParticleSet& p = s.particles;
    fill_box_lattice(p, body, dimension);
    std::mt19937 generator(11u);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::vector<char> frozen(static_cast<std::size_t>(p.size()));
    const Vec3 plane = dimension == 3 ? Vec3::Ones() : Vec3(1.0, 1.0, 0.0);
    for (Index i = 0; i < p.size(); ++i) {
        p.body_id[i] = p.position[i].x() < 0.35 ? 0 : 1;
        if (p.position[i].x() < 0.1) {
            p.wall_id[i] = 0;
            p.body_id[i] = 2;
        }
        frozen[i] = p.wall_id[i] >= 0 ? 1 : 0;
        const Vec3 jitter(value(generator), value(generator), value(generator));
        const Vec3 velocity(value(generator), value(generator), value(generator));
        p.position[i] += 0.02 * jitter.cwiseProduct(plane);
        p.velocity[i] = velocity.cwiseProduct(plane);
        p.density[i] *= 1.0 + 0.05 * value(generator);
        for (int c = 0; c < 6; ++c) {
            // Plane strain: sigma_zz stays, the xz and yz shears are 0.
            p.stress[i][c] = dimension == 2 && c >= 4 ? 0.0 : 1e4 * value(generator);
        }
    }
    s.neighbours.update(p.position, frozen, true);
}

/// Whether the kernel lists AVX2 among this processor's flags (/proc/cpuinfo, Linux): the
/// processor's own statement, independent of the compiler's run-time check the lanes use.
bool processor_lists_avx2() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("flags", 0) == 0) {
            std::istringstream flags(line.substr(line.find(':') + 1));
            std::string flag;
            while (flags >> flag) {
                if (flag == "avx2") {
                    return true;
                }
            }
            return false;
        }
    }
    return false;
}

// The vector lanes are meant to do the scalar rows' operations in their order (no fused
// multiply-add, IEEE division and square root) and to add the terms in the list's order: the
// velocity gradients, accelerations and heating rates must then be the same bits, not merely
// close.
TEST(PairLanes, SameBitsAsTheScalarRows) {
    if (!pair_lanes_available()) {
        // Skipped only on a processor without AVX2; one that lists it must run the lanes, or
        // every run there would take the scalar rows unseen.
        ASSERT_FALSE(processor_lists_avx2())
            << "/proc/cpuinfo lists avx2 but the pair passes do not run their lanes";
        GTEST_SKIP() << "no AVX2 on this processor: the pair passes run the scalar rows only";
    }
    const int threads_before = omp_get_max_threads();
    for (const auto& [dimension, fixed_speed] :
         {std::pair{3, 0.0}, std::pair{3, 30.0}, std::pair{2, 0.0}}) {
        Scene s(dimension);
        fill(s, dimension);
        ParticleSet& p = s.particles;
        SphOptions options;
        options.dimension = dimension;
        options.particle_spacing = 0.1;
        options.viscosity = {1.0, 2.0, fixed_speed};
        options.contact.stiffness = 1e6;
        options.gravity = dimension == 3 ? Vec3(0.0, 0.0, -9.81) : Vec3(0.0, -9.81, 0.0);
        for (const bool halve : {false, true}) {
            if (halve) {
                s.neighbours.halve_pairs(continuum_keys(p));
                // Rows the lanes take as they are (NeighbourList::same_key_row) and rows whose
                // pairs they pick both occur.
                Index whole = 0;
                for (Index i = 0; i < p.size(); ++i) {
                    whole += s.neighbours.same_key_row(i) ? 1 : 0;
                }
                EXPECT_GT(whole, 0);
                EXPECT_LT(whole, p.size());
            }
            for (const int threads : {1, 2}) {
                omp_set_num_threads(threads);
                ForceInputs inputs;
                inputs.sound_speed.assign(static_cast<std::size_t>(p.size()), 0.0);
                for (Index i = 0; i < p.size(); ++i) {
                    inputs.sound_speed[i] = 50.0 + static_cast<double>(i % 7);
                }
                std::vector<Mat3> scalar_gradient;
                compute_velocity_gradient(p, s.neighbours, s.kernel, false, scalar_gradient,
                                          inputs.gradient_correction, nullptr, nullptr,
                                          PairArithmetic::scalar);
                // As the solver runs it: in 3D the lanes read the records they write; plane
                // strain stores W'(r)/r, which the scalar force row reads and the force lanes
                // evaluate again.
                std::vector<Mat3> gradient;
                compute_velocity_gradient(
                    p, s.neighbours, s.kernel, false, gradient, inputs.gradient_correction,
                    dimension == 2 ? &inputs.entry_factor : nullptr, nullptr,
                    PairArithmetic::lanes_where_available, &inputs.pair_records);
                // The kinematic lanes ran (they alone write records in this pass).
                EXPECT_EQ(inputs.pair_records.size(),
                          dimension == 3 ? static_cast<std::size_t>(p.size()) : 0U);
                for (Index i = 0; i < p.size(); ++i) {
                    for (int k = 0; k < 9; ++k) {
                        EXPECT_EQ(std::memcmp(gradient[i].data() + k, scalar_gradient[i].data() + k,
                                              sizeof(double)),
                                  0)
                            << dimension << "D, particle " << i << " entry " << k;
                    }
                }
                prepare_force_inputs(p, options.artificial_stress, inputs);
                ASSERT_FALSE(inputs.pair_records.empty());
                std::vector<double> heating;
                compute_accelerations(p, s.neighbours, s.kernel, options, inputs, heating);
                const std::vector<Vec3> lanes = p.acceleration;
                const std::vector<double> lanes_heating = heating;
                compute_accelerations(p, s.neighbours, s.kernel, options, inputs, heating, nullptr,
                                      PairArithmetic::scalar);
                double largest = 0.0;
                for (Index i = 0; i < p.size(); ++i) {
                    largest = std::max(largest, std::abs(heating[i]));
                    for (int c = 0; c < 3; ++c) {
                        EXPECT_EQ(std::memcmp(&lanes[i][c], &p.acceleration[i][c], sizeof(double)),
                                  0)
                            << dimension << "D, particle " << i << " component " << c << ": "
                            << lanes[i][c] << " against " << p.acceleration[i][c];
                    }
                    EXPECT_EQ(std::memcmp(&lanes_heating[i], &heating[i], sizeof(double)), 0)
                        << dimension << "D, particle " << i;
                }
                // The scene exercises the viscosity (and so the whole pair term).
                EXPECT_GT(largest, 0.0);
            }
        }
    }
    omp_set_num_threads(threads_before);
}

} // namespace
} // namespace grainload::sph
