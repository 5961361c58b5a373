// ShapeSplines math core: the sparse (banded, cyclic) solves of the spline families.
#ifndef shapesplines_SparseSolve_h
#define shapesplines_SparseSolve_h

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace shapesplines
{
using Triplets = std::vector<Eigen::Triplet<double>>;

/**
 * Solves A X = B for a square sparse A given as triplets (duplicates add up)
 * and three right-hand sides, one per coordinate. Banded and cyclic-banded
 * systems cost O(n). Throws std::runtime_error if A is singular. With
 * conditionEstimate, also estimates the 1-norm condition number of A with
 * its rows scaled to a largest entry of 1 (Hager-Higham: a few more solves
 * with A and its transpose, still O(n)).
 */
Eigen::MatrixX3d solveSparse(int n, const Triplets& entries, const Eigen::MatrixX3d& rhs,
  double* conditionEstimate = nullptr);

/// Above this condition estimate, rounding can cost more than 1e-4 of relative
/// accuracy (condition * machine epsilon): the solution is not to be trusted.
constexpr double UntrustedCondition = 1e-4 / 2.220446049250313e-16;
} // namespace shapesplines

#endif
