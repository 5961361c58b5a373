// The automatic shape mode every family shares (preserveShapeAutomatically),
// on toy families whose levels do known things, and every family's default
// mode on the data users have (noisy helices and trefoils, random 3D
// polylines, 3D staircases), generated here.
#include "AutomaticShape.h"
#include "GeneralizedCubicSpline.h"
#include "MathTestUtilities.h"
#include "QQRSpline.h"
#include "SparseSolve.h"
#include "TensionQuinticFit.h"
#include "VariableDegreeSpline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <string>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
/// What a toy run varies: its curve (see ToyCurve) and its ladder's options.
struct Toy
{
  double Wiggle = 0.0;
  int WiggleFrom = 0; ///< the first span that wiggles (the others blend with their chords)
  int TwistedSpan = -1;
  /// The twist sits two spans past the highest span raised (TwistedSpan
  /// while none is): each raise moves the violation on, never away.
  bool TwistRunsAhead = false;
  /// A second twist, on span MovingTwist[0] while it is at level 0, on span
  /// MovingTwist[1] once it is raised (far away: no round's audit sees it).
  std::array<int, 2> MovingTwist{ -1, -1 };
  double Detour = 0.0;
  bool Uniform = false;
  bool RetryFromCommonLevel = false;
  bool RaiseTwistNeighbours = true;
  unsigned Mends = ~0u;
  /// Refining after the searches (off: the tests of the search count its builds alone).
  bool Refine = false;
  /// Raising this span makes the family's system singular (Build throws).
  int SingularSpan = -1;
  ProgressCallback Progress;
};

/**
 * A toy family with a level per span: the cubic through the data, on each
 * span blended with its chord by w = min(1, level / 2) (w = 1: the span is
 * straight, which breaks no criterion of Definition 1), and, with Wiggle,
 * a bump of level * Wiggle * h out of the plane z = 0 added instead (more
 * violations the higher the level on planar data). With TwistedSpan, that
 * span of the cubic carries a twist along z, h tau^4 (1 - tau)^4 * 16, which
 * vanishes at its knots to the third derivative: the span's torsion changes
 * sign, its knots' does not; the blend with the chord takes it away (the
 * same for MovingTwist's). With Detour, a span at level 1 bulges Detour * h
 * off its chord instead of half blending (beyond the automatic mode's
 * deviation bound when large).
 */
class ToyCurve final : public Curve
{
public:
  ToyCurve(const CleanPolyline& data, const std::vector<double>& knots, std::vector<int> levels,
    const Toy& toy)
    : Curve(knots, data.Closed)
    , Cubic(CubicSpline::interpolate(data.Points, knots, data.Closed))
    , Points(data.Points)
    , Levels(std::move(levels))
    , Wiggle(toy.Wiggle)
    , WiggleFrom(toy.WiggleFrom)
    , TwistedSpan(toy.TwistRunsAhead ? twistAhead(this->Levels, toy.TwistedSpan) : toy.TwistedSpan)
    , MovedTwist(toy.MovingTwist[0] < 0 || this->Levels[toy.MovingTwist[0]] == 0
          ? toy.MovingTwist[0]
          : toy.MovingTwist[1])
    , Detour(toy.Detour)
  {
  }

  Derivatives evaluateOnSpan(int span, double t, int order) const override
  {
    Derivatives d = this->Cubic.evaluateOnSpan(span, t, order);
    const double h = this->Knots[span + 1] - this->Knots[span];
    const double tau = (t - this->Knots[span]) / h;
    if (span == this->TwistedSpan || span == this->MovedTwist)
    {
      // d^m/dt^m of 16 h tau^4 (1 - tau)^4, by its power form in tau.
      const std::array<double, 9> twist{ 0, 0, 0, 0, 16, -64, 96, -64, 16 };
      for (int m = 0; m <= order; ++m)
      {
        double value = 0.0;
        for (int n = 8; n >= m; --n)
        {
          double falling = 1.0;
          for (int i = 0; i < m; ++i)
          {
            falling *= n - i;
          }
          value += twist[n] * falling * std::pow(tau, n - m);
        }
        d[m].z() += value * h / std::pow(h, m);
      }
    }
    if (this->Wiggle > 0.0 && span >= this->WiggleFrom)
    {
      const double a = this->Levels[span] * this->Wiggle * h;
      const double w = 2.0 * Pi / h;
      for (int m = 0; m <= order; ++m)
      {
        const double phase = 2.0 * Pi * tau + 0.5 * Pi * m; // d^m/dt^m sin
        d[m].z() += a * std::pow(w, m) * std::sin(phase);
      }
      return d;
    }
    if (this->Detour > 0.0 && this->Levels[span] == 1)
    {
      const double a = this->Detour * h;
      const double w = Pi / h;
      for (int m = 0; m <= order; ++m)
      {
        d[m].z() += a * std::pow(w, m) * std::sin(Pi * tau + 0.5 * Pi * m); // d^m/dt^m sin
      }
      return d;
    }
    const double w = std::min(1.0, 0.5 * this->Levels[span]);
    const Vec3& a = this->Points[span];
    const Vec3& b = this->Points[(span + 1) % this->Points.size()];
    for (Vec3& v : d)
    {
      v *= 1.0 - w;
    }
    d[0] += w * (a + tau * (b - a));
    if (order >= 1)
    {
      d[1] += w * (b - a) / h;
    }
    return d;
  }

  static int twistAhead(const std::vector<int>& levels, int start)
  {
    for (int j = static_cast<int>(levels.size()) - 1; j >= 0; --j)
    {
      if (levels[j] > 0)
      {
        return j + 2;
      }
    }
    return start;
  }

  std::vector<SpanParameter> spanParameters() const override
  {
    return { { "Level", std::vector<double>(this->Levels.begin(), this->Levels.end()), true } };
  }

private:
  CubicSpline Cubic;
  std::vector<Vec3> Points;
  std::vector<int> Levels;
  double Wiggle;
  int WiggleFrom;
  int TwistedSpan;
  int MovedTwist;
  double Detour;
};

struct ToyRun
{
  int Builds = 0;
  std::vector<int> Levels;
  std::vector<int> FirstRaise; ///< the levels of the first round's curve
};

/// What a toy builder runs: the whole automatic mode, or a part of it.
using AutomaticDriver =
  std::function<AutomaticShape(const FitContext&, const CleanPolyline&, const ShapeLadder&)>;

CurveBuilder toyBuilder(
  ToyRun& run, const Toy& toy = {}, AutomaticDriver driver = preserveShapeAutomatically)
{
  return [&run, toy, driver](const FitContext& context) {
    ShapeLadder ladder;
    ladder.TopLevel = 2;
    ladder.Uniform = toy.Uniform;
    ladder.RetryFromCommonLevel = toy.RetryFromCommonLevel;
    ladder.RaiseTwistNeighbours = toy.RaiseTwistNeighbours;
    ladder.Mends = toy.Mends;
    ladder.Refine = toy.Refine;
    ladder.Build = [&](const std::vector<int>& levels) -> std::unique_ptr<Curve> {
      if (++run.Builds == 2)
      {
        run.FirstRaise = levels;
      }
      if (toy.SingularSpan >= 0 && levels[toy.SingularSpan] > 0)
      {
        throw SingularSystem();
      }
      return std::make_unique<ToyCurve>(context.Data, context.Knots, levels, toy);
    };
    FitOptions options = context.Options;
    options.Progress = toy.Progress;
    const FitContext withProgress{ context.Data, context.Knots, options, context.CoordinateNoise,
      context.PointValues, context.RoundingSteps };
    AutomaticShape found = driver(withProgress, context.Data, ladder);
    run.Levels = found.Levels;
    return builtCurve(std::move(found));
  };
}

/// A straight run of 100 points, then the Akima data: the cubic fails only
/// in and near the Akima part.
std::vector<Vec3> straightRunThenAkima()
{
  std::vector<Vec3> points;
  for (int i = -100; i < 0; ++i)
  {
    points.emplace_back(i, 10.0, 0.0);
  }
  for (const Vec3& p : akima())
  {
    points.push_back(p);
  }
  return points;
}
} // namespace

TEST(AutomaticShape, RaisesOnlyTheFailingSpansUntilNoneFails)
{
  const FittedPolyline cubic = fitPolyline(akima(), FitOptions{}, cubicBuilder());
  ASSERT_FALSE(cubic.Audit.preserving());
  ToyRun run;
  const FittedPolyline fit = fitPolyline(akima(), FitOptions{}, toyBuilder(run));
  EXPECT_TRUE(fit.Audit.preserving()) << fit.Audit.violations();
  // Its own audit agrees with an independent one of the final curve.
  EXPECT_EQ(fit.Audit.SpanMask,
    auditCurve(*fit.Spline, fit.Data, fit.Shape, FitOptions{}.Tolerances, 16, fit.CoordinateNoise).SpanMask);
  // A level moves its own span only: exactly the spans the cubic failed are
  // raised (planar data: no torsion, whose failures also raise neighbours).
  for (size_t j = 0; j < run.Levels.size(); ++j)
  {
    EXPECT_EQ(run.Levels[j] > 0, cubic.Audit.SpanMask[j] != 0) << "span " << j;
  }
  EXPECT_LE(run.Builds, 4);
}

TEST(AutomaticShape, ARaiseThatMakesTheSystemSingularIsUndoneAndFrozen)
{
  // qqr's local parameters can make an open line's end condition depend on
  // the other rows: that level is not a curve, and the search goes on
  // without it instead of failing the line.
  const FittedPolyline cubic = fitPolyline(akima(), FitOptions{}, cubicBuilder());
  const std::vector<unsigned>& masks = cubic.Audit.SpanMask;
  const auto failing =
    std::find_if(masks.begin(), masks.end(), [](unsigned mask) { return mask != 0; });
  ASSERT_NE(failing, masks.end());
  Toy singular;
  singular.SingularSpan = static_cast<int>(failing - masks.begin());
  ToyRun run;
  const FittedPolyline fit = fitPolyline(akima(), FitOptions{}, toyBuilder(run, singular));
  ASSERT_TRUE(fit.Spline);
  EXPECT_EQ(run.Levels[singular.SingularSpan], 0);
  EXPECT_NE(fit.Audit.SpanMask[singular.SingularSpan], 0u);
  EXPECT_LT(fit.Audit.violations(), cubic.Audit.violations());
}

TEST(AutomaticShape, ASpanWhoseTorsionChangesSignRaisesItsNeighboursWithIt)
{
  // Raised alone, such a span pushes its torsion's sign change into the next
  // span (the third derivative spreads through a family's solve): the driver
  // raises the neighbours in the same round. A clean helix whose span 20
  // alone twists: the first round raises spans 19 to 21, and no other; a
  // ladder that turns that off (qqr's flattening: neighbouring knots
  // flattened make its interpolation singular) raises span 20 alone.
  const std::vector<Vec3> points = helix(16, 3);
  constexpr int Twisted = 20;
  for (const bool neighbours : { true, false })
  {
    Toy twisted;
    twisted.TwistedSpan = Twisted;
    twisted.RaiseTwistNeighbours = neighbours;
    ToyRun run;
    const FittedPolyline fit = fitPolyline(points, FitOptions{}, toyBuilder(run, twisted));
    EXPECT_TRUE(fit.Audit.preserving()) << fit.Audit.violations();
    ASSERT_FALSE(run.FirstRaise.empty());
    for (int j = 0; j < static_cast<int>(run.FirstRaise.size()); ++j)
    {
      const int reach = neighbours ? 1 : 0;
      EXPECT_EQ(run.FirstRaise[j] > 0, std::abs(j - Twisted) <= reach) << "span " << j;
    }
  }
  // The twist is what failed: without it the helix needs no raise.
  ToyRun clean;
  EXPECT_TRUE(fitPolyline(points, FitOptions{}, toyBuilder(clean)).Audit.preserving());
  EXPECT_EQ(clean.Builds, 1);
}

