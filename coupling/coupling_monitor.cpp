#include "coupling/coupling_monitor.hpp"

#include "io/binary_stream.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace grainload::coupling {

namespace {

/// Below this share of the interface impulse's magnitude a component is the residue of sums
/// that cancel (the x and y of a load along z), not a momentum to compare.
constexpr double kNegligibleShare = 1e-3;

} // namespace

Vec3 load_resultant(const Eigen::VectorXd& load) {
    Vec3 sum = Vec3::Zero();
    for (Eigen::Index n = 0; n + 5 < load.size(); n += 6) {
        sum += load.segment<3>(n);
    }
    return sum;
}

double relative_change(const Eigen::VectorXd& next, const Eigen::VectorXd& previous) {
    const double scale = next.norm();
    return scale > 0.0 ? (next - previous).norm() / scale : (previous.norm() > 0.0 ? 1.0 : 0.0);
}

void append_interface_figures(int a, const Vec3& load, const CouplingMonitor& monitor,
                              std::vector<io::ResultFigure>& results) {
    const std::string axis(1, static_cast<char>('x' + a));
    results.push_back({"interface_force_" + axis, load[a], "N", std::nullopt, ""});
    results.push_back(
        {"interface_impulse_" + axis, monitor.wall_impulse()[a], "N s", std::nullopt, ""});
    results.push_back(shell_impulse_figure(axis, monitor.shell_impulse()[a],
                                           monitor.wall_impulse()[a],
                                           monitor.wall_impulse().norm()));
}

io::ResultFigure shell_impulse_figure(const std::string& axis, double shell, double wall,
                                      double magnitude) {
    if (std::abs(wall) < kNegligibleShare * magnitude) {
        return {"shell_impulse_" + axis, shell, "N s", std::nullopt,
                "its interface_impulse is below 1e-3 of the impulse: not compared"};
    }
    return {"shell_impulse_" + axis, shell, "N s", wall,
            "the sand's impulse on the coupled walls (interface_impulse): momentum conservation "
            "across the interface"};
}

void CouplingMonitor::add(const WindowRecord& record) {
    windows_.push_back(record);
    const double before = created_energy();
    sand_work_ += record.sand_work;
    shell_work_ += record.shell_work;
    if (energy_error() >= largest_error_) {
        largest_error_ = energy_error();
        largest_error_time_ = record.time;
    }
    growing_windows_ = created_energy() > before ? growing_windows_ + 1 : 0;
    largest_work_ = std::max(largest_work_, std::abs(sand_work_));
    wall_impulse_ += record.wall_impulse;
    shell_impulse_ += record.shell_impulse;
    subcycles_ += record.subcycles * record.iterations;
    largest_subcycles_ = std::max(largest_subcycles_, record.subcycles);
    sand_seconds_ += record.sand_seconds;
    fem_seconds_ += record.fem_seconds;
    map_seconds_ += record.map_seconds;
}

double CouplingMonitor::relative_to_work(double energy, double scale) const {
    const double reference = std::max(largest_work_, scale);
    return reference > 0.0 ? energy / reference : 0.0;
}

double CouplingMonitor::relative_energy_error(double scale) const {
    return relative_to_work(std::abs(energy_error()), scale);
}

double CouplingMonitor::relative_created_energy(double scale) const {
    return relative_to_work(created_energy(), scale);
}

std::optional<std::string> CouplingMonitor::check(double limit, double scale) const {
    const double created = relative_created_energy(scale);
    if (std::isfinite(created) && (!(created > limit) || growing_windows_ < kGrowthWindows)) {
        return std::nullopt;
    }
    std::ostringstream out;
    out << "coupling window " << windows_.size()
        << " ending at t = " << (windows_.empty() ? 0.0 : windows_.back().time)
        << " s: the interface created energy: since t = " << largest_error_time_
        << " s the shell received " << created_energy()
        << " J more than the sand's work on the walls (in all, sand work " << sand_work_
        << " J, shell work " << shell_work_ << " J), " << created
        << " of the interface work, above the limit " << limit << ", grown for " << growing_windows_
        << " windows";
    return out.str();
}

void CouplingMonitor::write_csv(io::OutputStreams& output) const {
    std::ostringstream csv;
    csv.precision(12);
    double sand = sand_work_, shell = shell_work_;
    for (std::size_t k = windows_.size(); k-- > written_;) {
        sand -= windows_[k].sand_work;
        shell -= windows_[k].shell_work;
    }
    for (; written_ < windows_.size(); ++written_) {
        const WindowRecord& w = windows_[written_];
        sand += w.sand_work;
        shell += w.shell_work;
        csv << w.time << ',' << w.length << ',' << w.subcycles << ',' << w.iterations << ','
            << w.load_change << ',' << w.sand_work << ',' << w.shell_work << ',' << sand - shell
            << ',' << w.wall_impulse.x() << ',' << w.wall_impulse.y() << ',' << w.wall_impulse.z()
            << ',' << w.shell_impulse.x() << ',' << w.shell_impulse.y() << ','
            << w.shell_impulse.z() << ',' << w.sand_seconds << ',' << w.fem_seconds << ','
            << w.map_seconds << '\n';
    }
    output
        .open("coupling.csv",
              "time_s,window_s,subcycles,iterations,load_change,sand_work_J,shell_work_J,"
              "energy_error_J,wall_impulse_x_Ns,wall_impulse_y_Ns,wall_impulse_z_Ns,"
              "shell_impulse_x_Ns,shell_impulse_y_Ns,shell_impulse_z_Ns,sand_s,fem_s,map_s\n")
        .append(csv.str());
}

std::vector<double> CouplingMonitor::state() const {
    return {sand_work_,
            shell_work_,
            largest_work_,
            largest_error_,
            largest_error_time_,
            static_cast<double>(growing_windows_),
            wall_impulse_.x(),
            wall_impulse_.y(),
            wall_impulse_.z(),
            shell_impulse_.x(),
            shell_impulse_.y(),
            shell_impulse_.z(),
            static_cast<double>(subcycles_),
            static_cast<double>(largest_subcycles_)};
}

void CouplingMonitor::set_state(const std::vector<double>& state) {
    if (state.size() != 14) {
        throw std::runtime_error("checkpoint: the coupling monitor holds 14 values, found " +
                                 std::to_string(state.size()));
    }
    sand_work_ = state[0];
    shell_work_ = state[1];
    largest_work_ = state[2];
    largest_error_ = state[3];
    largest_error_time_ = state[4];
    constexpr double kMostInt = std::numeric_limits<int>::max();
    // Whole numbers below 2^53 are exact in a double.
    constexpr double kMostExact = 9007199254740992.0;
    growing_windows_ =
        static_cast<int>(io::state_count(state[5], kMostInt, "the growing coupling windows"));
    wall_impulse_ = Vec3(state[6], state[7], state[8]);
    shell_impulse_ = Vec3(state[9], state[10], state[11]);
    subcycles_ = static_cast<long long>(io::state_count(state[12], kMostExact, "the sub-cycles"));
    largest_subcycles_ =
        static_cast<int>(io::state_count(state[13], kMostInt, "the most sub-cycles of a window"));
    // The wall-clock seconds are not state: a restarted run times its own windows, and two
    // runs of one case write the same checkpoint (so `cmp` can compare them).
    sand_seconds_ = 0.0;
    fem_seconds_ = 0.0;
    map_seconds_ = 0.0;
    windows_.clear();
    written_ = 0;
}

} // namespace grainload::coupling
