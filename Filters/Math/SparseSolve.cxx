#include "SparseSolve.h"

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <utility>

namespace shapesplines
{
namespace
{
using SparseLU = Eigen::SparseLU<Eigen::SparseMatrix<double>>;

/// Widest band (lower + upper bandwidth) solved as a band: an open curve's
/// systems have at most 12; a cyclic one's corners go to the sparse LU.
constexpr int WidestBand = 16;

/**
 * LU with partial pivoting of a banded matrix (LAPACK's dgbtf2 in row-major
 * storage). Its rows are first ordered by their leftmost column, so that
 * systems assembled with their end conditions in the last rows are banded
 * too; solves take and return vectors in the original row order. For the
 * small bands of the spline systems this costs O(n) with no ordering or
 * symbolic analysis, far less than a general sparse LU.
 */
class BandLU
{
public:
  /// The factorisation, or nothing when the matrix is not narrowly banded.
  static std::optional<BandLU> factor(int n, const Triplets& entries)
  {
    BandLU lu;
    lu.N = n;
    std::vector<int> leftmost(n, n), rightmost(n, -1);
    for (const auto& entry : entries)
    {
      leftmost[entry.row()] = std::min(leftmost[entry.row()], entry.col());
      rightmost[entry.row()] = std::max(rightmost[entry.row()], entry.col());
    }
    lu.Order.resize(n);
    std::iota(lu.Order.begin(), lu.Order.end(), 0);
    std::stable_sort(lu.Order.begin(), lu.Order.end(),
      [&](int a, int b) { return leftmost[a] < leftmost[b]; });
    std::vector<int> position(n);
    int lower = 0, upper = 0;
    for (int r = 0; r < n; ++r)
    {
      const int row = lu.Order[r];
      position[row] = r;
      if (rightmost[row] >= 0)
      {
        lower = std::max(lower, r - leftmost[row]);
        upper = std::max(upper, rightmost[row] - r);
      }
    }
    if (lower + upper > WidestBand)
    {
      return std::nullopt;
    }
    lu.Lower = lower;
    lu.Width = 2 * lower + upper + 1; // pivoting fills the upper band by the lower one
    lu.Band.assign(static_cast<size_t>(n) * lu.Width, 0.0);
    for (const auto& entry : entries)
    {
      lu.at(position[entry.row()], entry.col()) += entry.value();
    }
    lu.Pivot.resize(n);
    for (int k = 0; k < n; ++k)
    {
      const int last = std::min(n - 1, k + lower);
      int p = k;
      for (int i = k + 1; i <= last; ++i)
      {
        if (std::abs(lu.at(i, k)) > std::abs(lu.at(p, k)))
        {
          p = i;
        }
      }
      lu.Pivot[k] = p;
      if (lu.at(p, k) == 0.0)
      {
        lu.Singular = true;
        return lu;
      }
      const int end = std::min(n - 1, k + lu.Width - 1 - lower);
      if (p != k)
      {
        for (int j = k; j <= end; ++j)
        {
          std::swap(lu.at(k, j), lu.at(p, j));
        }
      }
      const double diagonal = lu.at(k, k);
      for (int i = k + 1; i <= last; ++i)
      {
        const double factor = lu.at(i, k) / diagonal;
        lu.at(i, k) = factor;
        if (factor != 0.0)
        {
          for (int j = k + 1; j <= end; ++j)
          {
            lu.at(i, j) -= factor * lu.at(k, j);
          }
        }
      }
    }
    return lu;
  }

  bool singular() const { return this->Singular; }