TEST(AutomaticShape, ALadderLeavesAloneTheSpansWhereLevelZeroFailsWhatItDoesNotMend)
{
  // Akima's cubic fails convexity and collinearity (planar: no torsion). A
  // ladder meant for torsion signs only leaves those spans (and their
  // neighbours) at level 0, so nothing is raised after the first build; the
  // same ladder meant for everything mends them. The twisted helix fails only
  // the torsion sign: the torsion ladder searches it; entered by a straight
  // run, whose spans the cubic bends (collinearity), it still mends the twist
  // (a long line fails a little of everything: qqr's flattening had not been
  // searched on a noisy helix of 2e4 points for one convexity failure) and
  // leaves the run as the cubic makes it.
  Toy forTorsion;
  forTorsion.Mends = criterionBit(ShapeCriterion::TorsionSignAtKnot) |
    criterionBit(ShapeCriterion::TorsionSignOnSpan);
  ToyRun skipped;
  const FittedPolyline akimaFit =
    fitPolyline(akima(), FitOptions{}, toyBuilder(skipped, forTorsion));
  EXPECT_EQ(skipped.Builds, 1);
  EXPECT_EQ(std::count(skipped.Levels.begin(), skipped.Levels.end(), 0),
    static_cast<long>(skipped.Levels.size()));
  EXPECT_EQ(akimaFit.Audit.violations(),
    fitPolyline(akima(), FitOptions{}, cubicBuilder()).Audit.violations());
  ToyRun searched;
  EXPECT_TRUE(fitPolyline(akima(), FitOptions{}, toyBuilder(searched)).Audit.preserving());
  forTorsion.TwistedSpan = 20;
  ToyRun twisted;
  const FittedPolyline helixFit =
    fitPolyline(helix(16, 3), FitOptions{}, toyBuilder(twisted, forTorsion));
  EXPECT_TRUE(helixFit.Audit.preserving()) << helixFit.Audit.violations();
  EXPECT_GT(twisted.Builds, 1);

  std::vector<Vec3> entered;
  for (int k = 4; k > 0; --k)
  {
    entered.emplace_back(2.0 + k, -3.0 * k, 0.0); // a straight run towards the helix' start
  }
  const std::vector<Vec3> turns = helix(16, 3);
  entered.insert(entered.end(), turns.begin(), turns.end());
  forTorsion.TwistedSpan = 24;
  const FittedPolyline cubic = fitPolyline(entered, FitOptions{}, cubicBuilder());
  const int collinearity = static_cast<int>(ShapeCriterion::Collinearity);
  ASSERT_GT(cubic.Audit.Failures[collinearity], 0);
  ToyRun mixed;
  const FittedPolyline mixedFit = fitPolyline(entered, FitOptions{}, toyBuilder(mixed, forTorsion));
  EXPECT_EQ(mixedFit.Audit.Failures[static_cast<int>(ShapeCriterion::TorsionSignOnSpan)], 0);
  EXPECT_GT(mixed.Levels[24], 0);
  EXPECT_EQ(mixedFit.Audit.Failures[collinearity], cubic.Audit.Failures[collinearity]);
  EXPECT_EQ(mixed.Levels[0] + mixed.Levels[1] + mixed.Levels[2], 0);
}

TEST(AutomaticShape, UniformLadderRaisesEverySpanTogether)
{
  Toy uniform;
  uniform.Uniform = true;
  ToyRun run;
  const FittedPolyline fit = fitPolyline(akima(), FitOptions{}, toyBuilder(run, uniform));
  EXPECT_TRUE(fit.Audit.preserving());
  EXPECT_EQ(std::count(run.Levels.begin(), run.Levels.end(), run.Levels.front()),
    static_cast<long>(run.Levels.size()));
  EXPECT_GT(run.Levels.front(), 0);
}

TEST(AutomaticShape, SearchesFromACommonLevelWhereOneStepUpBreaksTheBounds)
{
  // One level up takes a span five chords off its chord (beyond the
  // deviation bound: undone, frozen), two levels straighten it. Span by
  // span the search keeps the cubic; from the common level 2 nothing fails.
  const FittedPolyline cubic = fitPolyline(akima(), FitOptions{}, cubicBuilder());
  ASSERT_GT(cubic.Audit.violations(), 0);
  for (const bool retry : { false, true })
  {
    Toy detour;
    detour.Detour = 5.0;
    detour.RetryFromCommonLevel = retry;
    ToyRun run;
    const FittedPolyline fit = fitPolyline(akima(), FitOptions{}, toyBuilder(run, detour));
    const std::vector<int>& levels = run.Levels;
    const long spans = static_cast<long>(levels.size());
    if (retry)
    {
      EXPECT_TRUE(fit.Audit.preserving());
      EXPECT_EQ(std::count(levels.begin(), levels.end(), 2), spans);
    }
    else
    {
      EXPECT_EQ(fit.Audit.violations(), cubic.Audit.violations());
      EXPECT_EQ(std::count(levels.begin(), levels.end(), 0), spans);
    }
  }
}

TEST(AutomaticShape, SearchesFromEachWindowsBestCommonLevel)
{
  // Two spans fail far apart (more than twice RetryReach): span 5's twist,
  // whose span and neighbours bulge beyond the bounds at level 1 and are
  // straight at 2, and span 100's, which stays whatever its level and whose
  // neighbourhood wiggles out of plane when raised. The first search keeps
  // both; the common level 2 mends the first window but breaks the second
  // more, so no common level beats the first search. Each window at its own
  // best level (2 around span 5, 0 around span 100) leaves only the twist
  // at span 100 (both were left before).
  Toy apart;
  apart.TwistedSpan = 5;
  apart.Detour = 5.0;
  apart.MovingTwist = { 100, 100 };
  apart.Wiggle = 0.05;
  apart.WiggleFrom = 70;
  apart.RetryFromCommonLevel = true;
  ToyRun run;
  const FittedPolyline fit = fitPolyline(helix(16, 8), FitOptions{}, toyBuilder(run, apart));
  EXPECT_EQ(fit.Audit.violations(), 1);
  ASSERT_EQ(fit.Audit.Where.size(), 1u);
  EXPECT_EQ(fit.Audit.Where[0].Where, 100);
  EXPECT_EQ(run.Levels[5], 2);
  EXPECT_EQ(run.Levels[100], 0);
}

TEST(AutomaticShape, SearchesAgainOnlyAroundWhatTheFirstSearchLeftFailing)
{
  // The Akima data after a straight run of 100 points: the cubic fails only
  // in and near the Akima part. The first search keeps the cubic (one step
  // up detours beyond the bounds); the retry from the common level searches
  // only within RetryReach spans of the failing ones: the run's far spans keep level 0.
  const std::vector<Vec3> points = straightRunThenAkima();
  const FittedPolyline cubic = fitPolyline(points, FitOptions{}, cubicBuilder());
  ASSERT_GT(cubic.Audit.violations(), 0);
  const int spans = static_cast<int>(cubic.Audit.SpanMask.size());
  const int firstFailing = static_cast<int>(std::find_if(cubic.Audit.SpanMask.begin(),
                             cubic.Audit.SpanMask.end(), [](unsigned mask) { return mask != 0; }) -
    cubic.Audit.SpanMask.begin());
  ASSERT_GT(firstFailing, 40); // the run's far spans pass as the cubic
  Toy detour;
  detour.Detour = 5.0;
  detour.RetryFromCommonLevel = true;
  ToyRun run;
  const FittedPolyline fit = fitPolyline(points, FitOptions{}, toyBuilder(run, detour));
  EXPECT_TRUE(fit.Audit.preserving());
  for (int j = 0; j < spans; ++j)
  {
    EXPECT_EQ(run.Levels[j], j < firstFailing - RetryReach ? 0 : 2) << "span " << j;
  }
}

TEST(AutomaticShape, ImprovingAFirstSearchDoesWhatTheWholeModeDoesAfterIt)
{
  // Where one step up detours beyond the bounds, the first search alone
  // keeps the cubic's violations; improving its curve (the retry from the
  // common level) mends them as the whole mode does, with the same levels,
  // building only what the whole mode builds after its first search.
  const std::vector<Vec3> points = straightRunThenAkima();
  Toy detour;
  detour.Detour = 5.0;
  detour.RetryFromCommonLevel = true;
  ToyRun first;
  const FittedPolyline searched =
    fitPolyline(points, FitOptions{}, toyBuilder(first, detour, searchShape));
  const FittedPolyline cubic = fitPolyline(points, FitOptions{}, cubicBuilder());
  EXPECT_EQ(searched.Audit.violations(), cubic.Audit.violations());
  ASSERT_GT(searched.Audit.violations(), 0);
  ToyRun whole;
  const FittedPolyline mended = fitPolyline(points, FitOptions{}, toyBuilder(whole, detour));
  EXPECT_TRUE(mended.Audit.preserving());
  ToyRun stages;
  int buildsBeforeImproving = -1;
  auto improveFirstSearch = [&](const FitContext& context, const CleanPolyline& reference,
                              const ShapeLadder& ladder) {
    AutomaticShape found = searchShape(context, reference, ladder);
    buildsBeforeImproving = stages.Builds;
    return improveShape(std::move(found), context, reference, ladder);
  };
  const FittedPolyline improved =
    fitPolyline(points, FitOptions{}, toyBuilder(stages, detour, improveFirstSearch));
  EXPECT_TRUE(improved.Audit.preserving());
  EXPECT_EQ(stages.Levels, whole.Levels);
  EXPECT_EQ(buildsBeforeImproving, first.Builds);
  EXPECT_GT(stages.Builds, first.Builds);
  EXPECT_EQ(stages.Builds, whole.Builds);

  // A curve without violations is returned as it is: nothing is built.
  int buildsOfMendedCurve = -1;
  ToyRun again;
  auto improveTwice = [&](const FitContext& context, const CleanPolyline& reference,
                        const ShapeLadder& ladder) {
    AutomaticShape found =
      improveShape(searchShape(context, reference, ladder), context, reference, ladder);
    buildsOfMendedCurve = again.Builds;
    return improveShape(std::move(found), context, reference, ladder);
  };
  fitPolyline(points, FitOptions{}, toyBuilder(again, detour, improveTwice));
  EXPECT_EQ(again.Builds, buildsOfMendedCurve);
  EXPECT_EQ(again.Levels, whole.Levels);
}

TEST(AutomaticShape, KeepsTheBestCurveMetAndStopsRaisingWhatDoesNotHelp)
{
  // Every level adds a wiggle out of the data's plane: raising only adds
  // violations. The mode ends with the start's curve, after a few rounds.
  const FittedPolyline cubic = fitPolyline(akima(), FitOptions{}, cubicBuilder());
  Toy wiggling;
  wiggling.Wiggle = 0.05;
  ToyRun run;
  const FittedPolyline fit = fitPolyline(akima(), FitOptions{}, toyBuilder(run, wiggling));
  EXPECT_EQ(fit.Audit.violations(), cubic.Audit.violations());
  EXPECT_EQ(std::count(run.Levels.begin(), run.Levels.end(), 0), static_cast<long>(run.Levels.size()));
  EXPECT_LE(run.Builds, 10);
}

