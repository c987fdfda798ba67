#pragma once
// [[sph.probe]]: the particles nearest given points, their stresses written to probes.csv.

#include "io/key_spec.hpp"
#include "particles/scene_part.hpp"
#include "sph/particle_set.hpp"

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace grainload::sph {

/// The keys of each [[sph.probe]].
inline constexpr std::array<io::KeySpec, 2> kProbeKeys{{
    {"name", "string", "", "names the probe's columns in probes.csv"},
    {"position", "length vector", "", "the probe follows the particle nearest this point at t = 0"},
}};

/// One [[sph.probe]] as read (read_probe_settings, sph/sph_case_reader.hpp).
struct ProbeSettings {
    std::string name;
    Vec3 position; ///< m: the probe follows the material particle nearest it at t = 0
};

/// The [[sph.probe]] tables as one scene part: each probe follows the material particle
/// nearest its position at t = 0 and writes its stress, von Mises stress, pressure and plastic
/// strain to probes.csv at every output instant, until that particle leaves through a sink.
class ProbeSet final : public particles::ScenePart {
  public:
    /// The probes `settings` placed on `particles` (which the part observes from then on); null
    /// when there are none.
    static std::unique_ptr<ProbeSet> place(const std::vector<ProbeSettings>& settings,
                                           const ParticleSet& particles);

    std::string_view name() const override { return "sph.probe"; }
    void after_removal(std::span<const Index> new_index) override;
    void at_output(double time, io::OutputStreams& output) override;

  private:
    explicit ProbeSet(const ParticleSet& particles) : particles_(&particles) {}
    const ParticleSet* particles_;
    /// A name and its particle (-1 once the particle left).
    std::vector<std::pair<std::string, Index>> probes_;
};

} // namespace grainload::sph