  /// Solves A x = b (columns of b), b in the original row order.
  template <typename Matrix>
  Matrix solve(const Matrix& b) const
  {
    const int n = this->N;
    Matrix x(b.rows(), b.cols());
    for (int r = 0; r < n; ++r)
    {
      x.row(r) = b.row(this->Order[r]);
    }
    for (int k = 0; k < n; ++k)
    {
      if (this->Pivot[k] != k)
      {
        x.row(k).swap(x.row(this->Pivot[k]));
      }
      for (int i = k + 1; i <= std::min(n - 1, k + this->Lower); ++i)
      {
        x.row(i) -= this->at(i, k) * x.row(k);
      }
    }
    for (int i = n - 1; i >= 0; --i)
    {
      for (int j = i + 1; j <= std::min(n - 1, i + this->Width - 1 - this->Lower); ++j)
      {
        x.row(i) -= this->at(i, j) * x.row(j);
      }
      x.row(i) /= this->at(i, i);
    }
    return x;
  }

  /// Solves A^T y = c, y in the original row order.
  Eigen::VectorXd solveTransposed(const Eigen::VectorXd& c) const
  {
    const int n = this->N;
    Eigen::VectorXd w = c;
    for (int i = 0; i < n; ++i)
    {
      for (int j = std::max(0, i - (this->Width - 1 - this->Lower)); j < i; ++j)
      {
        w[i] -= this->at(j, i) * w[j];
      }
      w[i] /= this->at(i, i);
    }
    for (int k = n - 1; k >= 0; --k)
    {
      for (int i = k + 1; i <= std::min(n - 1, k + this->Lower); ++i)
      {
        w[k] -= this->at(i, k) * w[i];
      }
      if (this->Pivot[k] != k)
      {
        std::swap(w[k], w[this->Pivot[k]]);
      }
    }
    Eigen::VectorXd y(n);
    for (int r = 0; r < n; ++r)
    {
      y[this->Order[r]] = w[r];
    }
    return y;
  }

private:
  double& at(int i, int j) { return this->Band[static_cast<size_t>(i) * this->Width + j - i + this->Lower]; }
  double at(int i, int j) const
  {
    return this->Band[static_cast<size_t>(i) * this->Width + j - i + this->Lower];
  }