TEST(AutomaticShape, RefiningKeepsOnlyWhatLowersTheViolationsWithinItsBudget)
{
  // Raising only adds violations (the wiggling toy): refining after the
  // search tries each span near one left failing at other levels, keeps
  // none of them, and stops within its budget of builds.
  const FittedPolyline cubic = fitPolyline(akima(), FitOptions{}, cubicBuilder());
  Toy wiggling;
  wiggling.Wiggle = 0.05;
  ToyRun searched;
  fitPolyline(akima(), FitOptions{}, toyBuilder(searched, wiggling));
  wiggling.Refine = true;
  ToyRun refined;
  const FittedPolyline fit = fitPolyline(akima(), FitOptions{}, toyBuilder(refined, wiggling));
  EXPECT_EQ(fit.Audit.violations(), cubic.Audit.violations());
  EXPECT_EQ(std::count(refined.Levels.begin(), refined.Levels.end(), 0),
    static_cast<long>(refined.Levels.size()));
  const int spans = static_cast<int>(refined.Levels.size());
  EXPECT_GT(refined.Builds, searched.Builds); // refining tried
  // Its trials and the searches' curve built again (an interpolation's
  // refining needs no level-0 curve).
  EXPECT_LE(refined.Builds, searched.Builds + RefineTrialsPerSpan * spans + 1);


  // No trial is kept, so a span listed next to several failing ones meets
  // the same curve each time: it is built at each of its other levels (1 and
  // the top, 2) once. On a longer line, whose budget does not bind.
  const std::vector<Vec3> longer = straightRunThenAkima();
  wiggling.Refine = false;
  ToyRun longerSearched;
  const FittedPolyline searchedFit = fitPolyline(longer, FitOptions{}, toyBuilder(longerSearched, wiggling));
  wiggling.Refine = true;
  ToyRun longerRefined;
  fitPolyline(longer, FitOptions{}, toyBuilder(longerRefined, wiggling));
  const int longerSpans = static_cast<int>(longer.size()) - 1;
  std::vector<char> listed(longerSpans, 0);
  int timesListed = 0;
  for (int j = 0; j < longerSpans; ++j)
  {
    if (searchedFit.Audit.SpanMask[j] != 0)
    {
      for (int k = std::max(0, j - RefineReach); k <= std::min(longerSpans - 1, j + RefineReach); ++k)
      {
        listed[k] = 1;
        ++timesListed;
      }
    }
  }
  const int distinct = static_cast<int>(std::count(listed.begin(), listed.end(), 1));
  const int builds = longerRefined.Builds - longerSearched.Builds;
  std::printf("refining the wiggling toy: %d spans listed %d times, %d builds after the searches\n",
    distinct, timesListed, builds);
  ASSERT_GT(timesListed, distinct) << "no span listed twice: the check would not tell";
  ASSERT_LT(2 * timesListed, RefineTrialsPerSpan * longerSpans) << "the budget binds";
  EXPECT_LE(builds, 2 * distinct + 1);
}

TEST(AutomaticShape, GivesUpAfterRoundsThatMeetNoBetterCurve)
{
  // Each raise mends its span and moves the twist two spans on: one
  // violation every round, never fewer, and no span raised twice (none
  // frozen). The search stops eight rounds after its best, not at the 64
  // rounds' cap (a long line's whole-line solves spent that way for nothing).
  Toy ahead;
  ahead.TwistedSpan = 20;
  ahead.TwistRunsAhead = true;
  ToyRun run;
  const FittedPolyline fit = fitPolyline(helix(16, 16), FitOptions{}, toyBuilder(run, ahead));
  EXPECT_EQ(fit.Audit.violations(), 1);
  EXPECT_LE(run.Builds, 12);
  EXPECT_GE(run.Builds, 9); // the eight rounds, after the start
}

TEST(AutomaticShape, SearchesOnFromTheBestCurveWhereItsWholeAuditFindsWhatTheRoundsMissed)
{
  // Raising span 2 mends its twist and twists span 12, beyond the reach of
  // the round's audit: the first round's curve counts one violation (the
  // twist running ahead from span 20), the best met, and the search gives up
  // eight rounds later. Audited whole, the best curve fails at span 12 too;
  // the search goes on from it and straightens span 12 (its result kept 2
  // violations before).
  Toy hidden;
  hidden.TwistedSpan = 20;
  hidden.TwistRunsAhead = true;
  hidden.MovingTwist = { 2, 12 };
  ToyRun run;
  const FittedPolyline fit = fitPolyline(helix(16, 16), FitOptions{}, toyBuilder(run, hidden));
  EXPECT_EQ(fit.Audit.violations(), 1);
  EXPECT_GT(run.Levels[2], 0);
  EXPECT_EQ(run.Levels[12], 2);
  EXPECT_EQ(fit.Audit.Failures[static_cast<int>(ShapeCriterion::TorsionSignOnSpan)], 1);
}

TEST(AutomaticShape, ReportsProgressEveryRoundAndStopsWhenAsked)
{
  int calls = 0;
  Toy counted;
  counted.Progress = [&](double) { return ++calls > 0; };
  ToyRun run;
  fitPolyline(akima(), FitOptions{}, toyBuilder(run, counted));
  EXPECT_GE(calls, 2);
  Toy stopping;
  stopping.Progress = [](double) { return false; };
  ToyRun stopped;
  EXPECT_THROW(fitPolyline(akima(), FitOptions{}, toyBuilder(stopped, stopping)), FitAborted);
}

