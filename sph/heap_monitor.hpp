#pragma once
// The [sph.heap] table at work: one body's kinetic energy followed, its final heap measured.

#include "io/frame.hpp"
#include "io/key_spec.hpp"
#include "sph/heap_measures.hpp"
#include "sph/particle_set.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace grainload::sph {

/// The keys of [sph.heap]: the heap figures of one body in summary.json.
inline constexpr std::array<io::KeySpec, 3> kHeapKeys{{
    {"body", "string", "", "a [[sph.body]] name"},
    {"origin", "length vector", "",
     "3D: a point on the heap's vertical axis; 2D: a point on its back face"},
    {"rest_fraction", "number in (0, 1)", "1e-4",
     "at rest: the body's kinetic energy below this fraction of its peak", 1e-4},
}};

/// [sph.heap] as read (read_heap_settings, sph/sph_case_reader.hpp).
struct HeapSettings {
    int body = -1;        ///< index of the [[sph.body]] measured
    Vec3 origin;          ///< m: a point on the heap's axis (3D) or back face (2D)
    double rest_fraction; ///< at rest below this fraction of the peak kinetic energy
};

/// The case's [sph.heap] table at work: follows one body's kinetic energy step by step and, at
/// the end, measures the heap it formed (sph/heap_measures.hpp) for summary.json.
class HeapMonitor {
  public:
    /// The floor level is the lowest particle bottom of the body as generated; up is against
    /// `gravity` (not zero: read_heap_settings refuses a heap without it).
    HeapMonitor(const HeapSettings& settings, const ParticleSet& particles, double spacing,
                const Vec3& gravity, int dimension);

    /// Add the body's kinetic energy at `time` (after a step) to the history.
    void record(double time, const ParticleSet& particles);
    void append_results(const ParticleSet& particles, std::vector<io::ResultFigure>& results) const;

    std::vector<double> state() const { return rest_.state(); }
    void set_state(const std::vector<double>& state) { rest_.set_state(state); }

  private:
    std::vector<Vec3> body_positions(const ParticleSet& particles) const;
    std::vector<double> body_masses(const ParticleSet& particles) const;

    int body_ = -1;
    HeapFrame frame_;
    double initial_height_ = 0.0;
    RestDetector rest_;
};

} // namespace grainload::sph
