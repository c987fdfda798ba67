#include "coupling/interface_accelerator.hpp"

#include <Eigen/QR>

namespace grainload::coupling {

Eigen::VectorXd InterfaceAccelerator::next(const Eigen::VectorXd& input,
                                           const Eigen::VectorXd& output) {
    const Eigen::VectorXd residual = output - input;
    return method_ == Accelerator::aitken ? aitken(input, residual)
                                          : quasi_newton(input, output, residual);
}

Eigen::VectorXd InterfaceAccelerator::aitken(const Eigen::VectorXd& input,
                                             const Eigen::VectorXd& residual) {
    // omega(k) = -omega(k-1) r(k-1) . (r(k) - r(k-1)) / |r(k) - r(k-1)|^2.
    if (previous_residual_.size() == residual.size()) {
        const Eigen::VectorXd change = residual - previous_residual_;
        const double squared = change.squaredNorm();
        if (squared > 0.0) {
            omega_ = -omega_ * previous_residual_.dot(change) / squared;
        }
    }
    previous_residual_ = residual;
    return input + omega_ * residual;
}

Eigen::VectorXd InterfaceAccelerator::quasi_newton(const Eigen::VectorXd& input,
                                                   const Eigen::VectorXd& output,
                                                   const Eigen::VectorXd& residual) {
    residuals_.push_back(residual);
    outputs_.push_back(output);
    const auto columns = static_cast<Eigen::Index>(residuals_.size()) - 1;
    if (columns == 0) {
        return input + omega_ * residual;
    }
    // Degroote et al. 2009, eqs. 13-16: V and W hold the differences of the residuals and of
    // the outputs to the newest pass; the least-squares c of V c = -r(k) is the combination of
    // earlier passes that best cancels the residual, and the next input is H(F(k)) + W c.
    Eigen::MatrixXd v(residual.size(), columns);
    Eigen::MatrixXd w(residual.size(), columns);
    for (Eigen::Index j = 0; j < columns; ++j) {
        v.col(j) = residual - residuals_[static_cast<std::size_t>(j)];
        w.col(j) = output - outputs_[static_cast<std::size_t>(j)];
    }
    // Column pivoting with its default threshold drops passes that repeat earlier ones (a
    // rank-deficient V), which a plain QR would turn into huge coefficients.
    const Eigen::VectorXd c = v.colPivHouseholderQr().solve(-residual);
    return output + w * c;
}

} // namespace grainload::coupling