TEST(AutomaticShape, ASearchsProgressNeverGoesBackAndRefiningReportsTheSecondHalf)
{
  // Its whole audits only check for an abort: they had reported their own
  // fraction of the spans, back to 0 after a round (and on a long line up to
  // the end of it before the first raise).
  std::vector<double> fractions;
  Toy toy;
  toy.Wiggle = 0.05; // raising only adds violations: rounds, then refining tries every level
  toy.Refine = true;
  toy.Progress = [&](double fraction) {
    fractions.push_back(fraction);
    return true;
  };
  ToyRun run;
  fitPolyline(akima(), FitOptions{}, toyBuilder(run, toy, searchShape));
  ASSERT_GE(fractions.size(), 3u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_GT(fractions.back(), 0.0);
  EXPECT_LE(fractions.back(), 0.5);

  fractions.clear();
  ToyRun whole;
  fitPolyline(akima(), FitOptions{}, toyBuilder(whole, toy));
  const auto refining =
    std::find_if(fractions.begin(), fractions.end(), [](double f) { return f >= 0.5; });
  ASSERT_NE(refining, fractions.end()) << "refining reported nothing";
  EXPECT_TRUE(std::is_sorted(refining, fractions.end()));
  EXPECT_LT(fractions.back(), 1.0);
}

TEST(AutomaticShape, KnotLevelsTakeTheHigherSpan)
{
  EXPECT_EQ(knotLevels({ 0, 2, 1 }, false), (std::vector<int>{ 0, 2, 2, 1 }));
  EXPECT_EQ(knotLevels({ 0, 2, 1 }, true), (std::vector<int>{ 1, 2, 2 }));
  const auto doubling = [](double x) { return std::min(8.0, 2.0 * x); };
  EXPECT_EQ(raisedTimes(1.0, 2, doubling), 4.0);
  EXPECT_EQ(raisedTimes(1.0, 9, doubling), 8.0);
  EXPECT_EQ(stepsToCap(1.0, doubling), 3);
}

namespace
{
struct Family
{
  const char* Name;
  CurveBuilder Fixed, Automatic;
  bool AlwaysPreserves; ///< reaches zero violations on every line of usersData()
};

/// Whether a curve's span parameter of that name (qqr's "Flattening",
/// "Straightness") is above 0 on some span.
bool movedSomewhere(const Curve& curve, const std::string& name)
{
  for (const SpanParameter& parameter : curve.spanParameters())
  {
    const auto& values = parameter.Values;
    if (parameter.Name == name &&
      std::any_of(values.begin(), values.end(), [](double value) { return value > 0.0; }))
    {
      return true;
    }
  }
  return false;
}

std::vector<Family> families()
{
  GeneralizedCubicOptions generalized;
  VariableDegreeOptions degree;
  QuinticFitOptions quintic;
  QQROptions qqr;
  std::vector<Family> all;
  all.push_back({ "generalized cubic", nullptr, generalizedCubicBuilder(generalized), true });
  all.push_back({ "variable degree", nullptr, variableDegreeBuilder(degree), true });
  all.push_back({ "tension quintic", nullptr, tensionQuinticBuilder(quintic), false });
  all.push_back({ "qqr", nullptr, qqrBuilder(qqr), false });
  generalized.Automatic = degree.Automatic = quintic.Automatic = qqr.Automatic = false;
  all[0].Fixed = generalizedCubicBuilder(generalized);
  all[1].Fixed = variableDegreeBuilder(degree);
  all[2].Fixed = tensionQuinticBuilder(quintic);
  all[3].Fixed = qqrBuilder(qqr);
  return all;
}

/// A line fitted by a family's fixed and default (automatic) modes, and the
/// figures the bounds limit.
struct BothModes
{
  FittedPolyline Fixed, Automatic;
  BoundFigures FixedBounds, AutomaticBounds;
};

BothModes fitBoth(const Family& family, const std::vector<Vec3>& points)
{
  BothModes both{ fitPolyline(points, FitOptions{}, family.Fixed),
    fitPolyline(points, FitOptions{}, family.Automatic), {}, {} };
  both.FixedBounds = boundFigures(both.Fixed);
  both.AutomaticBounds = boundFigures(both.Automatic);
  return both;
}
} // namespace

TEST(AutomaticShape, EveryFamilysDefaultModeOnUsersDataKeepsTheCurveRegular)
{
  // No cusp, ever: the largest curvature within 1e3 times the data's largest
  // discrete curvature (1e4 with straight runs), the speed above 1e-3 of the
  // chord's, or no worse than the fixed parameters' curve. Never more
  // violations than the fixed parameters'; the generalized cubic and the
  // variable degree spline remove them all (on more random polylines, see
  // RefiningMendsWhatTheSearchesLeaveOnRandomPolylines, a few are left).
  for (const Family& family : families())
  {
    int fixedTotal = 0, automaticTotal = 0;
    for (const UsersData& line : usersData())
    {
      const BothModes fit = fitBoth(family, line.Points);
      const BoundFigures& bounds = fit.AutomaticBounds;
      const BoundFigures& start = fit.FixedBounds;
      const int fixed = fit.Fixed.Audit.violations(), automatic = fit.Automatic.Audit.violations();
      fixedTotal += fixed;
      automaticTotal += automatic;
      std::printf("%s, %s: violations %d -> %d, curvature / data's %.3g (fixed %.3g), lowest speed %.3g\n",
        family.Name, line.Name.c_str(), fixed, automatic, bounds.Curvature, start.Curvature,
        bounds.Speed);
      EXPECT_TRUE(withinBoundsOrNoWorse(bounds, start))
        << family.Name << ", " << line.Name;
      EXPECT_LE(automatic, fixed) << family.Name << ", " << line.Name;
      if (family.AlwaysPreserves)
      {
        EXPECT_EQ(automatic, 0) << family.Name << ", " << line.Name;
      }
    }
    std::printf("%s: %d violations fixed, %d automatic\n", family.Name, fixedTotal, automaticTotal);
    EXPECT_LT(automaticTotal, fixedTotal) << family.Name;
    // qqr, by flattening and straightening spans, most (measured 8 of 457
    // left, 18 before the searches' curves were refined; its exponents alone
    // left 262 of 511).
    if (std::string(family.Name) == "qqr")
    {
      EXPECT_LE(automaticTotal, 0.03 * fixedTotal);
    }
  }
}

TEST(AutomaticShape, RefiningMendsWhatTheSearchesLeaveOnRandomPolylines)
{
  // Random 3D polylines of 60 points (turns of any angle, steps 0.5-1.5):
  // the searches raise a neighbourhood together, overshoot, and freeze a
  // span whose raise stalls. Refining their curves (each span near one left
  // failing tried alone at other levels) leaves, of the 100 lines below,
  // 7 violations for the generalized cubic, 9 for the variable degree
  // spline, 56 for the quintic and 34 for qqr; the searches alone left 17,
  // 7, 84 and 94. Within the bounds, never more than the fixed parameters'.
  // Before the audit found the curvature peaks next to knots (boundary
  // layers, near-cusps between a knot's sample and its neighbour) it left
  // 5, 0, 42 and 32, with 15, 46, 40 and 3 of these curves beyond the
  // curvature bound at 2000 samples a span (up to 1.8e5 times the data's).
  const std::vector<Family> all = families();
  const std::map<std::string, int> most = { { "generalized cubic", 10 },
    { "variable degree", 12 }, { "tension quintic", 70 }, { "qqr", 45 } };
  for (const Family& family : all)
  {
    int fixedTotal = 0, automaticTotal = 0;
    for (unsigned seed = 0; seed < 100; ++seed)
    {
      const BothModes fit = fitBoth(family, randomWalk(60, seed));
      fixedTotal += fit.Fixed.Audit.violations();
      automaticTotal += fit.Automatic.Audit.violations();
      EXPECT_LE(fit.Automatic.Audit.violations(), fit.Fixed.Audit.violations())
        << family.Name << " " << seed;
      EXPECT_TRUE(withinBoundsOrNoWorse(fit.AutomaticBounds, fit.FixedBounds))
        << family.Name << " " << seed;
    }
    std::printf("%s on 100 random polylines: %d violations fixed, %d automatic\n", family.Name,
      fixedTotal, automaticTotal);
    EXPECT_LE(automaticTotal, most.at(family.Name)) << family.Name;
  }
}

TEST(AutomaticShape, QQRsDefaultModeKeepsTheTorsionSignsOfNoisyHelices)
{
  // Helices with 0.1% noise (two turns of 50 points): the fixed curve's
  // violations are torsion signs where the data barely twist. Moving those
  // spans towards their chords mends most (measured: 83 of 879 left on 40
  // helices before the audit let the torsion waver where it touches zero);
  // flattening the curve at their knots mends the others, within the
  // bounds. Straightening runs first and flattening only where it leaves
  // violations, since a flattened knot has curvature 0: on helices of the
  // benchmark's kind (16 points a turn) the curvature's median error over
  // the middle half stays within four times the fixed curve's (measured
  // 4.8% against 1.4%; flattening first, 40% on 19 lines of 20 flattened).
  for (const double perTurn : { 25.0, 16.0 })
  {
    int fixedTotal = 0, automaticTotal = 0, flattenedLines = 0;
    std::vector<double> fixedErrors, automaticErrors;
    QQROptions fixedOptions;
    fixedOptions.Automatic = false;
    for (unsigned seed = 0; seed < 20; ++seed)
    {
      const std::vector<Vec3> points = noisyHelixPoints(50, perTurn, 0.001, seed);
      const FittedPolyline fixed = fitPolyline(points, FitOptions{}, qqrBuilder(fixedOptions));
      const FittedPolyline automatic = fitPolyline(points, FitOptions{}, qqrBuilder(QQROptions{}));
      fixedTotal += fixed.Audit.violations();
      automaticTotal += automatic.Audit.violations();
      EXPECT_TRUE(withinBounds(boundFigures(automatic))) << "seed " << seed;
      flattenedLines += movedSomewhere(*automatic.Spline, "Flattening");
      fixedErrors.push_back(medianCurvatureError(fixed));
      automaticErrors.push_back(medianCurvatureError(automatic));
    }
    const double fixedError = median(fixedErrors), automaticError = median(automaticErrors);
    std::printf("qqr on 20 noisy helices, %g points a turn: %d violations fixed, %d automatic; %d "
                "lines flattened; median curvature error %.4f fixed, %.4f automatic\n",
      perTurn, fixedTotal, automaticTotal, flattenedLines, fixedError, automaticError);
    EXPECT_GT(fixedTotal, 200);
    EXPECT_LE(automaticTotal, 0.02 * fixedTotal);
    if (perTurn == 25.0)
    {
      EXPECT_GT(flattenedLines, 0);
      EXPECT_LT(flattenedLines, 15); // measured 9; 20 when flattening ran first
    }
    else
    {
      EXPECT_LT(automaticError, 4.0 * fixedError);
    }
  }
}

TEST(AutomaticShape, TheQuinticsDefaultModeKeepsTheTorsionSignsOfNoisyHelices)
{
  // Helices with 0.1% noise at 16 points a turn (the benchmark's kind): the
  // quintic's violations left were torsion signs on spans whose four points
  // lie nearly in a plane, where the data's torsion touches zero and the
  // curve's wavers about it (ShapeAudit.TorsionTouchingZeroMayWaverThere).
  // Lowering gamma there bent the curve and never mended them (31 left on
  // 400 such helices); now none is left, within the bounds.
  int fixedTotal = 0, automaticTotal = 0;
  QuinticFitOptions fixedOptions;
  fixedOptions.Automatic = false;
  for (unsigned seed = 0; seed < 60; ++seed)
  {
    const std::vector<Vec3> points = noisyHelixPoints(50, 16.0, 0.001, seed);
    const FittedPolyline fixed =
      fitPolyline(points, FitOptions{}, tensionQuinticBuilder(fixedOptions));
    const FittedPolyline automatic =
      fitPolyline(points, FitOptions{}, tensionQuinticBuilder(QuinticFitOptions{}));
    fixedTotal += fixed.Audit.violations();
    automaticTotal += automatic.Audit.violations();
    EXPECT_TRUE(withinBounds(boundFigures(automatic))) << "seed " << seed;
  }
  std::printf("quintic on 60 noisy helices: %d violations fixed, %d automatic\n", fixedTotal,
    automaticTotal);
  EXPECT_GT(fixedTotal, 100);
  EXPECT_EQ(automaticTotal, 0);
}

TEST(AutomaticShape, QQRsStraighteningStartsFromTheFlattenedCurveToo)
{
  // Trefoils with 1% noise fail convexity and torsion signs together:
  // flattening leaves violations, and straightening from the unflattened
  // curve left 71 on these 20 lines. Straightening also from the flattened
  // curve (its knots kept flat) and keeping the better leaves 50, some lines
  // with knots flattened and spans straightened both.
  int fixedTotal = 0, automaticTotal = 0, bothMoves = 0;
  QQROptions fixedOptions;
  fixedOptions.Automatic = false;
  for (unsigned seed = 0; seed < 20; ++seed)
  {
    const std::vector<Vec3> points = noisyTrefoilPoints(100, 0.01, seed);
    const FittedPolyline fixed = fitPolyline(points, FitOptions{}, qqrBuilder(fixedOptions));
    const FittedPolyline automatic = fitPolyline(points, FitOptions{}, qqrBuilder(QQROptions{}));
    fixedTotal += fixed.Audit.violations();
    automaticTotal += automatic.Audit.violations();
    EXPECT_TRUE(withinBounds(boundFigures(automatic))) << "seed " << seed;
    EXPECT_LE(automatic.Audit.violations(), fixed.Audit.violations()) << "seed " << seed;
    bothMoves += movedSomewhere(*automatic.Spline, "Flattening") &&
      movedSomewhere(*automatic.Spline, "Straightness");
  }
  std::printf("qqr on 20 noisy trefoils: %d violations fixed, %d automatic; %d lines flattened and "
              "straightened\n",
    fixedTotal, automaticTotal, bothMoves);
  EXPECT_LE(automaticTotal, 60);
  EXPECT_GE(bothMoves, 3);
}

/// The largest curvature of a fit's curve at many samples a span, over the
/// reference polygon's largest discrete curvature: what no probe of the audit chooses.
double denselySampledCurvature(const FittedPolyline& fit, int samplesPerSpan)
{
  const Curve& curve = *fit.Spline;
  const auto& knots = curve.knots();
  double largest = 0.0;
  for (int j = 0; j < curve.numberOfSpans(); ++j)
  {
    const double h = knots[j + 1] - knots[j];
    for (int k = 0; k <= samplesPerSpan; ++k)
    {
      const Derivatives d = curve.evaluateOnSpan(j, knots[j] + h * k / samplesPerSpan, 2);
      largest = std::max(largest, curvature(d[1], d[2]));
    }
  }
  return largest / *std::max_element(fit.Shape.Curvature.begin(), fit.Shape.Curvature.end());
}

TEST(AutomaticShape, EveryFamilysDefaultModeKeepsTheCurvatureBoundBetweenItsSamples)
{
  // The bound holds on the curve, not on the audit's 16 samples a span: a
  // tension's boundary layer at a knot (a generalized cubic span at tension
  // 256 peaked at 4.5e4 times the data's within 0.25% of its knot, 12.8 at
  // its samples) or a near-cusp between a knot's sample and its neighbour
  // (a variable degree span at degree 35: 1.7e4, 630 at its samples). Before
  // the audit looked there, 5, 12, 8 and 0 of these random polylines and
  // unevenly spaced noisy helices were beyond the bound at 1024 samples a
  // span (generalized cubic, variable degree, quintic, qqr; up to 1.1e5
  // times the data's). Each is within it, or no worse than its fixed curve there.
  for (const Family& family : families())
  {
    int beyond = 0;
    double largest = 0.0;
    for (unsigned seed = 0; seed < 40; ++seed)
    {
      const std::vector<Vec3> points =
        seed < 20 ? randomWalk(60, seed) : unevenNoisyHelixPoints(50, 0.01, seed + 60);
      const FittedPolyline fixed = fitPolyline(points, FitOptions{}, family.Fixed);
      const FittedPolyline automatic = fitPolyline(points, FitOptions{}, family.Automatic);
      constexpr int SamplesPerSpan = 1024;
      const double curvature = denselySampledCurvature(automatic, SamplesPerSpan);
      const bool within = curvature <= (hasStraightRuns(automatic) ? 1e4 : 1e3) ||
        curvature <= denselySampledCurvature(fixed, SamplesPerSpan);
      beyond += !within;
      largest = std::max(largest, curvature);
      EXPECT_TRUE(within) << family.Name << ", seed " << seed << ": " << curvature;
    }
    std::printf("%s: %d of 40 curves beyond the curvature bound at 1024 samples a span, largest "
                "%.3g times the data's\n",
      family.Name, beyond, largest);
  }
}

TEST(AutomaticShape, EveryFamilysDefaultModeOnDenselySampledNoisyHelices)
{
  // Helices sampled densely for their noise (25 to 64 points a turn, noise
  // 0.5% and 1% of the radius: a step of 10 to 52 times the noise), where
  // the data's discrete torsion is mostly the noise's and a third of the
  // fixed curves' spans fail (usersData() samples 16 a turn). The
  // generalized cubic and the variable degree spline remove every violation
  // (measured: 0 left of 905 to 7408 per family and density on 300 helices
  // each), within the bounds. The quintic and qqr cannot (their spans do
  // not gather the bend at the knots, see the README): never more than
  // their fixed curves', within the bounds, and not much more than measured
  // here: 1.4% (quintic) and 12% (qqr) of the fixed curves' left.
  std::vector<std::vector<Vec3>> lines;
  unsigned seed = 0;
  for (const double perTurn : { 25.0, 40.0, 64.0 })
  {
    for (const double noise : { 0.005, 0.01 })
    {
      for (int k = 0; k < 4; ++k)
      {
        lines.push_back(noisyHelixPoints(50, perTurn, noise, seed++));
      }
    }
  }
  const std::map<std::string, double> leftAtMost{ { "generalized cubic", 0.0 },
    { "variable degree", 0.0 }, { "tension quintic", 0.03 }, { "qqr", 0.2 } };
  for (const Family& family : families())
  {
    int fixedTotal = 0, automaticTotal = 0;
    for (size_t i = 0; i < lines.size(); ++i)
    {
      const BothModes fit = fitBoth(family, lines[i]);
      const int fixed = fit.Fixed.Audit.violations(), automatic = fit.Automatic.Audit.violations();
      fixedTotal += fixed;
      automaticTotal += automatic;
      EXPECT_TRUE(withinBoundsOrNoWorse(fit.AutomaticBounds, fit.FixedBounds))
        << family.Name << ", line " << i;
      EXPECT_LE(automatic, fixed) << family.Name << ", line " << i;
    }
    std::printf("%s, %zu densely sampled noisy helices: %d violations fixed, %d automatic\n",
      family.Name, lines.size(), fixedTotal, automaticTotal);
    EXPECT_GT(fixedTotal, 10 * static_cast<int>(lines.size())) << family.Name; // data that fail
    EXPECT_LE(automaticTotal, leftAtMost.at(family.Name) * fixedTotal) << family.Name;
  }
}

TEST(AutomaticShape, EveryFamilysDefaultModeKeepsTheCurveRegularOnUnevenlySpacedPoints)
{
  // Noisy points at random places along a helix: close pairs next to long
  // gaps, where a raised parameter moves the curve far away (the quintic's
  // abscissae are solved for the whole line). Undoing a raise moves it too:
  // checked again, the bounds hold (checked once, one quintic line of 200
  // points ended at 2.3e3 times the data's curvature, its fixed curve at 2.4).
  for (const Family& family : families())
  {
    int fixedTotal = 0, automaticTotal = 0;
    double largest = 0.0;
    unsigned seed = 1;
    for (const int count : { 25, 50, 100, 200 })
    {
      for (const double noise : { 0.001, 0.005, 0.01 })
      {
        for (int k = 0; k < 15; ++k, ++seed)
        {
          const BothModes fit = fitBoth(family, unevenNoisyHelixPoints(count, noise, seed));
          const BoundFigures& bounds = fit.AutomaticBounds;
          const BoundFigures& start = fit.FixedBounds;
          fixedTotal += fit.Fixed.Audit.violations();
          automaticTotal += fit.Automatic.Audit.violations();
          largest = std::max(largest, bounds.Curvature);
          EXPECT_TRUE(withinBoundsOrNoWorse(bounds, start))
            << family.Name << ", " << count << " points, noise " << noise << ", seed " << seed
            << ": curvature / data's " << bounds.Curvature << " (fixed " << start.Curvature
            << "), lowest speed " << bounds.Speed;
          EXPECT_LE(fit.Automatic.Audit.violations(), fit.Fixed.Audit.violations()) << family.Name;
        }
      }
    }
    std::printf("%s, 180 unevenly spaced noisy helices: %d violations fixed, %d automatic, largest "
                "curvature over the data's %.3g\n",
      family.Name, fixedTotal, automaticTotal, largest);
    // What each family leaves at most (measured 0.20%, 0.16%, 2.1%, 5.3%;
    // 0.20%, 0.62%, 1.9%, 5.3% before settling let a global solve's ripple
    // pass; 0.04%, 0%, 1.6%, 5.3% while the audit missed the curvature peaks next
    // to knots, with 8, 15, 23 and 5 curves beyond the curvature bound at
    // 2000 samples a span, up to 2.6e5 times the data's; 1.9% and 6.0% before
    // settling reached far levels and refining went worst first;
    // before the searches' curves were refined 0.04%, 0.09%, 3.2%, 10.7%, the
    // quintic 18% before its search from a common level, qqr 12.7% before
    // it straightened from the flattened curve too).
    const std::map<std::string, double> leftAtMost{ { "generalized cubic", 0.01 },
      { "variable degree", 0.01 }, { "tension quintic", 0.025 }, { "qqr", 0.08 } };
    EXPECT_LT(automaticTotal, leftAtMost.at(family.Name) * fixedTotal) << family.Name;
  }
}

TEST(AutomaticShape, TorsionZerosOfCleanUnevenlySpacedPointsLeaveTheCurveAlone)
{
  // Exact points of a trefoil, whose torsion changes sign six times, at
  // uneven spacing: near a zero the discrete torsion is off by its own size
  // and a cubic's torsion steps at every knot, so a curve that converges
  // puts its zero up to two knots from the data's. The automatic modes used
  // to move it there by bending the curve: of these 50 lines, 6 with the
  // generalized cubic and 6 with qqr, the curvature up to 37% and 572% of
  // its largest off the fixed curve's (which is within 1.2% of the
  // trefoil's at 200 points). Now the audit lets the torsion waver about
  // its zero by its error, and the fixed curve keeps the shape.
  constexpr double Jitter = 0.95;
  for (const Family& family : families())
  {
    int moved = 0, lines = 0;
    double farthest = 0.0;
    for (const int count : { 200, 400 })
    {
      for (unsigned seed = 1; seed <= 25; ++seed)
      {
        const BothModes fit = fitBoth(family, unevenTrefoilPoints(count, Jitter, seed));
        const std::vector<FrenetFrame> fixed = sampleFit(fit.Fixed).Frames;
        const std::vector<FrenetFrame> automatic = sampleFit(fit.Automatic).Frames;
        ASSERT_EQ(fixed.size(), automatic.size());
        double largest = 0.0, change = 0.0;
        for (size_t k = 0; k < fixed.size(); ++k)
        {
          largest = std::max(largest, fixed[k].Curvature);
          change = std::max(change, std::abs(automatic[k].Curvature - fixed[k].Curvature));
        }
        const double relative = change / largest;
        farthest = std::max(farthest, relative);
        moved += relative > 0.05;
        ++lines;
        EXPECT_LE(fit.Automatic.Audit.violations(), fit.Fixed.Audit.violations())
          << family.Name << ", " << count << " points, seed " << seed;
      }
    }
    std::printf("%s: %d of %d uneven clean trefoils' curvature moved by more than 5%% of its "
                "largest, at most %.3g\n",
      family.Name, moved, lines, farthest);
    EXPECT_EQ(moved, 0) << family.Name;
  }
}

TEST(AutomaticShape, EveryFamilysDefaultModeKeepsTheBoundsOnNearlyStraightNoisyLines)
{
  // A straight line of length 10 through 100 points that stray 1e-6 from it
  // (a measured straight edge): its turns of about 1e-5 are above epsilon_1,
  // so the audit keeps them. The curvature bound is the data's own; with a
  // floor of one over the diagonal, the quintic's default bent these lines
  // to 1.35e4 times the data's curvature (through the filter, another such
  // line to 1.4e5: a radius of a hundredth of the line).
  for (const Family& family : families())
  {
    double largest = 0.0;
    for (unsigned seed = 1; seed <= 10; ++seed)
    {
      std::mt19937 random(seed);
      std::normal_distribution<double> noise(0.0, 1e-6);
      std::vector<Vec3> points;
      for (int i = 0; i < 100; ++i)
      {
        points.push_back(10.0 * i / 99.0 * Vec3(0.48, -0.6, 0.64) +
          Vec3(noise(random), noise(random), noise(random)));
      }
      const BothModes fit = fitBoth(family, points);
      largest = std::max(largest, fit.AutomaticBounds.Curvature);
      EXPECT_TRUE(withinBoundsOrNoWorse(fit.AutomaticBounds, fit.FixedBounds))
        << family.Name << ", seed " << seed << ": curvature / data's "
        << fit.AutomaticBounds.Curvature << " (fixed " << fit.FixedBounds.Curvature << ")";
      EXPECT_LE(fit.Automatic.Audit.violations(), fit.Fixed.Audit.violations())
        << family.Name << ", seed " << seed;
    }
    std::printf("%s, nearly straight lines: largest curvature %.3g times the data's\n", family.Name,
      largest);
  }
}

TEST(AutomaticShape, ANearRepeatedPointMakesNoSpike)
{
  // A helix with one point repeated 1e-10 of a segment away in a random
  // direction (a streamline stalling): merged as a repeat, so no family
  // turns within it (before: the quintic's, qqr's and the variable degree
  // spline's curvature 1e5 times the helix's, fixed and automatic alike).
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  for (const Family& family : families())
  {
    for (int trial = 0; trial < 3; ++trial)
    {
      std::vector<Vec3> points = helix(8, 3);
      const Vec3 direction = Vec3(normal(random), normal(random), normal(random)).normalized();
      const double segment = (points[11] - points[10]).norm();
      points.insert(points.begin() + 11, points[10] + 1e-10 * segment * direction);
      for (const CurveBuilder* builder : { &family.Fixed, &family.Automatic })
      {
        const FittedPolyline fit = fitPolyline(points, FitOptions{}, *builder);
        EXPECT_EQ(fit.Data.MergedPoints, 1) << family.Name;
        EXPECT_LT(denselySampledCurvature(fit, 64), 10.0) << family.Name << ", trial " << trial;
      }
    }
  }
}

TEST(AutomaticShape, EveryFamilysDefaultModeKeepsItsBoundsOnHeavyTailedSpacing)
{
  // Exact points with gaps from 1e-11 of a turn to two turns: a level
  // raised far away moves a span next to a close pair, and where every span
  // near it already was at level 0 the bounds were not restored (before: 4
  // of these 60 lines beyond them with the variable degree spline, one
  // 2.9 of its segments away from its data where its fixed curve is 0.38
  // away; 1 with the quintic, at 3.9e4 times the data's curvature, 3.4e4
  // fixed). And the quintic's lowered gamma can leave its abscissae not
  // increasing: no curve at those levels, not a failure of the line (before:
  // the automatic mode threw where the fixed one fits).
  for (const Family& family : families())
  {
    int fixedTotal = 0, automaticTotal = 0;
    double farthest = 0.0;
    for (const int count : { 20, 40, 80 })
    {
      for (unsigned seed = 1; seed <= 20; ++seed)
      {
        const BothModes fit = fitBoth(family, heavyTailedHelixPoints(count, seed));
        const BoundFigures& bounds = fit.AutomaticBounds;
        const BoundFigures& start = fit.FixedBounds;
        fixedTotal += fit.Fixed.Audit.violations();
        automaticTotal += fit.Automatic.Audit.violations();
        farthest = std::max(farthest, bounds.Deviation);
        // The deviation and the speed: the curvature's peaks on these knots
        // are narrower than the samples (see the note on spikes in design.md).
        EXPECT_TRUE(bounds.Deviation <= std::max(MaximumPolygonDeviation, start.Deviation))
          << family.Name << ", " << count << " points, seed " << seed << ": deviation "
          << bounds.Deviation << " (fixed " << start.Deviation << ")";
        EXPECT_TRUE(bounds.Speed >= std::min(1e-3, start.Speed))
          << family.Name << ", " << count << " points, seed " << seed << ": lowest speed "
          << bounds.Speed << " (fixed " << start.Speed << ")";
        EXPECT_LE(fit.Automatic.Audit.violations(), fit.Fixed.Audit.violations())
          << family.Name << ", " << count << " points, seed " << seed;
      }
    }
    std::printf("%s, 60 heavy-tailed helices: %d violations fixed, %d automatic, farthest span "
                "%.3g of its segments\n",
      family.Name, fixedTotal, automaticTotal, farthest);
  }
}

namespace
{
/// The points moved into the plane z = 0.
std::vector<Vec3> flattened(std::vector<Vec3> points)
{
  for (Vec3& p : points)
  {
    p.z() = 0.0;
  }
  return points;
}

/// count points at random places along two turns of a planar spiral whose
/// radius grows from 1 to 3.4, in the plane z = 0, with in-plane noise of a
/// fraction `noise` of the outer radius.
std::vector<Vec3> noisyPlanarSpiral(int count, double noise, unsigned seed)
{
  std::vector<Vec3> points;
  for (const double t : randomParameters(count, 0.0, 4.0 * Pi, seed))
  {
    points.emplace_back((1.0 + 0.19 * t) * std::cos(t), (1.0 + 0.19 * t) * std::sin(t), 0.0);
  }
  return flattened(withNoise(points, noise * 3.4, seed + 1000));
}

/// count points at random places around the ellipse 2 cos t, sin t (a closed
/// line), with noise of a fraction `noise` of its diagonal in the plane z = 0
/// or, `lifted`, out of it too.
std::vector<Vec3> noisyEllipse(int count, double noise, bool lifted, unsigned seed)
{
  std::vector<Vec3> points;
  for (const double t : randomParameters(count, 0.0, 2.0 * Pi * (count - 1.0) / count, seed))
  {
    points.emplace_back(2.0 * std::cos(t), std::sin(t), 0.0);
  }
  points = withNoise(points, noise * 4.5, seed + 1000);
  return lifted ? points : flattened(points);
}
} // namespace

TEST(AutomaticShape, EveryFamilysDefaultModeOnPlanarAndClosedLines)
{
  // Users' data in a plane (2D tracks, digitised outlines, tool paths) and
  // closed outlines: no torsion at all in the plane, the bounds hold between
  // samples too (a quintic kept 1.25e3 times the data's curvature between the
  // audit's samples before the audit looked between samples that turn more
  // than their curvatures explain), never more violations than the fixed
  // parameters'. The generalized cubic and the variable degree spline remove
  // nearly all; the quintic most; qqr most (its exponents alone, before it
  // straightened spans, removed next to none in a plane: at a knot an
  // exponent only scales the curvature vector,
  // QQRSpline.AnExponentScalesTheCurvatureAtItsKnotWithoutTurningIt).
  struct Line
  {
    std::vector<Vec3> Points;
    bool Closed, Planar;
  };
  std::vector<Line> lines;
  unsigned seed = 1;
  for (const int count : { 40, 80, 160 })
  {
    for (const double noise : { 0.001, 0.005 })
    {
      for (int k = 0; k < 4; ++k, ++seed)
      {
        lines.push_back({ noisyPlanarSpiral(count, noise, seed), false, true });
        lines.push_back({ noisyEllipse(count / 2, noise, k % 2 == 1, seed), true, k % 2 == 0 });
      }
    }
  }
  // What each family leaves at most (measured 1.1%, 0.76%, 2.1%, 5.4%; 2.0%,
  // 3.8%, 4.2%, 5.4% before settling let a global solve's ripple pass; 0.19%,
  // 0.87%, 2.4%, 13% while the audit missed the curvature peaks next to knots).
  const std::map<std::string, double> leftAtMost{ { "generalized cubic", 0.03 },
    { "variable degree", 0.03 }, { "tension quintic", 0.15 }, { "qqr", 0.2 } };
  for (const Family& family : families())
  {
    int fixedTotal = 0, automaticTotal = 0;
    double largest = 0.0, planarTorsion = 0.0;
    for (const Line& line : lines)
    {
      FitOptions options;
      options.Closed = line.Closed;
      const FittedPolyline fixed = fitPolyline(line.Points, options, family.Fixed);
      const FittedPolyline automatic = fitPolyline(line.Points, options, family.Automatic);
      const BoundFigures bounds = boundFigures(automatic);
      const BoundFigures start = boundFigures(fixed);
      fixedTotal += fixed.Audit.violations();
      automaticTotal += automatic.Audit.violations();
      largest = std::max(largest, bounds.Curvature);
      EXPECT_TRUE(withinBoundsOrNoWorse(bounds, start))
        << family.Name << ", " << line.Points.size() << " points, closed " << line.Closed
        << ": curvature / data's " << bounds.Curvature << " (fixed " << start.Curvature << ")";
      EXPECT_LE(automatic.Audit.violations(), fixed.Audit.violations()) << family.Name;
      for (const FrenetFrame& frame : sampleFit(automatic).Frames)
      {
        planarTorsion = line.Planar ? std::max(planarTorsion, std::abs(frame.Torsion)) : planarTorsion;
      }
    }
    std::printf("%s, %zu planar spirals and closed ellipses: %d violations fixed, %d automatic, "
                "largest curvature over the data's %.3g, largest torsion in the plane %g\n",
      family.Name, lines.size(), fixedTotal, automaticTotal, largest, planarTorsion);
    EXPECT_EQ(planarTorsion, 0.0) << family.Name;
    EXPECT_LE(automaticTotal, leftAtMost.at(family.Name) * fixedTotal) << family.Name;
  }
}

TEST(AutomaticShape, EveryFamilysDefaultModeKeepsTheAccuracyOfDenseExactPoints)
{
  // 400 exact points at random places along two turns of a helix: close
  // points among them whose end planes turn by a little less than epsilon_2
  // were called coplanar, and the curve's binormal, which turns by as much
  // along the span, failed the audit. Raising the parameter there cost the
  // curvature (largest error over the middle half, seed 1: generalized cubic
  // 0.5% -> 1400%, variable degree 0.25% -> 9e4%).
  const double curvature = 1.0 / 1.0625, torsion = 0.25 / 1.0625;
  for (const Family& family : families())
  {
    for (unsigned seed = 1; seed <= 4; ++seed)
    {
      const std::vector<Vec3> points = randomlySpacedHelix(400, 0.25, seed);
      const FittedPolyline fixed = fitPolyline(points, FitOptions{}, family.Fixed);
      const FittedPolyline automatic = fitPolyline(points, FitOptions{}, family.Automatic);
      const RelativeErrors before = interiorErrors(fixed, curvature, torsion, 100);
      const RelativeErrors after = interiorErrors(automatic, curvature, torsion, 100);
      std::printf("%s, seed %u: curvature error %.3g -> %.3g, torsion %.3g -> %.3g, violations %d -> %d\n",
        family.Name, seed, before.Curvature, after.Curvature, before.Torsion, after.Torsion,
        fixed.Audit.violations(), automatic.Audit.violations());
      EXPECT_LE(after.Curvature, 2.0 * before.Curvature + 0.005) << family.Name << ", seed " << seed;
      EXPECT_LE(after.Torsion, 2.0 * before.Torsion + 0.01) << family.Name << ", seed " << seed;
    }
  }
}

TEST(AutomaticShape, StepsStopNearWhatASpanNeeds)
{
  // On smooth noisy data (helices and trefoils: no straight runs, no sharp
  // turns) the families that keep the shape take no more tension or degree
  // than the violations need: the largest curvature stays within 250 times
  // the data's largest discrete curvature, far inside the cusp bound of
  // 1e3. Steps of x4 in tension or x2 in degree overshot it (455 and 486
  // times here; now 68 and 198: the variable degree spline's search, a
  // chaotic path on noisy points, took 118 before the audit let torsion
  // change sign within a span of where the data put it, and 196 on the
  // benchmark's users' data of other seeds).
  for (const Family& family : families())
  {
    const std::string name = family.Name;
    if (name != "generalized cubic" && name != "variable degree")
    {
      continue;
    }
    double largest = 0.0;
    for (const UsersData& line : usersData())
    {
      if (line.Name.rfind("helix", 0) != 0 && line.Name.rfind("trefoil", 0) != 0)
      {
        continue;
      }
      const FittedPolyline automatic = fitPolyline(line.Points, FitOptions{}, family.Automatic);
      const double curvature = boundFigures(automatic).Curvature;
      largest = std::max(largest, curvature);
      EXPECT_LE(curvature, 250.0) << name << ", " << line.Name;
    }
    std::printf("%s: largest curvature over the data's %.3g\n", name.c_str(), largest);
  }
}

TEST(AutomaticShape, StraightRunsBecomeStraightSpans)
{
  // Where Definition 1 calls the data collinear, the spans on both sides of a
  // collinear point are straight (the tangent within 1e-3 of the segment,
  // criterion (i)) in the families whose tension limit is the data polygon,
  // and in qqr, whose spans straighten (QQRKnotShape::Straightness).
  for (const Family& family : families())
  {
    const std::string name = family.Name;
    if (name == "tension quintic")
    {
      continue;
    }
    for (unsigned seed = 1; seed <= 4; ++seed)
    {
      const FittedPolyline fit = fitPolyline(staircase(5, 5, seed), FitOptions{}, family.Automatic);
      EXPECT_EQ(fit.Audit.Failures[int(ShapeCriterion::Collinearity)], 0) << name << " " << seed;
      const BoundFigures bounds = boundFigures(fit);
      EXPECT_LE(bounds.Curvature, 1e4) << name;
      EXPECT_GE(bounds.Speed, 1e-3) << name;
    }
  }
}

namespace
{
/// Two turns of the helix (cos t, sin t, t / 4) sampled at perTurn points a
/// turn, entered and left along its tangent by straight runs of one turn's
/// length at the same spacing: a tool path's line into an arc, a vessel's
/// straight stretch into a bend (tangent continuous, the curvature jumps).
/// The helix's spans are perTurn .. 3 perTurn - 1.
std::vector<Vec3> helixBetweenStraightRuns(int perTurn)
{
  const double a = 1.0, b = 0.25, c = std::hypot(a, b);
  const double step = 2.0 * Pi * c / perTurn;
  auto onHelix = [&](double t) -> Vec3 { return Vec3(a * std::cos(t), a * std::sin(t), b * t); };
  auto tangent = [&](double t) -> Vec3 { return Vec3(-a * std::sin(t), a * std::cos(t), b) / c; };
  const double end = 4.0 * Pi;
  std::vector<Vec3> points;
  for (int i = perTurn; i > 0; --i)
  {
    points.push_back(onHelix(0.0) - tangent(0.0) * (i * step));
  }
  for (int i = 0; i <= 2 * perTurn; ++i)
  {
    points.push_back(onHelix(2.0 * Pi * i / perTurn));
  }
  for (int i = 1; i <= perTurn; ++i)
  {
    points.push_back(onHelix(end) + tangent(end) * (i * step));
  }
  return points;
}

/// The curvature and torsion of the helix of helixBetweenStraightRuns.
constexpr double JoinedHelixCurvature = 1.0 / 1.0625, JoinedHelixTorsion = 0.25 / 1.0625;

/// Per span, the largest relative curvature error against that helix
/// (spans off the helix: 0).
std::vector<double> helixSpanCurvatureErrors(const FittedPolyline& fit, int perTurn)
{
  std::vector<double> errors(fit.Data.numberOfSpans(), 0.0);
  const SampledCurve sampled = sampleFit(fit);
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    const int span = sampled.Samples.Span[k];
    if (span >= perTurn && span < 3 * perTurn)
    {
      const double error =
        std::abs(sampled.Frames[k].Curvature - JoinedHelixCurvature) / JoinedHelixCurvature;
      errors[span] = std::max(errors[span], error);
    }
  }
  return errors;
}
} // namespace

