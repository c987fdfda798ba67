#pragma once
// The [sph.heap] table at work: one body's kinetic energy followed, its final heap measured.

#include "io/frame.hpp"
#include "sph/heap_measures.hpp"
#include "sph/particle_set.hpp"

#include <optional>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The case's [sph.heap] table at work: follows one body's kinetic energy step by step and, at
/// the end, measures the heap it formed (sph/heap_measures.hpp) for summary.json.
class HeapMonitor {
  public:
    /// Reads `body`, `origin` and `rest_fraction` of [sph.heap]; the floor level is the lowest
    /// particle bottom of the body as generated. Gravity defines up, so it must not be zero.
    HeapMonitor(const io::CaseTable& heap, const std::vector<std::string>& body_names,
                const ParticleSet& particles, double spacing, const Vec3& gravity, int dimension);

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
