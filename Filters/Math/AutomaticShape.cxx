#include "AutomaticShape.h"

#include "ExtendedIndex.h"
#include "SparseSolve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace shapesplines
{
namespace
{
int failingBits(unsigned mask)
{
  int bits = 0;
  for (; mask; mask &= mask - 1)
  {
    ++bits;
  }
  return bits;
}

/// Per span of an audit: whether anything fails on it.
std::vector<char> failingSpans(const ShapeAudit& audit)
{
  std::vector<char> failing(audit.SpanMask.size());
  std::transform(audit.SpanMask.begin(), audit.SpanMask.end(), failing.begin(),
    [](unsigned mask) { return mask != 0; });
  return failing;
}

/// Per span: whether it lies within reach of a marked one (a closed line's wrap around).
std::vector<char> withinReach(const std::vector<char>& marked, int reach, bool closed)
{
  const int spans = static_cast<int>(marked.size());
  std::vector<char> in(spans, 0);
  for (int j = 0; j < spans; ++j)
  {
    for (int d = -reach; d <= reach && marked[j]; ++d)
    {
      const int k = closed ? wrapIndex(j + d, spans) : j + d;
      if (k >= 0 && k < spans)
      {
        in[k] = 1;
      }
    }
  }
  return in;
}

/**
 * The state of one automatic search (searchShape, improveShape): the levels
 * per span and what the rounds learnt about each span, the curve of the
 * current levels and its span-by-span audit.
 */
class ShapeSearch
{
public:
  ShapeSearch(const FitContext& context, const CleanPolyline& reference, const ShapeLadder& ladder,
    bool raiseTwistNeighbours)
    : RaiseTwistNeighbours(raiseTwistNeighbours)
    , Context(context)
    , Reference(reference)
    , Ladder(ladder)
    , Shape(discreteShape(reference, context.Options.Tolerances, ladder.ReferenceNoise,
        context.CoordinateNoise, context.RoundingSteps))
    , Spans(reference.numberOfSpans())
    , Auditor(reference, this->Shape, context.Options.Tolerances,
        context.Options.AuditSubdivisions, context.CoordinateNoise,
        ladder.Bounds.CurvatureChange > 0.0 ? AuditFigures::BoundsAndSampleCurvatures
                                            : AuditFigures::Bounds)
    , Levels(this->Spans, 0)
    , Frozen(this->Spans, 0)
    , OutsideMends(this->Spans, 0)
    , Stalls(this->Spans, 0)
    , Step(this->Spans, 1)
    , RaisedBefore(this->Spans, 0)
    , Stale(this->Spans, 1)
  {
    const double largestTurn = *std::max_element(this->Shape.Curvature.begin(), this->Shape.Curvature.end());
    const bool straightRuns =
      std::any_of(this->Shape.Collinear.begin(), this->Shape.Collinear.end(), [](char c) { return c; });
    const double diagonal = boundingBoxDiagonal(reference.Points);
    const ShapeBounds& bounds = ladder.Bounds;
    // Relative to the data's own turns however slight: with a floor of one
    // over the diagonal, the quintic bent a line whose points stray 1e-7 of
    // its length to a radius of a hundredth of it (1.4e5 times the data's
    // curvature). Only points with no turn at all take that floor.
    const double fallback = diagonal > 0.0 ? 1.0 / diagonal : 1.0;
    this->CurvatureBound =
      (straightRuns ? bounds.StraightRunCurvatureFactor : bounds.CurvatureFactor) *
      (largestTurn > 0.0 ? largestTurn : fallback);
    if (diagonal > 0.0)
    {
      // Noisy points turn tightly for their size: their factor alone let the
      // quintic make what the filter then warns about as a cusp (the aorta:
      // 1.1e6 over the diagonal; at this bound 4.6e5, the same violations).
      this->CurvatureBound = std::min(this->CurvatureBound, CuspCurvature / diagonal);
    }
  }

  AutomaticShape run()
  {
    this->start();
    for (int j = 0; j < this->Spans; ++j)
    {
      this->OutsideMends[j] = (this->Audit.SpanMask[j] & ~this->Ladder.Mends) != 0;
      this->Frozen[j] = this->Frozen[j] || this->OutsideMends[j];
    }
    return this->search();
  }

  /**
   * Searches again only around the spans an earlier search left failing:
   * outside that window the spans keep that search's levels, frozen; inside,
   * they start from level 0 (start) or a common level (startAt). A long
   * line's few violations left then cost a search of their neighbourhood,
   * not of the whole line.
   */
  void keepOutside(const AutomaticShape& earlier, int reach)
  {
    std::fill(this->Frozen.begin(), this->Frozen.end(), 1);
    for (const int j : this->around(failingSpans(earlier.Audit), reach))
    {
      this->Frozen[j] = 0;
    }
    for (int j = 0; j < this->Spans; ++j)
    {
      this->Levels[j] = this->Frozen[j] ? earlier.Levels[j] : 0;
    }
  }

  /// Builds the start levels (level 0 unless keepOutside) and audits them whole.
  void start()
  {
    this->buildWhole();
    for (int j = 0; j < this->Spans && this->Ladder.Bounds.CurvatureChange > 0.0; ++j)
    {
      this->StartCurvatures.push_back(this->Auditor.sampleCurvatures(j));
    }
    this->Best = this->StartLevels = this->Levels;
    this->BestViolations = this->StartViolations = this->Audit.violations();
  }

  /**
   * Starts instead from every span not frozen (keepOutside) at one level,
   * but level 0 around the spans that this pushes beyond the bounds, until
   * none is but where level 0 already was. False if that takes more than a
   * few rebuilds.
   */
  bool startAt(int level) { return this->startAt(std::vector<int>(this->Spans, level)); }

  /// The same from the levels given, span by span.
  bool startAt(const std::vector<int>& levels)
  {
    for (int j = 0; j < this->Spans; ++j)
    {
      this->Levels[j] = this->Frozen[j] ? this->Levels[j] : levels[j];
    }
    if (!this->settleWithinBounds(false))
    {
      return false;
    }
    this->Best = this->StartLevels = this->Levels;
    this->BestViolations = this->StartViolations = this->Audit.violations();
    return true;
  }

  int violations() const { return this->Audit.violations(); }
  const ShapeAudit& audit() const { return this->Audit; }
  const std::vector<int>& levels() const { return this->Levels; }

  /**
   * The rounds after start(), and the best curve met. The best is judged on
   * the audits of each round's neighbourhood, which miss what a global solve
   * moves farther away: once the rounds end elsewhere, the best curve is
   * audited whole and, where that finds failures they missed, the search
   * goes on from it, once (the aorta's second line: qqr 3 -> 1 violations
   * left; 12 seeds of the users' data generator: the quintic 502 -> 492).
   */
  AutomaticShape search()
  {
    int round = this->searchRounds(1);
    if (this->Best != this->Levels)
    {
      const int counted = this->BestViolations;
      this->switchToWhole(this->Best);
      this->BestViolations = this->Audit.violations();
      if (this->BestViolations > counted)
      {
        const std::vector<int> audited = this->Best;
        const int auditedViolations = this->BestViolations;
        std::fill(this->Step.begin(), this->Step.end(), 1);
        std::fill(this->RaisedBefore.begin(), this->RaisedBefore.end(), 0);
        round = this->searchRounds(round);
        this->keepIfBetterWhole(audited, auditedViolations);
      }
    }
    // Misled by its neighbourhoods' audits, a search can end worse than
    // where it started (a heavy-tailed helix: the quintic 1 -> 5 violations).
    if (this->StartViolations < this->BestViolations)
    {
      this->keepIfBetterWhole(this->StartLevels, this->StartViolations);
    }
    return this->finish(round);
  }

  /**
   * Where the searches left violations: each span near one left failing
   * (RefineReach on each side, in refineOrder's order; skipped once none
   * near it fails) tried alone at a few other levels (refinedLevels), the
   * curve rebuilt and audited around it, the change kept where it lowers
   * the violations within the bounds; twice over, at most `trials` builds.
   * The curve audited whole if it has fewer violations than found, none
   * otherwise.
   */
  std::optional<AutomaticShape> refine(const AutomaticShape& found, int trials)
  {
    if (this->Ladder.Bounds.CurvatureChange > 0.0)
    {
      this->start(); // level 0's curvatures, which that bound compares with
    }
    this->Levels = found.Levels;
    this->buildWhole();
    std::vector<Figures> before(this->Spans);
    for (int j = 0; j < this->Spans; ++j)
    {
      before[j] = this->figures(j);
    }
    auto withinBounds = [&](const std::vector<int>& spans) {
      return std::none_of(spans.begin(), spans.end(),
        [&](int j) { return this->beyond(this->figures(j), before[j]); });
    };
    int violations = this->violations();
    std::vector<int> keptLevels = this->Levels;
    std::unique_ptr<shapesplines::Curve> kept = std::move(this->Curve);
    // The spans last audited on a trial's curve that was not kept, audited
    // again on the kept one only once a trial elsewhere needs them (the next
    // trial is mostly around the same span).
    std::vector<int> rejected;
    auto restoreOutside = [&](const std::vector<int>& moved) {
      for (const int k : rejected)
      {
        if (std::find(moved.begin(), moved.end(), k) == moved.end())
        {
          this->Auditor.audit(*kept, k);
        }
      }
      rejected.clear();
    };
    // A span whose every level was tried since the last trial kept would meet
    // the same curve and the same findings again (a span listed next to
    // several failing ones, or again in the second pass): passed over.
    int keptTrials = 0;
    std::vector<int> triedSinceKept(this->Spans, -1);
    for (int pass = 0; pass < RefinePasses && violations > 0; ++pass)
    {
      restoreOutside({});
      const ShapeAudit audit = this->Auditor.result();
      const std::vector<int> order = this->refineOrder(audit);
      std::vector<char> failing = failingSpans(audit); // on the kept curve
      const int violationsBefore = violations;
      for (size_t t = 0; t < order.size() && violations > 0 && trials > 0; ++t)
      {
        const double passDone = (pass + static_cast<double>(t) / order.size()) / RefinePasses;
        this->progressAt(static_cast<int>(t), 64, SearchShare + (1.0 - SearchShare) * passDone);
        const int j = order[t];
        std::vector<char> marked(this->Spans, 0);
        marked[j] = 1;
        const std::vector<int> near = this->around(marked, RefineReach);
        if (std::none_of(near.begin(), near.end(), [&](int k) { return failing[k] != 0; }) ||
          triedSinceKept[j] == keptTrials)
        {
          continue; // what it was listed for has been mended, or nothing changed since its trials
        }
        const std::vector<int> moved = this->around(marked, this->Ladder.Reach);
        const int keptBefore = keptTrials;
        for (const int level : this->refinedLevels(keptLevels[j]))
        {
          if (trials-- <= 0)
          {
            break; // and refining ends: no mark below is read again
          }
          this->Levels = keptLevels;
          this->Levels[j] = level;
          try
          {
            this->Curve = this->Ladder.Build(this->Levels);
          }
          catch (const SingularSystem&)
          {
            continue; // not a curve: the kept one stays
          }
          restoreOutside(moved);
          // Only the spans failing on the kept curve can lose a violation:
          // they are audited first, the others left without findings, which
          // counts the trial's violations from below; most trials end there
          // (87-90% of qqr's and the quintic's on noisy helices).
          for (const int k : moved)
          {
            if (failing[k])
            {
              this->Auditor.audit(*this->Curve, k);
            }
            else
            {
              this->Auditor.forget(k);
            }
          }
          if (this->Auditor.result().violations() >= violations)
          {
            rejected = moved;
            continue;
          }
          for (const int k : moved)
          {
            if (!failing[k])
            {
              this->Auditor.audit(*this->Curve, k);
            }
          }
          const ShapeAudit trial = this->Auditor.result();
          const int now = trial.violations();
          if (now < violations && withinBounds(moved))
          {
            failing = failingSpans(trial);
            violations = now;
            keptLevels = this->Levels;
            kept = std::move(this->Curve);
            ++keptTrials;
          }
          else
          {
            rejected = moved;
          }
        }
        if (keptTrials == keptBefore)
        {
          triedSinceKept[j] = keptTrials;
        }
      }
      if (violations == violationsBefore)
      {
        break;
      }
    }
    if (keptLevels == found.Levels)
    {
      return std::nullopt; // no trial kept: the curve found
    }
    this->Levels = keptLevels;
    this->Curve = std::move(kept);
    std::fill(this->Stale.begin(), this->Stale.end(), 1);
    this->auditStale(); // a global solve moves far spans a little
    std::vector<int> all(this->Spans);
    std::iota(all.begin(), all.end(), 0);
    if (this->violations() >= found.Audit.violations() || !withinBounds(all))
    {
      return std::nullopt;
    }
    AutomaticShape result;
    result.Rounds = found.Rounds;
    result.Spline = std::move(this->Curve);
    result.Audit = std::move(this->Audit);
    result.Levels = std::move(this->Levels);
    return result;
  }

private:
  /// The best curve met, audited whole, if it has fewer violations than
  /// the levels given (whole: count); those levels and their curve otherwise.
  void keepIfBetterWhole(const std::vector<int>& levels, int count)
  {
    if (this->Best == levels)
    {
      return;
    }
    this->switchToWhole(this->Best);
    this->BestViolations = this->Audit.violations();
    if (this->BestViolations >= count)
    {
      this->Best = levels;
      this->switchToWhole(levels);
      this->BestViolations = count;
    }
  }

  /// The curve of these levels, audited whole (built only if they are not the current ones).
  void switchToWhole(const std::vector<int>& levels)
  {
    if (levels != this->Levels)
    {
      this->Levels = levels;
      this->buildWhole();
    }
    else
    {
      this->auditStale();
    }
    this->AuditedWhole = true;
  }

  /// Rounds of raises from round on, until the search stops; the round it stopped at.
  int searchRounds(int round)
  {
    int roundsWithoutBetter = 0;
    for (; round <= this->Ladder.MaxRounds && roundsWithoutBetter < MostRoundsWithoutBetter; ++round)
    {
      this->progressAt(round, 1, SearchShare * round / this->Ladder.MaxRounds);
      const std::vector<char> raise = this->chooseRaises();
      if (std::none_of(raise.begin(), raise.end(), [](char r) { return r; }))
      {
        if (this->AuditedWhole || this->WholeAudits >= MostWholeAudits)
        {
          break;
        }
        this->auditWhole(); // nothing seen failing, or nothing left to raise: look everywhere
        continue;
      }
      this->raiseAndAudit(raise);
      ++roundsWithoutBetter;
      if (this->Audit.violations() < this->BestViolations)
      {
        this->Best = this->Levels;
        this->BestViolations = this->Audit.violations();
        roundsWithoutBetter = 0;
      }
    }
    return round;
  }

  /// Whole-curve audits after the first: a global solve moves far spans a little.
  static constexpr int MostWholeAudits = 4;
  /// Rounds of raises without a curve better than the best met before the
  /// search gives up: a 1e5-point noisy helix's variable degree retry met
  /// its best in 8 rounds and then spent 55 more whole-line solves hovering
  /// 10-20% above it.
  static constexpr int MostRoundsWithoutBetter = 8;

  /// What the bounds limit on a span.
  struct Figures
  {
    double Curvature = 0.0, Speed = 1.0, Deviation = 0.0, Change = 1.0;
  };

  Figures figures(int j) const
  {
    return { this->Auditor.largestCurvature(j), this->Auditor.lowestSpeed(j),
      this->Auditor.largestDeviation(j), this->curvatureChange(j) };
  }

  /// The largest factor between span j's curvature and the level-0 curve's
  /// at the same samples (see ShapeBounds::CurvatureChange): below it where
  /// the latter stands above the noise, above the larger of it and the
  /// noise's curvature anywhere (a kink on a straighter stretch); 1 when
  /// that bound is off.
  double curvatureChange(int j) const
  {
    const std::vector<double>& vertexNoise = this->Ladder.ReferenceNoise;
    if (this->Ladder.Bounds.CurvatureChange <= 0.0 || this->StartCurvatures.empty())
    {
      return 1.0;
    }
    const double chord = this->Reference.segment(j).norm();
    const double sagitta = vertexNoise.empty()
      ? 0.0
      : std::max(vertexNoise[j], vertexNoise[(j + 1) % vertexNoise.size()]);
    const double noise = NoiseSignificance * 8.0 * sagitta / std::max(chord * chord, 1e-300);
    const std::vector<double>& start = this->StartCurvatures[j];
    const std::vector<double>& now = this->Auditor.sampleCurvatures(j);
    double change = 1.0;
    for (size_t k = 0; k < start.size() && k < now.size(); ++k)
    {
      if (start[k] > noise)
      {
        change = std::max(change, start[k] / std::max(now[k], 1e-300));
      }
      change = std::max(change, now[k] / std::max({ start[k], noise, 1e-300 }));
    }
    return change;
  }

  /// Span j, or -1 beyond an open curve's ends (closed curves wrap).
  int span(int j) const
  {
    if (this->Reference.Closed)
    {
      return wrapIndex(j, this->Spans);
    }
    return j >= 0 && j < this->Spans ? j : -1;
  }

  /// The spans within reach of a marked one.
  std::vector<int> around(const std::vector<char>& marked, int reach) const
  {
    const std::vector<char> in = withinReach(marked, reach, this->Reference.Closed);
    std::vector<int> spans;
    for (int j = 0; j < this->Spans; ++j)
    {
      if (in[j])
      {
        spans.push_back(j);
      }
    }
    return spans;
  }

  /// Whether a span's figures cross a bound, and are worse there than `than`.
  bool beyond(const Figures& now, const Figures& than) const
  {
    const ShapeBounds& bounds = this->Ladder.Bounds;
    return (now.Curvature > this->CurvatureBound && now.Curvature > than.Curvature) ||
      (now.Speed < bounds.SpeedFraction && now.Speed < than.Speed) ||
      (now.Deviation > bounds.Deviation && now.Deviation > than.Deviation) ||
      (bounds.CurvatureChange > 0.0 && now.Change > bounds.CurvatureChange &&
        now.Change > than.Change);
  }

  /// The spans beyond the bounds, whatever they were before (CurvatureChange
  /// aside: it is measured from level 0's curve, which a common start is not).
  std::vector<char> beyondBounds() const
  {
    constexpr double Infinity = std::numeric_limits<double>::infinity();
    const Figures unbeatable{ 0.0, Infinity, 0.0, Infinity };
    std::vector<char> beyond(this->Spans, 0);
    for (int j = 0; j < this->Spans; ++j)
    {
      beyond[j] = this->beyond(this->figures(j), unbeatable);
    }
    return beyond;
  }

  /**
   * Lowers to level 0 the spans around those beyond the bounds and rebuilds,
   * until none is but where level 0 already was (a global solve moves spans
   * the search did not check). Where every span within Reach of one beyond
   * the bounds already is at level 0 and the level-0 curve is within them
   * there, farther levels pushed it out: the reach doubles until some are
   * lowered (the variable degree spline on a helix with gaps from 1e-11 of
   * a turn to two kept a span 2.9 of its segments away from its data, 0.37
   * at level 0). False if that takes more than a few rebuilds. built: the
   * current curve is of these levels, audited whole.
   */
  bool settleWithinBounds(bool built)
  {
    auto lowerAround = [&](const std::vector<char>& marked, int reach) {
      bool lowered = false;
      for (const int j : this->around(marked, reach))
      {
        lowered = lowered || this->Levels[j] != 0;
        this->Levels[j] = 0;
      }
      return lowered;
    };
    constexpr int MostResets = 8;
    for (int reset = 0; reset <= MostResets; ++reset, built = false)
    {
      if (!built)
      {
        this->buildWhole();
      }
      const std::vector<char> beyond = this->beyondBounds();
      bool lowered = lowerAround(beyond, this->Ladder.Reach);
      if (!lowered && std::any_of(beyond.begin(), beyond.end(), [](char b) { return b; }))
      {
        // From the third rebuild on, a span within a global solve's ripple of
        // level 0's figures is not pushed: rebuilds move level-0 spans a little,
        // and chasing that ripple failed settling, which gave the whole line
        // back to level 0 (a quintic planar spiral: 60 violations instead of 5).
        constexpr double Ripple = 0.05;
        const double ripple = reset >= 2 ? Ripple : 0.0;
        const std::vector<Figures>& levelZero = this->levelZeroFigures();
        std::vector<char> pushed(this->Spans, 0);
        for (int j = 0; j < this->Spans; ++j)
        {
          const Figures& zero = levelZero[j];
          const Figures rippled{ zero.Curvature * (1.0 + ripple), zero.Speed * (1.0 - ripple),
            zero.Deviation * (1.0 + ripple), zero.Change * (1.0 + ripple) };
          pushed[j] = beyond[j] && this->beyond(this->figures(j), rippled);
        }
        for (int reach = 2 * this->Ladder.Reach; !lowered && reach < 2 * this->Spans; reach *= 2)
        {
          lowered = lowerAround(pushed, reach);
        }
      }
      if (!lowered)
      {
        return true;
      }
    }
    return false;
  }

  /// Per span, the level-0 curve's figures (built and audited apart, once, when first asked).
  const std::vector<Figures>& levelZeroFigures()
  {
    if (this->LevelZero.empty())
    {
      const FitOptions& options = this->Context.Options;
      CurveAuditor auditor(this->Reference, this->Shape, options.Tolerances,
        options.AuditSubdivisions, this->Context.CoordinateNoise, AuditFigures::Bounds);
      const std::unique_ptr<shapesplines::Curve> curve =
        this->Ladder.Build(std::vector<int>(this->Spans, 0));
      for (int j = 0; j < this->Spans; ++j)
      {
        auditor.audit(*curve, j);
        this->LevelZero.push_back({ auditor.largestCurvature(j), auditor.lowestSpeed(j),
          auditor.largestDeviation(j), 1.0 });
      }
    }
    return this->LevelZero;
  }

  /**
   * The spans refine() tries in a pass, in an order that does not depend on
   * the direction of the line (each trial kept changes what the next one
   * meets): the failing spans worst first (SpanDeficiency, then the longer
   * segment of the reference), each followed by its neighbours up to
   * RefineReach away, nearest first, the worse (or longer) of a pair first.
   */
  std::vector<int> refineOrder(const ShapeAudit& audit) const
  {
    auto first = [&](int a, int b) {
      const double deficiencyA = audit.SpanDeficiency[a], deficiencyB = audit.SpanDeficiency[b];
      if (deficiencyA != deficiencyB)
      {
        return deficiencyA > deficiencyB;
      }
      const double lengthA = this->Reference.segment(a).norm();
      const double lengthB = this->Reference.segment(b).norm();
      return lengthA != lengthB ? lengthA > lengthB : a < b;
    };
    std::vector<int> failing = this->around(failingSpans(audit), 0);
    std::sort(failing.begin(), failing.end(), first);
    std::vector<int> order;
    for (const int f : failing)
    {
      order.push_back(f);
      for (int distance = 1; distance <= RefineReach; ++distance)
      {
        int before = this->span(f - distance), after = this->span(f + distance);
        if (before >= 0 && after >= 0 && first(after, before))
        {
          std::swap(before, after);
        }
        for (const int j : { before, after })
        {
          if (j >= 0)
          {
            order.push_back(j);
          }
        }
      }
    }
    return order;
  }

  /**
   * The levels refine() tries a span at, other than its own: 0 (unless the
   * ladder says otherwise) and 1 (the searches raise a neighbourhood together
   * and overshoot: most of what refining mends on short noisy lines) and a
   * quarter, half and all of the top (where a span stalled or met the bounds
   * short of the level that mends it).
   */
  std::vector<int> refinedLevels(int level) const
  {
    const int top = this->Ladder.TopLevel;
    const int lowest = this->Ladder.RefineBackToLevelZero ? 0 : 1;
    std::vector<int> levels;
    for (const int other : { 0, 1, top / 4, top / 2, top })
    {
      if (other != level && other >= lowest && other <= top &&
        std::find(levels.begin(), levels.end(), other) == levels.end())
      {
        levels.push_back(other);
      }
    }
    return levels;
  }

  bool canRise(int j) const
  {
    return j >= 0 && !this->Frozen[j] && this->Levels[j] < this->Ladder.TopLevel;
  }

  /// Each failing span, or where it cannot rise, its neighbours (all spans: Uniform).
  std::vector<char> chooseRaises() const
  {
    std::vector<char> raise(this->Spans, 0);
    if (this->Audit.preserving())
    {
      return raise;
    }
    auto raiseNeighbours = [&](int j) {
      for (const int neighbour : { this->span(j - 1), this->span(j + 1) })
      {
        raise[std::max(neighbour, 0)] |= this->canRise(neighbour);
      }
    };
    for (int j = 0; j < this->Spans; ++j)
    {
      if (this->Ladder.Uniform)
      {
        raise[j] = this->canRise(j);
      }
      else if (this->Audit.SpanMask[j] != 0 && this->canRise(j))
      {
        raise[j] = 1;
        // Torsion is a third derivative, which the solve spreads over the
        // neighbours: a span raised alone pushes its sign change into the
        // next span, which then fails in the round after. Raised together,
        // the three take half the rounds (measured on noisy helices).
        const bool twists = this->Audit.SpanMask[j] & criterionBit(ShapeCriterion::TorsionSignOnSpan);
        if (this->RaiseTwistNeighbours && twists)
        {
          raiseNeighbours(j);
        }
      }
      else if (this->Audit.SpanMask[j] != 0 && !this->OutsideMends[j])
      {
        raiseNeighbours(j);
      }
    }
    return raise;
  }

  void auditWhole()
  {
    this->auditStale();
    this->AuditedWhole = true;
    ++this->WholeAudits;
    if (this->Best == this->Levels)
    {
      this->BestViolations = this->Audit.violations();
    }
  }

  /// The current curve's audit, every span not yet audited on it.
  void auditStale()
  {
    for (int j = 0; j < this->Spans; ++j)
    {
      // A whole audit only checks for an abort: the line's fraction stays where
      // the rounds or trials put it (it had run ahead to the end on the first).
      reportProgress(this->Context.Options.Progress, j, 1024, this->ReportedFraction);
      if (this->Stale[j])
      {
        this->Auditor.audit(*this->Curve, j);
      }
    }
    std::fill(this->Stale.begin(), this->Stale.end(), 0);
    this->Audit = this->Auditor.result();
  }

  /// Reports the line's progress at fraction (it can abort).
  void progressAt(long step, long every, double fraction)
  {
    this->ReportedFraction = fraction;
    reportProgress(this->Context.Options.Progress, step, every, fraction);
  }

  /// The curve of the current levels, audited whole.
  void buildWhole()
  {
    this->Curve = this->Ladder.Build(this->Levels);
    std::fill(this->Stale.begin(), this->Stale.end(), 1);
    this->auditStale();
  }

  void rebuild(const std::vector<int>& moved)
  {
    this->Curve = this->Ladder.Build(this->Levels);
    std::fill(this->Stale.begin(), this->Stale.end(), 1);
    for (const int j : moved)
    {
      this->Auditor.audit(*this->Curve, j);
      this->Stale[j] = 0;
    }
  }

  /**
   * Rebuilds with the spans' raises on top of levels already solved. Where
   * the system is singular (qqr's local parameters can make an open line's
   * end condition depend on the other rows), halves them until the span
   * that makes it so, whose raise is undone and its level frozen.
   */
  void rebuildAvoidingSingular(const std::vector<int>& spans, const std::vector<int>& previous,
    std::vector<char>& raise, const std::vector<int>& moved)
  {
    try
    {
      this->rebuild(moved);
      return;
    }
    catch (const SingularSystem&)
    {
    }
    const std::vector<int> raisedLevels = this->Levels;
    for (const int j : spans)
    {
      this->Levels[j] = previous[j];
    }
    if (spans.size() == 1)
    {
      const int j = spans.front();
      this->Frozen[j] = 1;
      this->Step[j] = 1;
      this->RaisedBefore[j] = raise[j] = 0;
      this->rebuild(moved); // the levels solved before
      return;
    }
    const auto middle = spans.begin() + static_cast<std::ptrdiff_t>(spans.size() / 2);
    for (const std::vector<int>& part : { std::vector<int>(spans.begin(), middle),
           std::vector<int>(middle, spans.end()) })
    {
      for (const int j : part)
      {
        this->Levels[j] = raisedLevels[j];
      }
      this->rebuildAvoidingSingular(part, previous, raise, moved);
    }
  }

  void raiseAndAudit(std::vector<char> raise)
  {
    // A span raised again (still failing) takes a step twice as long: the
    // level it needs is reached in a few rounds, overshooting it at most 2x.
    const std::vector<int> previous = this->Levels;
    for (int j = 0; j < this->Spans; ++j)
    {
      this->Step[j] = raise[j] && this->RaisedBefore[j] ? 2 * this->Step[j] : std::max(1, this->Step[j] / 2);
      this->Levels[j] = raise[j] ? std::min(this->Ladder.TopLevel, this->Levels[j] + this->Step[j]) : this->Levels[j];
      this->RaisedBefore[j] = raise[j];
    }
    const std::vector<int> moved = this->around(raise, this->Ladder.Reach);
    std::vector<Figures> before(this->Spans);
    for (const int j : moved)
    {
      before[j] = this->figures(j);
    }
    std::vector<int> raised;
    for (int j = 0; j < this->Spans; ++j)
    {
      if (raise[j])
      {
        raised.push_back(j);
      }
    }
    this->rebuildAvoidingSingular(raised, previous, raise, moved);
    // An undone raise moves the curve too (a global solve): check again.
    while (this->undoBeyondBounds(raise, previous, moved, before))
    {
      this->rebuild(moved);
    }
    const ShapeAudit next = this->Auditor.result();
    this->AuditedWhole = false;
    this->freezeStalled(raise, next);
    this->Audit = next;
  }

  /**
   * Undoes the raises near a span pushed beyond the bounds (and beyond where
   * it was): a long step is tried again as a single one, a single one is the
   * last (the span's level is frozen). True if anything was undone.
   */
  bool undoBeyondBounds(std::vector<char>& raise, const std::vector<int>& previous,
    const std::vector<int>& moved, const std::vector<Figures>& before)
  {
    std::vector<char> beyond(this->Spans, 0);
    bool anyBeyond = false;
    for (const int j : moved)
    {
      if (this->beyond(this->figures(j), before[j]))
      {
        beyond[j] = anyBeyond = true;
      }
    }
    bool undone = false;
    for (const int j : anyBeyond ? this->around(beyond, this->Ladder.Reach) : std::vector<int>{})
    {
      if (raise[j])
      {
        this->Levels[j] = previous[j];
        this->Frozen[j] = this->Step[j] == 1;
        this->Step[j] = 1;
        this->RaisedBefore[j] = raise[j] = 0;
        undone = true;
      }
    }
    return undone;
  }

  /// Freezes a level that has three times in a row not brought its spans
  /// closer to passing (fewer failures, or a tenth less deficiency).
  void freezeStalled(const std::vector<char>& raise, const ShapeAudit& next)
  {
    auto nearby = [&](const ShapeAudit& a, int j) {
      double deficiency = 0.0;
      int bits = 0;
      for (int d = -1; d <= 1; ++d)
      {
        const int k = this->span(j + d);
        if (k >= 0)
        {
          deficiency += a.SpanDeficiency[k];
          bits += failingBits(a.SpanMask[k]);
        }
      }
      return std::make_pair(bits, deficiency);
    };
    constexpr int MostStalls = 3;
    for (int j = 0; j < this->Spans; ++j)
    {
      if (raise[j])
      {
        const auto [bitsBefore, deficiencyBefore] = nearby(this->Audit, j);
        const auto [bitsAfter, deficiencyAfter] = nearby(next, j);
        const bool helped = bitsAfter < bitsBefore || deficiencyAfter < 0.9 * deficiencyBefore;
        this->Stalls[j] = helped ? 0 : this->Stalls[j] + 1;
        this->Frozen[j] = this->Frozen[j] || this->Stalls[j] >= MostStalls;
      }
    }
  }

  /// The best curve met, audited whole.
  AutomaticShape finish(int rounds)
  {
    AutomaticShape result;
    result.Rounds = rounds;
    const bool current = this->Best == this->Levels;
    if (current && !this->AuditedWhole)
    {
      this->auditStale();
    }
    this->Levels = this->Best;
    if (!this->settleWithinBounds(current))
    {
      std::fill(this->Levels.begin(), this->Levels.end(), 0);
      this->buildWhole();
    }
    result.Spline = std::move(this->Curve);
    result.Audit = std::move(this->Audit);
    result.Levels = std::move(this->Levels);
    return result;
  }

  const bool RaiseTwistNeighbours;
  const FitContext& Context;
  const CleanPolyline& Reference;
  const ShapeLadder& Ladder;
  const DiscreteShape Shape;
  const int Spans;
  double CurvatureBound = 0.0;
  CurveAuditor Auditor;
  std::vector<int> Levels;
  std::vector<char> Frozen; ///< no longer raised: beyond the bounds, or stalled
  /// Left as they are, neighbours too: level 0 fails what the ladder does not mend there.
  std::vector<char> OutsideMends;
  std::vector<int> Stalls;
  std::vector<int> Step;
  std::vector<char> RaisedBefore; ///< raised in the last round
  std::unique_ptr<shapesplines::Curve> Curve;
  std::vector<char> Stale; ///< not audited on the current curve (a global solve moves every span)
  ShapeAudit Audit;
  bool AuditedWhole = true;
  int WholeAudits = 0;
  std::vector<int> Best;
  int BestViolations = 0;
  /// The levels the search started from and their violations, audited whole.
  std::vector<int> StartLevels;
  int StartViolations = 0;
  std::vector<std::vector<double>> StartCurvatures; ///< per span, of level 0 (CurvatureChange)
  std::vector<Figures> LevelZero; ///< see levelZeroFigures
  /// The line's fraction last reported: a search's rounds the first
  /// SearchShare of it, refining the rest (a search that ends early jumps).
  double ReportedFraction = 0.0;
  static constexpr double SearchShare = 0.5;
};
} // namespace

std::vector<int> knotLevels(const std::vector<int>& spanLevels, bool closed)
{
  const int spans = static_cast<int>(spanLevels.size());
  const int knots = closed ? spans : spans + 1;
  std::vector<int> levels(knots, 0);
  for (int j = 0; j < spans; ++j)
  {
    levels[j] = std::max(levels[j], spanLevels[j]);
    int& right = levels[(j + 1) % knots];
    right = std::max(right, spanLevels[j]);
  }
  return levels;
}

double raisedTimes(double start, int level, const std::function<double(double)>& raise)
{
  double value = start;
  for (int step = 0; step < level; ++step)
  {
    const double next = raise(value);
    if (next == value)
    {
      break;
    }
    value = next;
  }
  return value;
}

int stepsToCap(double start, const std::function<double(double)>& raise)
{
  constexpr int MostSteps = 64;
  double value = start;
  int steps = 0;
  for (; steps < MostSteps; ++steps)
  {
    const double next = raise(value);
    if (next == value)
    {
      break;
    }
    value = next;
  }
  return steps;
}

BuiltCurve builtCurve(AutomaticShape found)
{
  BuiltCurve built;
  built.Spline = std::move(found.Spline);
  built.Audit = std::move(found.Audit);
  return built;
}

BuiltCurve fixedOrAutomatic(bool automatic, const FitContext& context,
  const CleanPolyline& reference, const ShapeLadder& ladder)
{
  if (!automatic)
  {
    BuiltCurve built;
    built.Spline = ladder.Build(std::vector<int>(reference.numberOfSpans(), 0));
    return built;
  }
  return builtCurve(preserveShapeAutomatically(context, reference, ladder));
}

namespace
{
/// Levels 3, 5, 8, 12, ... (about x1.5 a step) below top, then top.
std::vector<int> commonLevels(int top)
{
  std::vector<int> levels;
  for (int level = std::min(3, top); level < top; level = std::max(level + 1, (3 * level + 1) / 2))
  {
    levels.push_back(level);
  }
  if (top > 0)
  {
    levels.push_back(top);
  }
  return levels;
}

/// Rounds of the search from the windows' assembled levels (searchFromCommonLevel).
constexpr int AssembledStartRounds = 2;

/**
 * The search again from a common level: every span at levels 3, 5, 8, 12,
 * ... up to the top (one or two up, the first search has tried; level 0
 * around spans this pushes beyond the bounds) until one keeps the shape,
 * and, where the windows around what the first search left failing are
 * several, each window at the level where it failed least; the start with
 * the fewest violations kept (none better than the first search's: no
 * search), and the search from there (a few rounds from the assembled one).
 * On a long line no single level beats the first search everywhere (a noisy
 * helix of 2e4 points, the quintic: 534 violations left with or without
 * this retry, 469 with the windows assembled; its pieces of 50 points, 348
 * without it, 292 with it). A level a little up can push a span beyond the
 * bounds where one far up is fine (the aorta's quintic: 1.9e4 times the
 * data's curvature at gamma 0.5 on every knot, 560 at 0.05), which a search
 * that stops at the bounds never reaches.
 */
std::optional<AutomaticShape> searchFromCommonLevel(const FitContext& context,
  const CleanPolyline& reference, const ShapeLadder& ladder, const AutomaticShape& earlier)
{
  // The windows around what the first search left failing, each numbered
  // (-1: outside them), and per window the fewest failures met and the levels then.
  const int spans = static_cast<int>(earlier.Levels.size());
  const std::vector<char> in =
    withinReach(failingSpans(earlier.Audit), RetryReach, reference.Closed);
  std::vector<int> window(spans, -1);
  int windows = 0;
  for (int j = 0; j < spans; ++j)
  {
    window[j] = !in[j] ? -1 : (j > 0 && in[j - 1] ? windows - 1 : windows++);
  }
  auto failuresPerWindow = [&](const ShapeAudit& audit) {
    std::vector<int> failures(windows, 0);
    for (int j = 0; j < spans; ++j)
    {
      if (window[j] >= 0)
      {
        failures[window[j]] += failingBits(audit.SpanMask[j]);
      }
    }
    return failures;
  };
  std::vector<int> fewest = failuresPerWindow(earlier.Audit);
  std::vector<int> assembled = earlier.Levels;

  // A search started from a level (or levels) around what the first search
  // left failing; none where the start takes too many rebuilds or its system
  // is singular (a level the first search never reached: not a start).
  auto started = [&](const ShapeLadder& searchLadder,
                   const auto& start) -> std::unique_ptr<ShapeSearch> {
    auto search = std::make_unique<ShapeSearch>(context, reference, searchLadder, true);
    search->keepOutside(earlier, RetryReach);
    try
    {
      if (search->startAt(start))
      {
        return search;
      }
    }
    catch (const SingularSystem&)
    {
      // not a start
    }
    return nullptr;
  };
  // The assembled start's ladder (a search keeps its ladder by reference).
  ShapeLadder shortSearch = ladder;
  shortSearch.MaxRounds = std::min(ladder.MaxRounds, AssembledStartRounds);
  std::unique_ptr<ShapeSearch> best;
  int violations = earlier.Audit.violations();
  auto keepIfFewer = [&](std::unique_ptr<ShapeSearch> search) {
    if (search && search->violations() < violations)
    {
      violations = search->violations();
      best = std::move(search);
    }
  };
  int previousStart = std::numeric_limits<int>::max();
  for (const int level : commonLevels(ladder.TopLevel))
  {
    if (violations == 0)
    {
      break;
    }
    std::unique_ptr<ShapeSearch> search = started(ladder, level);
    if (!search)
    {
      continue;
    }
    // Past the level that failed least, a level up pushes more spans beyond
    // the bounds (and back to level 0): a start that fails more than the one
    // below and than the best met ends the climb. (The quintic on 600 noisy
    // helices: on the 49 lines retried, levels 12 and 16 failed 6-29 times
    // where 8 failed 0-7; skipping 16 saved 3% of the default mode's work.)
    if (search->violations() > previousStart && search->violations() > violations)
    {
      break;
    }
    previousStart = search->violations();
    const std::vector<int> failures = failuresPerWindow(search->audit());
    for (int j = 0; j < spans; ++j)
    {
      if (window[j] >= 0 && failures[window[j]] < fewest[window[j]])
      {
        assembled[j] = search->levels()[j];
      }
    }
    for (int w = 0; w < windows; ++w)
    {
      fewest[w] = std::min(fewest[w], failures[w]);
    }
    keepIfFewer(std::move(search));
  }
  // Each window at the level it failed least at: on a long line no single
  // level beats the first search everywhere. Searched from for a few rounds
  // only (a 1e5-point noisy helix left 4808 violations after 2 rounds, 4791
  // after 8 and 4785 after 64, which cost 50% more time than 8).
  if (windows > 1 && violations > 0 && assembled != earlier.Levels)
  {
    keepIfFewer(started(shortSearch, assembled));
  }
  if (!best)
  {
    return std::nullopt;
  }
  try
  {
    return best->search();
  }
  catch (const SingularSystem&)
  {
    return std::nullopt;
  }
}
} // namespace

AutomaticShape searchShape(
  const FitContext& context, const CleanPolyline& reference, const ShapeLadder& ladder)
{
  AutomaticShape found;
  try
  {
    found = ShapeSearch(context, reference, ladder, ladder.RaiseTwistNeighbours).run();
  }
  catch (const SingularSystem&)
  {
    // Levels the raises never built (lowered around a span beyond the
    // bounds) can be singular too: the fixed parameters' curve then.
    found.Levels.assign(reference.numberOfSpans(), 0);
    found.Spline = ladder.Build(found.Levels);
    found.Audit = context.audit(*found.Spline, reference, ladder.ReferenceNoise);
  }
  return found;
}

AutomaticShape improveShape(AutomaticShape found, const FitContext& context,
  const CleanPolyline& reference, const ShapeLadder& ladder)
{
  if (ladder.RetrySpanBySpan && found.Audit.violations() > 0)
  {
    try
    {
      ShapeSearch retry(context, reference, ladder, false);
      retry.keepOutside(found, RetryReach);
      AutomaticShape again = retry.run();
      if (again.Audit.violations() < found.Audit.violations())
      {
        found = std::move(again);
      }
    }
    catch (const SingularSystem&)
    {
      // Singular levels (as in searchShape): the first search's curve stays.
    }
  }
  if (ladder.RetryFromCommonLevel && found.Audit.violations() > 0)
  {
    std::optional<AutomaticShape> again =
      searchFromCommonLevel(context, reference, ladder, found);
    if (again && again->Audit.violations() < found.Audit.violations())
    {
      found = std::move(*again);
    }
  }
  // Each trial builds the whole line: a long one is hardly refined.
  const long points = std::max(1L, static_cast<long>(reference.Points.size()));
  const int trials = static_cast<int>(std::min(
    RefineTrialsPerSpan * reference.numberOfSpans(), RefinePointBuilds / points));
  if (ladder.Refine && !ladder.Uniform && trials > 0 && found.Audit.violations() > 0)
  {
    try
    {
      std::optional<AutomaticShape> refined =
        ShapeSearch(context, reference, ladder, ladder.RaiseTwistNeighbours).refine(found, trials);
      if (refined)
      {
        found = std::move(*refined);
      }
    }
    catch (const SingularSystem&)
    {
      // Singular levels (as in searchShape): the searches' curve stays.
    }
  }
  return found;
}

AutomaticShape preserveShapeAutomatically(
  const FitContext& context, const CleanPolyline& reference, const ShapeLadder& ladder)
{
  return improveShape(searchShape(context, reference, ladder), context, reference, ladder);
}
} // namespace shapesplines