TEST(AutomaticShape, TheTensionFamiliesKeepStaircasesTurningAnyWayIn3D)
{
  // Straight runs of 2-5 points (each run its own spacing) joined by turns
  // of 20 to 160 degrees in random 3D directions, not only the axes' 90:
  // the generalized cubic and the variable degree spline keep every
  // criterion, within the bounds for straight runs. (qqr keeps most of the
  // 90-degree ones only: a straightened qqr span keeps a little curvature
  // along its length, and sharper turns take more; see design.md.)
  std::mt19937 random(17);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss;
  auto randomUnit = [&] {
    const Vec3 v(gauss(random), gauss(random), gauss(random));
    return Vec3(v.normalized());
  };
  std::vector<std::vector<Vec3>> lines;
  for (int line = 0; line < 30; ++line)
  {
    std::vector<Vec3> points = { Vec3::Zero() };
    Vec3 direction = randomUnit();
    const int runs = 3 + static_cast<int>(random() % 4);
    for (int run = 0; run < runs; ++run)
    {
      if (run > 0)
      {
        const double turn = (20.0 + 140.0 * uniform(random)) * Pi / 180.0;
        const Vec3 side = direction.cross(randomUnit()).normalized();
        direction = std::cos(turn) * direction + std::sin(turn) * side;
      }
      const int steps = 2 + static_cast<int>(random() % 4);
      const double step = (0.5 + 1.5 * uniform(random)) / steps;
      for (int k = 0; k < steps; ++k)
      {
        points.push_back(points.back() + step * direction);
      }
    }
    lines.push_back(points);
  }
  for (const Family& family : families())
  {
    const std::string name = family.Name;
    if (!family.AlwaysPreserves)
    {
      continue;
    }
    int fixedViolations = 0;
    for (size_t k = 0; k < lines.size(); ++k)
    {
      fixedViolations += fitPolyline(lines[k], FitOptions{}, family.Fixed).Audit.violations();
      const FittedPolyline fit = fitPolyline(lines[k], FitOptions{}, family.Automatic);
      EXPECT_EQ(fit.Audit.violations(), 0) << name << ", line " << k;
      const BoundFigures bounds = boundFigures(fit);
      EXPECT_LE(bounds.Curvature, 1e4) << name << ", line " << k;
      EXPECT_GE(bounds.Speed, 1e-3) << name << ", line " << k;
    }
    EXPECT_GT(fixedViolations, 100) << name; // the fixed curves do break the shape
  }
}

