#include "sph/probes.hpp"

#include "io/output_streams.hpp"
#include "sph/stress_measures.hpp"

#include <limits>
#include <sstream>

namespace grainload::sph {

std::unique_ptr<ProbeSet> ProbeSet::place(const std::vector<ProbeSettings>& settings,
                                          const ParticleSet& particles) {
    if (settings.empty()) {
        return nullptr;
    }
    std::unique_ptr<ProbeSet> set(new ProbeSet(particles));
    const auto& p = particles;
    for (const ProbeSettings& probe : settings) {
        const Vec3& x = probe.position;
        Index nearest = -1;
        double best = std::numeric_limits<double>::infinity();
        for (Index i = 0; i < p.size(); ++i) {
            const double d = (p.position[i] - x).norm();
            if (!p.is_wall(i) && d < best) {
                best = d;
                nearest = i;
            }
        }
        set->probes_.emplace_back(probe.name, nearest);
    }
    return set;
}

void ProbeSet::after_removal(std::span<const Index> new_index) {
    for (auto& probe : probes_) {
        if (probe.second >= 0) {
            probe.second = new_index[static_cast<std::size_t>(probe.second)];
        }
    }
}

void ProbeSet::at_output(double time, io::OutputStreams& output) {
    std::ostringstream rows;
    const auto& p = *particles_;
    for (const auto& [name, i] : probes_) {
        if (i < 0) { // its particle left through a sink
            continue;
        }
        const Voigt6& s = p.stress[i];
        rows << time << ',' << name << ',' << i << ',' << s[0] << ',' << s[1] << ',' << s[2] << ','
             << s[3] << ',' << von_mises_of(s) << ',' << pressure_of(s) << ','
             << p.plastic_strain[i] << '\n';
    }
    output
        .open("probes.csv", "time_s,probe,particle,stress_xx_Pa,stress_yy_Pa,stress_zz_Pa,"
                            "stress_xy_Pa,von_mises_Pa,pressure_Pa,plastic_strain\n")
        .append(rows.str());
}

} // namespace grainload::sph
