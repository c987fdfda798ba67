#pragma once
// The update of an iterated coupling window's interface load: Aitken or IQN-ILS.

#include <Eigen/Core>
#include <vector>

namespace grainload::coupling {

/// How an iterated coupling window updates its interface load between passes
/// (`coupling.accelerator`).
enum class Accelerator {
    /// Aitken's dynamic relaxation (Irons & Tuck 1969; Kuttler & Wall 2008, Comput. Mech.
    /// 43:61-72, eq. 44): one scalar factor, enough while one mode dominates the loop.
    aitken,
    /// Interface quasi-Newton with an approximation of the inverse Jacobian from least squares
    /// (IQN-ILS; Degroote, Bathe & Vierendeels 2009, Comput. Struct. 87:793-801, sec. 3): the
    /// passes of the window teach it the loop's response to the load, so it converges where
    /// the loop's gain exceeds one in several modes (a soft silo wall under sand).
    quasi_newton,
};

/// The fixed-point iteration F = H(F) of one window on the interface load F (H: run the window
/// under F and collect the sand's load). Each pass gives its input F(k) and output H(F(k));
/// next() returns the input of the pass after. The first update is the relaxed
/// F + omega (H(F) - F) for both methods.
class InterfaceAccelerator {
  public:
    InterfaceAccelerator(Accelerator method, double relaxation)
        : method_(method), omega_(relaxation) {}

    Eigen::VectorXd next(const Eigen::VectorXd& input, const Eigen::VectorXd& output);

  private:
    Eigen::VectorXd aitken(const Eigen::VectorXd& input, const Eigen::VectorXd& residual);
    Eigen::VectorXd quasi_newton(const Eigen::VectorXd& input, const Eigen::VectorXd& output,
                                 const Eigen::VectorXd& residual);

    Accelerator method_;
    double omega_;
    Eigen::VectorXd previous_residual_;
    std::vector<Eigen::VectorXd> residuals_; ///< r(k) = H(F(k)) - F(k) of every pass
    std::vector<Eigen::VectorXd> outputs_;   ///< H(F(k)) of every pass
};

} // namespace grainload::coupling