TEST(AutomaticShape, EveryFamilysDefaultModeConvergesNextToStraightRuns)
{
  // Straight runs into a helix: the fixed curves bend the runs (collinearity
  // fails), so every automatic mode acts. Its curvature and torsion must
  // still converge to the helix's: measured a quarter turn or more from the
  // joins, below 1e-3 at 128 points a turn and falling at least 3x from 64
  // (the disturbance of a join spans a fixed number of spans, a shrinking
  // part of the turn). The variable degree spline's and the quintic's
  // parameters sit at the knots, so straightening the run's last span also
  // tightens the helix's first: their joins spread over more spans (README).
  for (const Family& family : families())
  {
    RelativeErrors previous{ 1.0, 1.0 };
    for (const int perTurn : { 32, 64, 128 })
    {
      const std::vector<Vec3> points = helixBetweenStraightRuns(perTurn);
      const FittedPolyline fixed = fitPolyline(points, FitOptions{}, family.Fixed);
      const FittedPolyline automatic = fitPolyline(points, FitOptions{}, family.Automatic);
      // The helix's spans a quarter turn or more from both joins (4 turns' spans in all).
      const RelativeErrors away = interiorErrors(
        automatic, JoinedHelixCurvature, JoinedHelixTorsion, perTurn + perTurn / 4);
      std::printf("%s, %d points a turn: violations %d -> %d, a quarter turn from the joins "
                  "curvature %.3g, torsion %.3g\n",
        family.Name, perTurn, fixed.Audit.violations(), automatic.Audit.violations(),
        away.Curvature, away.Torsion);
      EXPECT_GT(fixed.Audit.Failures[int(ShapeCriterion::Collinearity)], 0) << family.Name;
      EXPECT_LE(automatic.Audit.violations(), fixed.Audit.violations()) << family.Name;
      if (std::string(family.Name) != "tension quintic")
      {
        EXPECT_TRUE(automatic.Audit.preserving()) << family.Name << ", " << perTurn;
      }
      EXPECT_LT(away.Curvature, previous.Curvature) << family.Name << ", " << perTurn;
      EXPECT_LT(away.Torsion, previous.Torsion) << family.Name << ", " << perTurn;
      if (perTurn == 128)
      {
        EXPECT_LT(away.Curvature, 1e-3) << family.Name;
        EXPECT_LT(away.Torsion, 1e-3) << family.Name;
        EXPECT_LE(away.Curvature, previous.Curvature / 3.0) << family.Name;
        EXPECT_LE(away.Torsion, previous.Torsion / 3.0) << family.Name;
      }
      previous = away;
    }
  }
}

