#include "SparseSolve.h"

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shapesplines
{
namespace
{
using SparseLU = Eigen::SparseLU<Eigen::SparseMatrix<double>>;

/**
 * Estimates ||A^-1 D||_1 from a factorisation of A, D diagonal (Hager's
 * method with Higham's safeguard, LAPACK's xLACON): a lower bound, in
 * practice within a factor of a few of the true value.
 */
double inverseOneNorm(SparseLU& lu, const Eigen::VectorXd& d) // transpose() is not const
{
  const auto n = d.size();
  Eigen::VectorXd x = Eigen::VectorXd::Constant(n, 1.0 / n);
  double estimate = 0.0;
  Eigen::Index previous = -1;
  for (int iteration = 0; iteration < 5; ++iteration)
  {
    const Eigen::VectorXd y = lu.solve(d.cwiseProduct(x));
    estimate = std::max(estimate, y.lpNorm<1>());
    const Eigen::VectorXd sign = y.unaryExpr([](double v) { return v >= 0.0 ? 1.0 : -1.0; });
    const Eigen::VectorXd z = d.cwiseProduct(Eigen::VectorXd(lu.transpose().solve(sign)));
    Eigen::Index j = 0;
    z.cwiseAbs().maxCoeff(&j);
    if (std::abs(z[j]) <= z.dot(x) || j == previous)
    {
      break;
    }
    x.setZero();
    x[j] = 1.0;
    previous = j;
  }
  // Higham's alternating-sign vector catches matrices that fool the iteration.
  Eigen::VectorXd alternating(n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    alternating[i] = (i % 2 == 0 ? 1.0 : -1.0) * (1.0 + (n > 1 ? double(i) / (n - 1) : 0.0));
  }
  const double safeguard =
    2.0 * Eigen::VectorXd(lu.solve(d.cwiseProduct(alternating))).lpNorm<1>() / (3.0 * n);
  return std::max(estimate, safeguard);
}
} // namespace

Eigen::MatrixX3d solveSparse(
  int n, const Triplets& entries, const Eigen::MatrixX3d& rhs, double* conditionEstimate)
{
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(matrix);
  if (lu.info() != Eigen::Success)
  {
    // Eigen's own words ("structurally singular, zero column") say nothing to a user.
    throw std::runtime_error("the spline's linear system is singular (too many knots for the "
                             "points, or points too unevenly spaced)");
  }
  Eigen::MatrixX3d solution = lu.solve(rhs);
  if (lu.info() != Eigen::Success || !solution.allFinite())
  {
    throw std::runtime_error("spline system could not be solved");
  }
  if (conditionEstimate)
  {
    // Of the row-equilibrated system D^-1 A (D: each row's largest |a_ij|),
    // which measures what rounding does to an LU solve with pivoting; a
    // merely ill-scaled row (a tiny end span's condition) is harmless.
    Eigen::VectorXd rowScale = Eigen::VectorXd::Zero(n);
    for (const auto& entry : entries)
    {
      rowScale[entry.row()] = std::max(rowScale[entry.row()], std::abs(entry.value()));
    }
    Eigen::VectorXd columnSums = Eigen::VectorXd::Zero(n);
    for (const auto& entry : entries)
    {
      columnSums[entry.col()] += std::abs(entry.value()) / rowScale[entry.row()];
    }
    *conditionEstimate = columnSums.maxCoeff() * inverseOneNorm(lu, rowScale);
  }
  return solution;
}
} // namespace shapesplines
