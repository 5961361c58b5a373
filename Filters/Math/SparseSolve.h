// ShapeSplines math core: the sparse (banded, cyclic) solves of the spline families.
#ifndef shapesplines_SparseSolve_h
#define shapesplines_SparseSolve_h

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <stdexcept>
#include <vector>

namespace shapesplines
{
/// Thrown when a spline's linear system is singular: its message is for the user.
class SingularSystem : public std::runtime_error
{
public:
  SingularSystem()
    : std::runtime_error("the spline's linear system is singular (too many knots for the "
                         "points, or points too unevenly spaced)")
  {
  }
};

using Triplets = std::vector<Eigen::Triplet<double>>;

/**
 * The estimated 1-norm condition number of the systems a curve was solved
 * with (Hager-Higham: a factorisation and a few solves with it and its
 * transpose, O(n) for a band), computed when first asked for and kept: an
 * automatic search builds many curves and returns one, and estimating each
 * cost a third of a tension quintic's build. Until then it holds the
 * systems' row-scaled entries. Not to be asked from two threads at once.
 */
class DeferredCondition
{
public:
  /// The largest estimate over the systems recorded; 1 without any.
  double value() const;
  /// Records a system of n unknowns, its entries row-scaled as solveSparse solved it.
  void record(int n, Triplets entries);
  /// Takes another's systems too (a curve solved in several systems).
  void merge(DeferredCondition other);

private:
  struct System
  {
    int Unknowns;
    Triplets Entries;
  };
  mutable std::vector<System> Pending;
  mutable double Largest = 1.0;
};

/**
 * Solves A X = B for a square sparse A given as triplets (duplicates add up)
 * and three right-hand sides, one per coordinate, with A's rows (and B's)
 * scaled to a largest entry of 1 first, so that rows of very different
 * scales keep their accuracy. Banded and cyclic-banded systems cost O(n).
 * Throws SingularSystem if A is singular. With condition, records that
 * row-scaled A there, for its condition number (DeferredCondition).
 */
Eigen::MatrixX3d solveSparse(int n, const Triplets& entries, const Eigen::MatrixX3d& rhs,
  DeferredCondition* condition = nullptr);

/**
 * The normal equations B^T W B X = B^T W P of a weighted least-squares fit,
 * gathered one row of B at a time: its nonzero entries b[a] in columns
 * columns[a] (a column met twice adds up, as a closed curve's wrapped basis
 * functions do), the point it fits and the row's weight.
 */
class NormalEquations
{
public:
  explicit NormalEquations(int unknowns)
    : Unknowns(unknowns)
    , Rhs(Eigen::MatrixX3d::Zero(unknowns, 3))
  {
  }

  template <class Entries>
  void add(const int* columns, const Entries& b, int count, const Eigen::Vector3d& point, double weight = 1.0)
  {
    for (int i = 0; i < count; ++i)
    {
      for (int j = 0; j < count; ++j)
      {
        this->Entries.emplace_back(columns[i], columns[j], weight * b[i] * b[j]);
      }
      this->Rhs.row(columns[i]) += weight * b[i] * point.transpose();
    }
  }

  /// X, one column per coordinate; see solveSparse.
  Eigen::MatrixX3d solve(DeferredCondition* condition = nullptr) const
  {
    return solveSparse(this->Unknowns, this->Entries, this->Rhs, condition);
  }

private:
  int Unknowns;
  Triplets Entries;
  Eigen::MatrixX3d Rhs;
};

/// Above this condition estimate, rounding can cost more than 1e-4 of relative
/// accuracy (condition * machine epsilon): the solution is not to be trusted.
constexpr double UntrustedCondition = 1e-4 / 2.220446049250313e-16;
} // namespace shapesplines

#endif