namespace
{
/// Curvature and torsion of a curve from its first three derivatives (the
/// closed forms the tests compare with).
std::array<double, 2> exactCurvatureTorsion(
  const Vec3& first, const Vec3& second, const Vec3& third)
{
  const Vec3 normal = first.cross(second);
  return { normal.norm() / std::pow(first.norm(), 3), normal.dot(third) / normal.squaredNorm() };
}

/// The largest curvature error of a fit to y = sin x for x in [pi/2, 7 pi/2].
double sineCurvatureError(const FittedPolyline& fit)
{
  const SampledCurve sampled = sampleFit(fit);
  double error = 0.0;
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    const double x = sampled.Samples.Values[k][0].x();
    if (x >= Pi / 2.0 && x <= 3.5 * Pi)
    {
      const double slope = std::cos(x);
      const double curvature = std::abs(std::sin(x)) / std::pow(1.0 + slope * slope, 1.5);
      error = std::max(error, std::abs(sampled.Frames[k].Curvature - curvature));
    }
  }
  return error;
}

/// Evenly spaced points of r(t) = (t, t^2 / 2, t^4 / 4), t in [-3/2, 3/2],
/// whose torsion 6 t / |r' x r''|^2 changes sign at t = 0; an even count puts
/// t = 0 in the middle of a span, whose four points are coplanar.
std::vector<Vec3> twistReversingPoints(int count)
{
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i)
  {
    const double t = -1.5 + 3.0 * i / (count - 1);
    points.emplace_back(t, t * t / 2.0, t * t * t * t / 4.0);
  }
  return points;
}

/// The largest curvature and torsion errors for |t| <= 1 over the largest
/// curvature and |torsion| there (t = x on this curve).
RelativeErrors twistReversingErrors(const FittedPolyline& fit)
{
  const SampledCurve sampled = sampleFit(fit);
  double largestCurvature = 0.0, largestTorsion = 0.0;
  RelativeErrors errors;
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    const double t = sampled.Samples.Values[k][0].x();
    if (std::abs(t) > 1.0)
    {
      continue;
    }
    const auto [curvature, torsion] = exactCurvatureTorsion(
      Vec3(1.0, t, t * t * t), Vec3(0.0, 1.0, 3.0 * t * t), Vec3(0.0, 0.0, 6.0 * t));
    largestCurvature = std::max(largestCurvature, curvature);
    largestTorsion = std::max(largestTorsion, std::abs(torsion));
    errors.Curvature =
      std::max(errors.Curvature, std::abs(sampled.Frames[k].Curvature - curvature));
    errors.Torsion = std::max(errors.Torsion, std::abs(sampled.Frames[k].Torsion - torsion));
  }
  errors.Curvature /= largestCurvature;
  errors.Torsion /= largestTorsion;
  return errors;
}
} // namespace

TEST(AutomaticShape, EveryFamilysDefaultModeConvergesWhereTheTorsionChangesSign)
{
  // Evenly spaced exact points around a zero of the torsion: the four points
  // around it are coplanar, and (iii) asked the curve to be planar along
  // that span, which no curve twisting on both sides is; every fixed curve
  // failed it at 16-64 points and every automatic mode flattened the curve
  // there (curvature errors 3.7-970 times the curve's largest). The audit
  // now reads such a span as where the torsion changes sign: no violation,
  // nothing raised, and the default modes converge like the fixed ones.
  for (const Family& family : families())
  {
    RelativeErrors previous{ 1.0, 1.0 };
    for (const int count : { 16, 32, 64, 128 })
    {
      const std::vector<Vec3> points = twistReversingPoints(count);
      const FittedPolyline automatic = fitPolyline(points, FitOptions{}, family.Automatic);
      const RelativeErrors errors = twistReversingErrors(automatic);
      std::printf("%s, %d points: violations %d, curvature %.3g, torsion %.3g\n", family.Name,
        count, automatic.Audit.violations(), errors.Curvature, errors.Torsion);
      EXPECT_TRUE(automatic.Audit.preserving()) << family.Name << ", " << count;
      EXPECT_LT(errors.Curvature, previous.Curvature) << family.Name << ", " << count;
      EXPECT_LT(errors.Torsion, previous.Torsion) << family.Name << ", " << count;
      if (count >= 32)
      {
        // At least second order in curvature, first in torsion (the cubics).
        EXPECT_LE(errors.Curvature, previous.Curvature / 3.0) << family.Name << ", " << count;
        EXPECT_LE(errors.Torsion, previous.Torsion / 1.8) << family.Name << ", " << count;
      }
      previous = errors;
    }
    EXPECT_LT(previous.Curvature, 1e-3) << family.Name;
    EXPECT_LT(previous.Torsion, 0.05) << family.Name;
  }
}

TEST(AutomaticShape, EveryFamilysDefaultModeConvergesUpToTheEndsOfAnOpenLine)
{
  // Natural ends (s'' = 0; s''' = 0 too for the variable degree spline) put
  // an error of the size of the curvature at both ends of every open line,
  // at any density: the generalized cubic's and the variable degree spline's
  // defaults were off by 100% of the curvature on an open helix at 8 to 64
  // points per turn, and the variable degree spline by 100% of the torsion.
  // Their polynomial ends (the end polynomial's derivatives) converge like
  // the inside, and the shape needs nothing raised.
  const double a = 1.0, b = 0.25;
  const double curvature = a / (a * a + b * b), torsion = b / (a * a + b * b);
  for (const Family& family : families())
  {
    RelativeErrors previous{ 1.0, 1.0 };
    for (const int perTurn : { 8, 16, 32, 64 })
    {
      const FittedPolyline automatic =
        fitPolyline(helix(perTurn, 2, a, b), FitOptions{}, family.Automatic);
      const RelativeErrors errors = interiorErrors(automatic, curvature, torsion, 0);
      std::printf("%s, %d points per turn: violations %d, whole-line curvature error %.3g, "
                  "torsion %.3g\n",
        family.Name, perTurn, automatic.Audit.violations(), errors.Curvature, errors.Torsion);
      EXPECT_TRUE(automatic.Audit.preserving()) << family.Name << ", " << perTurn;
      if (perTurn >= 32)
      {
        // At least second order in curvature, first in torsion (the cubics).
        EXPECT_LE(errors.Curvature, previous.Curvature / 3.0) << family.Name << ", " << perTurn;
        EXPECT_LE(errors.Torsion, previous.Torsion / 1.8) << family.Name << ", " << perTurn;
      }
      previous = errors;
    }
    EXPECT_LT(previous.Curvature, 0.02) << family.Name;
    EXPECT_LT(previous.Torsion, 0.05) << family.Name;
  }
}