  int N = 0;
  int Lower = 0;
  int Width = 1;
  bool Singular = false;
  std::vector<int> Order; ///< original row of each factored row
  std::vector<int> Pivot; ///< row swapped with row k at step k
  std::vector<double> Band;
};

/// Solves with a SparseLU and its transpose, as BandLU does.
class GeneralLU
{
public:
  explicit GeneralLU(SparseLU& lu)
    : LU(lu)
  {
  }
  template <typename Matrix>
  Matrix solve(const Matrix& b) const
  {
    return this->LU.solve(b);
  }
  Eigen::VectorXd solveTransposed(const Eigen::VectorXd& c) const
  {
    return this->LU.transpose().solve(c);
  }

private:
  SparseLU& LU; // transpose() is not const
};

/**
 * Factorises the n x n matrix of entries, as a band when it is one, and
 * calls use(factorisation); false, without calling, when it is singular.
 * The solve and its later condition estimate factorise alike.
 */
template <typename Use>
bool withFactorisation(int n, const Triplets& entries, Use&& use)
{
  if (const std::optional<BandLU> band = BandLU::factor(n, entries))
  {
    if (band->singular())
    {
      return false;
    }
    use(*band);
    return true;
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  SparseLU lu;
  lu.compute(matrix);
  if (lu.info() != Eigen::Success)
  {
    return false;
  }
  use(GeneralLU(lu));
  return true;
}

/**
 * Estimates ||A^-1||_1 from a factorisation of the n x n matrix A (Hager's
 * method with Higham's safeguard, LAPACK's xLACON): a lower bound, in
 * practice within a factor of a few of the true value.
 */
template <typename Factorisation>
double inverseOneNorm(const Factorisation& lu, int n)
{
  Eigen::VectorXd x = Eigen::VectorXd::Constant(n, 1.0 / n);
  double estimate = 0.0;
  Eigen::Index previous = -1;
  for (int iteration = 0; iteration < 5; ++iteration)
  {
    const Eigen::VectorXd y = lu.solve(x);
    estimate = std::max(estimate, y.lpNorm<1>());
    const Eigen::VectorXd sign = y.unaryExpr([](double v) { return v >= 0.0 ? 1.0 : -1.0; });
    const Eigen::VectorXd z = lu.solveTransposed(sign);
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
  for (int i = 0; i < n; ++i)
  {
    alternating[i] = (i % 2 == 0 ? 1.0 : -1.0) * (1.0 + (n > 1 ? double(i) / (n - 1) : 0.0));
  }
  const double safeguard =
    2.0 * lu.solve(alternating).template lpNorm<1>() / (3.0 * n);
  return std::max(estimate, safeguard);
}

/// The 1-norm condition number of the matrix of entries, from its factorisation.
template <typename Factorisation>
double conditionOf(const Factorisation& lu, int n, const Triplets& entries)
{
  Eigen::VectorXd columnSums = Eigen::VectorXd::Zero(n);
  for (const auto& entry : entries)
  {
    columnSums[entry.col()] += std::abs(entry.value());
  }
  return columnSums.maxCoeff() * inverseOneNorm(lu, n);
}

/**
 * D^-1 A and D^-1 B, D each row's largest |a_ij| (rows of zeros kept): the
 * system an LU with partial pivoting solves to rounding whatever the rows'
 * scales. Unscaled, a tiny end span's row (entries ~ 1 / h^3) let the
 * pivots lose the interpolation rows' accuracy: a qqr curve with an end
 * span 2e-6 of the others missed its points by 5e-5 at a condition of 3e6.
 */
std::pair<Triplets, Eigen::MatrixX3d> equilibrateRows(
  int n, const Triplets& entries, const Eigen::MatrixX3d& rhs)
{
  Eigen::VectorXd rowScale = Eigen::VectorXd::Zero(n);
  for (const auto& entry : entries)
  {
    rowScale[entry.row()] = std::max(rowScale[entry.row()], std::abs(entry.value()));
  }
  rowScale = rowScale.unaryExpr([](double scale) { return scale > 0.0 ? scale : 1.0; });
  Triplets scaled;
  scaled.reserve(entries.size());
  for (const auto& entry : entries)
  {
    scaled.emplace_back(entry.row(), entry.col(), entry.value() / rowScale[entry.row()]);
  }
  return { std::move(scaled), rhs.array().colwise() / rowScale.array() };
}

[[noreturn]] void singularSystem()
{
  // Eigen's own words ("structurally singular, zero column") say nothing to a user.
  throw SingularSystem();
}
} // namespace

Eigen::MatrixX3d solveSparse(
  int n, const Triplets& rawEntries, const Eigen::MatrixX3d& rawRhs, DeferredCondition* condition)
{
  auto scaled = equilibrateRows(n, rawEntries, rawRhs);
  const Eigen::MatrixX3d& rhs = scaled.second;
  Eigen::MatrixX3d solution;
  if (!withFactorisation(n, scaled.first, [&](const auto& lu) { solution = lu.solve(rhs); }))
  {
    singularSystem();
  }
  if (!solution.allFinite())
  {
    throw std::runtime_error("spline system could not be solved");
  }
  if (condition)
  {
    condition->record(n, std::move(scaled.first));
  }
  return solution;
}

void DeferredCondition::record(int n, Triplets entries)
{
  this->Pending.push_back({ n, std::move(entries) });
}

void DeferredCondition::merge(DeferredCondition other)
{
  this->Pending.insert(this->Pending.end(), std::make_move_iterator(other.Pending.begin()),
    std::make_move_iterator(other.Pending.end()));
  this->Largest = std::max(this->Largest, other.Largest);
}

double DeferredCondition::value() const
{
  for (const System& system : this->Pending)
  {
    // Factorised again: the solve's factorisation was not kept for it.
    double estimate = std::numeric_limits<double>::infinity();
    withFactorisation(system.Unknowns, system.Entries,
      [&](const auto& lu) { estimate = conditionOf(lu, system.Unknowns, system.Entries); });
    this->Largest = std::max(this->Largest, estimate);
  }
  this->Pending.clear();
  return this->Largest;
}
} // namespace shapesplines
