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
 * systems cost O(n). Throws std::runtime_error if A is singular.
 */
Eigen::MatrixX3d solveSparse(int n, const Triplets& entries, const Eigen::MatrixX3d& rhs);
} // namespace shapesplines

#endif
