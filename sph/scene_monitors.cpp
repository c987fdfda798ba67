#include "sph/scene_monitors.hpp"

#include "io/binary_stream.hpp"
#include "io/output_streams.hpp"

#include <utility>

namespace grainload::sph {

namespace {

class HeapPart final : public particles::ScenePart {
  public:
    HeapPart(HeapMonitor heap, const ParticleSet& particles)
        : heap_(std::move(heap)), particles_(&particles) {}
    std::string_view name() const override { return "sph.heap"; }
    void end_step(double time) override { heap_.record(time, *particles_); }
    void append_results(std::vector<io::ResultFigure>& results) const override {
        heap_.append_results(*particles_, results);
    }
    void write_checkpoint(std::ostream& out) const override { io::write_array(out, heap_.state()); }
    void read_checkpoint(std::istream& in) override {
        std::vector<double> state;
        io::read_array(in, state);
        heap_.set_state(state);
    }

  private:
    HeapMonitor heap_;
    const ParticleSet* particles_;
};

class EscapePart final : public particles::ScenePart {
  public:
    EscapePart(EscapeWatch watch, const ParticleSet& particles,
               std::function<std::string(int body_id)> body_name)
        : watch_(std::move(watch)), particles_(&particles), body_name_(std::move(body_name)) {}
    std::string_view name() const override { return "sph.escape_watch"; }
    std::optional<std::string> diagnose() const override {
        return watch_.check(*particles_, body_name_);
    }

  private:
    EscapeWatch watch_;
    const ParticleSet* particles_;
    std::function<std::string(int body_id)> body_name_;
};

} // namespace

std::unique_ptr<particles::ScenePart>
wall_map_part(particles::WallMapSet maps, const ParticleSet& set, const std::vector<Wall>& walls) {
    // The force of the bodies on each wall particle: its mass times its acceleration after the
    // step's force pass (accumulate_wall_load), at the particle, along the wall's normal there.
    auto loads = [&set, &walls](int w, std::vector<particles::WallLoad>& out) {
        const Wall& wall = walls[static_cast<std::size_t>(w)];
        out.resize(static_cast<std::size_t>(wall.count));
#pragma omp parallel for schedule(static)
        for (Index q = 0; q < wall.count; ++q) {
            const Index k = wall.first + q;
            out[static_cast<std::size_t>(q)] = {set.position[k],
                                                wall.normals[static_cast<std::size_t>(q)],
                                                set.mass[k] * set.acceleration[k]};
        }
    };
    return particles::wall_map_part("sph.wall_map", std::move(maps), std::move(loads));
}

std::unique_ptr<particles::ScenePart> heap_part(HeapMonitor heap, const ParticleSet& particles) {
    return std::make_unique<HeapPart>(std::move(heap), particles);
}

std::unique_ptr<particles::ScenePart>
escape_part(EscapeWatch watch, const ParticleSet& particles,
            std::function<std::string(int body_id)> body_name) {
    return std::make_unique<EscapePart>(std::move(watch), particles, std::move(body_name));
}

} // namespace grainload::sph
