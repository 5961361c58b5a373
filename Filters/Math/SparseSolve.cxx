#include "SparseSolve.h"

#include <Eigen/SparseLU>

#include <stdexcept>

namespace shapesplines
{
Eigen::MatrixX3d solveSparse(int n, const Triplets& entries, const Eigen::MatrixX3d& rhs)
{
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(matrix);
  if (lu.info() != Eigen::Success)
  {
    throw std::runtime_error("singular spline system: " + lu.lastErrorMessage());
  }
  Eigen::MatrixX3d solution = lu.solve(rhs);
  if (lu.info() != Eigen::Success || !solution.allFinite())
  {
    throw std::runtime_error("spline system could not be solved");
  }
  return solution;
}
} // namespace shapesplines