TEST(AutomaticShape, EveryFamilysDefaultModeConvergesThroughAnInflection)
{
  // y = sin x, x in [0, 4 pi], evenly spaced with points on its inflections
  // (17 to 129 points): each inflection's point and its neighbours are
  // collinear, and (i) asked the curve to be straight on the two spans
  // around it. Every fixed curve failed (3 violations at every count) and
  // every automatic mode flattened the curve there (curvature errors up to
  // 243 times the curve's largest; at 129 points 0.02-0.13, 5-6600 times
  // the fixed curves'). Read as an inflection: no violation, and the
  // default modes converge like the fixed ones, away from the ends.
  for (const Family& family : families())
  {
    double previous = 1.0;
    for (const int count : { 17, 33, 65, 129 })
    {
      std::vector<Vec3> points;
      for (int i = 0; i < count; ++i)
      {
        const double x = 4.0 * Pi * i / (count - 1);
        points.emplace_back(x, std::sin(x), 0.0);
      }
      const FittedPolyline automatic = fitPolyline(points, FitOptions{}, family.Automatic);
      const double error = sineCurvatureError(automatic);
      std::printf("%s, %d points: violations %d, curvature %.3g\n", family.Name, count,
        automatic.Audit.violations(), error);
      EXPECT_TRUE(automatic.Audit.preserving()) << family.Name << ", " << count;
      EXPECT_LT(error, previous) << family.Name << ", " << count;
      if (count >= 65)
      {
        EXPECT_LE(error, previous / 3.0) << family.Name << ", " << count;
      }
      previous = error;
    }
    EXPECT_LT(previous, 5e-3) << family.Name;
  }
}

TEST(AutomaticShape, EveryFamilysDefaultModeKeepsTheFixedCurvesAccuracyNearInflections)
{
  // y = sin x over two periods at 33-129 exact points, each a random
  // fraction (up to 0.35) of the spacing off the even grid: a point next to
  // an inflection has a small curvature, and the spline's inflection (and
  // the Menger curvature of uneven points) may sit on either side of it.
  // The audit asked the curvature's sign of the nearer point there; every
  // fixed curve failed 2-4 times and the automatic modes bent the curve
  // (on y = x^3 at 65 points: curvature errors 0.1-0.74 of the largest,
  // against 0.0011-0.0081). The curvature may now change sign anywhere on
  // the two spans around a point whose curvature is under half its
  // neighbour's that turns the other way.
  for (const Family& family : families())
  {
    for (const int count : { 33, 65, 129 })
    {
      for (const unsigned seed : { 1u, 2u, 3u })
      {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> jitter(-0.35, 0.35);
        std::vector<Vec3> points;
        for (int i = 0; i < count; ++i)
        {
          const double step = 4.0 * Pi / (count - 1);
          const double x = std::clamp((i + jitter(random)) * step, 0.0, 4.0 * Pi);
          points.emplace_back(x, std::sin(x), 0.0);
        }
        std::sort(points.begin(), points.end(),
          [](const Vec3& a, const Vec3& b) { return a.x() < b.x(); });
        const FittedPolyline fixed = fitPolyline(points, FitOptions{}, family.Fixed);
        const FittedPolyline automatic = fitPolyline(points, FitOptions{}, family.Automatic);
        const double fixedError = sineCurvatureError(fixed);
        const double error = sineCurvatureError(automatic);
        const std::string where = std::string(family.Name) + ", " + std::to_string(count) +
          ", seed " + std::to_string(seed);
        std::printf("%s: violations %d -> %d, curvature %.3g -> %.3g\n", where.c_str(),
          fixed.Audit.violations(), automatic.Audit.violations(), fixedError, error);
        EXPECT_EQ(automatic.Audit.violations(), 0) << where;
        EXPECT_LE(error, 1.5 * fixedError + 1e-6) << where;
      }
    }
  }
}

namespace
{
/// The (2, 3) torus knot and its derivatives in t.
std::array<Vec3, 4> torusKnot(double t)
{
  const double c2 = std::cos(2 * t), s2 = std::sin(2 * t);
  const double c3 = std::cos(3 * t), s3 = std::sin(3 * t);
  const double r = 2 + c3, r1 = -3 * s3, r2 = -9 * c3, r3 = 27 * s3;
  return { Vec3(r * c2, r * s2, s3), Vec3(r1 * c2 - 2 * r * s2, r1 * s2 + 2 * r * c2, 3 * c3),
    Vec3(r2 * c2 - 4 * r1 * s2 - 4 * r * c2, r2 * s2 + 4 * r1 * c2 - 4 * r * s2, -9 * s3),
    Vec3(r3 * c2 - 6 * r2 * s2 - 12 * r1 * c2 + 8 * r * s2,
      r3 * s2 + 6 * r2 * c2 - 12 * r1 * s2 - 8 * r * c2, -27 * c3) };
}

/// The largest curvature and torsion errors of a fit to the torus knot over
/// its largest curvature and |torsion|, each sample against the knot's
/// nearest point (of 2000, then Newton's method on the distance).
RelativeErrors torusKnotErrors(const FittedPolyline& fit)
{
  constexpr int Table = 2000;
  std::vector<Vec3> points(Table);
  for (int i = 0; i < Table; ++i)
  {
    points[i] = torusKnot(2 * Pi * i / Table)[0];
  }
  auto curvatureTorsion = [](double t) {
    const std::array<Vec3, 4> d = torusKnot(t);
    return exactCurvatureTorsion(d[1], d[2], d[3]);
  };
  double largestCurvature = 0.0, largestTorsion = 0.0;
  for (int i = 0; i < Table; ++i)
  {
    const std::array<double, 2> values = curvatureTorsion(2 * Pi * i / Table);
    largestCurvature = std::max(largestCurvature, values[0]);
    largestTorsion = std::max(largestTorsion, std::abs(values[1]));
  }
  const SampledCurve sampled = sampleFit(fit);
  RelativeErrors errors;
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    const Vec3 at = sampled.Samples.Values[k][0];
    int nearest = 0;
    for (int i = 1; i < Table; ++i)
    {
      nearest = (points[i] - at).squaredNorm() < (points[nearest] - at).squaredNorm() ? i : nearest;
    }
    double t = 2 * Pi * nearest / Table;
    for (int step = 0; step < 4; ++step)
    {
      const std::array<Vec3, 4> d = torusKnot(t);
      const Vec3 offset = d[0] - at;
      t -= offset.dot(d[1]) / (d[1].squaredNorm() + offset.dot(d[2]));
    }
    const std::array<double, 2> exact = curvatureTorsion(t);
    errors.Curvature = std::max(
      errors.Curvature, std::abs(sampled.Frames[k].Curvature - exact[0]) / largestCurvature);
    errors.Torsion =
      std::max(errors.Torsion, std::abs(sampled.Frames[k].Torsion - exact[1]) / largestTorsion);
  }
  return errors;
}

/// How much worse than its fixed curve an automatic curve may be: factor x
/// the fixed curve's error + floor.
struct Allowance
{
  double Factor;
  double Floor;
};

/// Fits the torus knot's points in the family's fixed and default modes,
/// prints both curves' errors and expects the default within the allowance.
FittedPolyline expectTorusKnotAccuracyKept(const Family& family, const std::vector<Vec3>& points,
  const FitOptions& options, const std::string& where, Allowance allowance)
{
  const FittedPolyline fixed = fitPolyline(points, options, family.Fixed);
  FittedPolyline automatic = fitPolyline(points, options, family.Automatic);
  const RelativeErrors fixedErrors = torusKnotErrors(fixed);
  const RelativeErrors errors = torusKnotErrors(automatic);
  std::printf("%s: violations %d -> %d, curvature %.3g -> %.3g, torsion %.3g -> %.3g\n",
    where.c_str(), fixed.Audit.violations(), automatic.Audit.violations(), fixedErrors.Curvature,
    errors.Curvature, fixedErrors.Torsion, errors.Torsion);
  EXPECT_LE(errors.Curvature, allowance.Factor * fixedErrors.Curvature + allowance.Floor) << where;
  EXPECT_LE(errors.Torsion, allowance.Factor * fixedErrors.Torsion + allowance.Floor) << where;
  return automatic;
}
} // namespace

TEST(AutomaticShape, EveryFamilysDefaultModeKeepsTheFixedCurvesAccuracyNearTorsionZeros)
{
  // A torus knot evenly sampled (closed, 33 to 129 points): its torsion
  // changes sign six times a turn, some zeros near a span's middle, where a
  // spline's torsion (one derivative above its curvature; a cubic's steps at
  // every knot) put its zero more than half a span off and the audit failed
  // it there; the generalized cubic's and qqr's automatic modes then bent
  // the curve (curvature errors 0.28-2.5 of the largest curvature at 33-65
  // points, against the fixed curves' 0.029-0.11). The sign change may now
  // happen within a span of where the data put it: every default mode keeps
  // its fixed curve's accuracy.
  for (const Family& family : families())
  {
    for (const int count : { 33, 64, 65, 129 })
    {
      std::vector<Vec3> points;
      for (int i = 0; i < count; ++i)
      {
        points.push_back(torusKnot(2 * Pi * i / count)[0]);
      }
      FitOptions closed;
      closed.Closed = true;
      const FittedPolyline automatic = expectTorusKnotAccuracyKept(family, points, closed,
        std::string(family.Name) + ", " + std::to_string(count) + " points", { 1.5, 1e-6 });
      EXPECT_TRUE(automatic.Audit.preserving()) << family.Name << ", " << count;
    }
  }
}

TEST(AutomaticShape, EveryDefaultModeKeepsItsAccuracyNearTorsionZerosOnUnevenSpacing)
{
  // The torus knot at parameters jittered by up to 0.35 of the spacing, open
  // and closed: the discrete torsion next to a zero is small on both sides
  // and the spline's zero can lie a segment beyond where the opposite
  // neighbour puts it (129 points, open: the generalized cubic's and qqr's
  // automatic modes bent the curve there, 0.018 -> 0.26 and 0.98 of the
  // largest curvature). Where a segment's own side's torsion grows to three
  // times its own within two segments, the sign may change within it too.
  for (const Family& family : families())
  {
    for (const bool closed : { false, true })
    {
      for (const unsigned seed : { 1u, 2u, 3u })
      {
        const int count = 129;
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> jitter(-0.35, 0.35);
        std::vector<Vec3> points;
        for (int i = 0; i < count; ++i)
        {
          points.push_back(torusKnot(2 * Pi * (i + jitter(random)) / count)[0]);
        }
        FitOptions options;
        options.Closed = closed;
        expectTorusKnotAccuracyKept(family, points, options,
          std::string(family.Name) + (closed ? ", closed" : ", open") + ", seed " +
            std::to_string(seed),
          { 2.0, 1e-3 });
      }
    }
  }
}

TEST(AutomaticShape, TheGeneralizedCubicAndQQRKeepAStraightRunsJoinLocal)
{
  // Their parameters sit on the spans: the run's last span straightens, the
  // helix's first keeps its own. At 32 points a turn, after each join the
  // curvature is within 10% of the helix's but on a few spans, and nowhere
  // beyond 3 times it (measured: generalized cubic 0 spans, 1.01 times; qqr
  // 4 spans, 2.2 times; the variable degree spline 7 spans, 90 times; the
  // quintic 12 spans, 2.1e3 times).
  const int perTurn = 32;
  for (const Family& family : families())
  {
    const std::string name = family.Name;
    const FittedPolyline automatic =
      fitPolyline(helixBetweenStraightRuns(perTurn), FitOptions{}, family.Automatic);
    const std::vector<double> errors = helixSpanCurvatureErrors(automatic, perTurn);
    int disturbed = 0;
    double largest = 0.0;
    for (int span = perTurn; span < 3 * perTurn; ++span)
    {
      disturbed += span < 2 * perTurn && errors[span] > 0.1;
      largest = std::max(largest, 1.0 + errors[span]);
    }
    std::printf("%s: curvature off by more than 10%% on %d spans after the first join, "
                "at most %.3g times the helix's\n",
      family.Name, disturbed, largest);
    if (name == "generalized cubic" || name == "qqr")
    {
      EXPECT_LE(disturbed, 6) << name;
      EXPECT_LE(largest, 3.0) << name;
    }
  }
}
