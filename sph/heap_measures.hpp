#pragma once
// The measures of a granular heap: height, run-out, surface slope, largest cluster.

#include "io/types.hpp"

#include <optional>
#include <vector>

namespace grainload::sph {

/// Where a granular heap is measured from (the case's [sph.heap] table, docs/user-guide/sph.md).
struct HeapFrame {
    Vec3 origin = Vec3::Zero(); ///< 3D: a point of the heap's vertical axis; 2D: of the back face
    Vec3 up = Vec3::UnitZ();    ///< unit vector against gravity
    double floor_level = 0.0;   ///< height (along up, from origin) of the floor the heap lies on
    double spacing = 0.0;       ///< particle spacing dp: particles are cubes of side dp
    int dimension = 3;
};

/// The heap figures of docs/theory/sph.md, "Heap measures"; lengths in m, angle in rad.
struct HeapMeasures {
    double final_height = 0.0;   ///< highest particle top of the heap above floor_level
    double axis_height = 0.0;    ///< highest particle top of the heap within dp of the axis
    double run_out = 0.0;        ///< farthest particle edge from the axis (3D) or back face (2D)
    double run_out_99 = 0.0;     ///< distance whose particles hold 99 % of the body's mass
    std::optional<double> angle; ///< least-squares slope of the surface from 20 % to 80 % height
    Index heap_count = 0;        ///< particles in the heap (the largest cluster)
    Index outside_count = 0;     ///< particles not connected to it
};

/// 1 for the particles of the largest cluster, where two particles are connected when their
/// centres are closer than `link_distance`; 0 for the rest. Ties go to the cluster holding the
/// lowest index.
std::vector<char> largest_cluster(const std::vector<Vec3>& position, double link_distance);

/// Height, run-out, surface slope and cluster counts of the particles `position` of masses
/// `mass` (one body). The heap is the largest cluster at a link distance of 1.5 spacings; the
/// mass-based run-out takes every particle of the body, in the heap or not.
HeapMeasures measure_heap(const std::vector<Vec3>& position, const std::vector<double>& mass,
                          const HeapFrame& frame);

/// Time to rest from a kinetic-energy history, fed one sample at a time: the first time after
/// the peak at which the energy falls below `fraction` of the peak. A new peak (the energy
/// rising above the old one) starts the search again.
class RestDetector {
  public:
    explicit RestDetector(double fraction) : fraction_(fraction) {}
    void add(double time, double kinetic_energy);
    double peak() const { return peak_; }
    double peak_time() const { return peak_time_; }
    double last() const { return last_; }
    /// Empty while the energy has not yet fallen below fraction * peak since the peak.
    std::optional<double> rest_time() const;
    /// The running state (peak, peak time, rest time or -1, last energy), for checkpoints.
    std::vector<double> state() const;
    void set_state(const std::vector<double>& state);

  private:
    double fraction_;
    double peak_ = 0.0;
    double peak_time_ = 0.0;
    double rest_time_ = -1.0;
    double last_ = 0.0;
};

} // namespace grainload::sph
