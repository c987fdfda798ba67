#include "io/steady_rate.hpp"

#include <stdexcept>

namespace grainload::io {

std::optional<SteadyRate> steady_rate(std::span<const double> time, std::span<const double> mass,
                                      double lower, double upper) {
    if (time.size() != mass.size()) {
        throw std::invalid_argument("steady_rate: as many times as masses expected");
    }
    if (mass.empty() || !(mass.back() > 0.0)) {
        return std::nullopt;
    }
    const double from = lower * mass.back();
    const double to = upper * mass.back();
    // Two passes (means, then centred sums): the textbook one-pass formula loses digits when
    // the times are far from zero compared with their spread.
    double t_mean = 0.0;
    double m_mean = 0.0;
    SteadyRate fit;
    for (std::size_t k = 0; k < time.size(); ++k) {
        if (mass[k] >= from && mass[k] <= to) {
            if (fit.samples == 0) {
                fit.start = time[k];
            }
            fit.end = time[k];
            t_mean += time[k];
            m_mean += mass[k];
            ++fit.samples;
        }
    }
    if (fit.samples < 3) {
        return std::nullopt;
    }
    t_mean /= fit.samples;
    m_mean /= fit.samples;
    double stt = 0.0;
    double stm = 0.0;
    for (std::size_t k = 0; k < time.size(); ++k) {
        if (mass[k] >= from && mass[k] <= to) {
            stt += (time[k] - t_mean) * (time[k] - t_mean);
            stm += (time[k] - t_mean) * (mass[k] - m_mean);
        }
    }
    if (!(stt > 0.0)) {
        return std::nullopt;
    }
    fit.rate = stm / stt;
    return fit;
}

} // namespace grainload::io
