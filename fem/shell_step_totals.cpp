#include "fem/shell_step_totals.hpp"

#include "io/binary_stream.hpp"

#include <stdexcept>
#include <vector>

namespace grainload::fem {

void ShellStepTotals::add(double load_factor, const StepReport& report) {
    any = true;
    last_load_factor = load_factor;
    last_iterations = static_cast<int>(report.log.size());
    last_solver = report.solver;
    if (!report.solver.empty()) {
        ++steps_by_solver[report.solver];
    }
}

namespace {

void write_text(std::ostream& out, const std::string& text) {
    io::write_array(out, std::vector<char>(text.begin(), text.end()));
}

std::string read_text(std::istream& in) {
    std::vector<char> bytes;
    io::read_array(in, bytes);
    return {bytes.begin(), bytes.end()};
}

} // namespace

void ShellStepTotals::write(std::ostream& out) const {
    io::write_array(out, std::vector<double>{any ? 1.0 : 0.0, last_load_factor,
                                             static_cast<double>(last_iterations),
                                             static_cast<double>(steps_by_solver.size())});
    write_text(out, last_solver);
    for (const auto& [solver, steps] : steps_by_solver) {
        write_text(out, solver);
        io::write_array(out, std::vector<double>{static_cast<double>(steps)});
    }
}

void ShellStepTotals::read(std::istream& in) {
    std::vector<double> head;
    io::read_array(in, head, 4, "shell step totals");
    // Counts are whole numbers well below 2^31; anything else is a damaged record.
    auto count = [](double value) {
        if (!(value >= 0.0 && value < 2147483647.0) || value != static_cast<int>(value)) {
            throw std::runtime_error("checkpoint: the shell's step totals are damaged");
        }
        return static_cast<int>(value);
    };
    *this = ShellStepTotals{};
    any = head[0] != 0.0;
    last_load_factor = head[1];
    last_iterations = count(head[2]);
    const int solvers = count(head[3]);
    last_solver = read_text(in);
    for (int k = 0; k < solvers; ++k) {
        const std::string solver = read_text(in);
        std::vector<double> steps;
        io::read_array(in, steps, 1, "shell steps of a solver");
        steps_by_solver[solver] = count(steps[0]);
    }
}

} // namespace grainload::fem
