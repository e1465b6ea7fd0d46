// The estimators of src/ensemble/ensemble_statistics against hand-computed values, and the
// Wilson interval's coverage over many synthetic ensembles of Bernoulli members.
#include "ensemble/ensemble_statistics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ensemble/member_case.hpp"

namespace flotsam {
namespace {

// Wilson (1927) intervals at 95%, as tabulated e.g. by Brown, Cai & DasGupta (2001) and by
// hand: 0/10 -> [0, 0.2775], 5/10 -> [0.2366, 0.7634], 10/10 -> [0.7225, 1], 7/20 ->
// [0.1812, 0.5671].
TEST(WilsonInterval, MatchesTabulatedValues) {
  const double tol = 5e-5;
  const Proportion none = wilson_interval(0, 10);
  EXPECT_EQ(none.p, 0.0);
  EXPECT_NEAR(none.lower, 0.0, 1e-15);
  EXPECT_NEAR(none.upper, 0.2775, tol);
  const Proportion half = wilson_interval(5, 10);
  EXPECT_NEAR(half.lower, 0.2366, tol);
  EXPECT_NEAR(half.upper, 0.7634, tol);
  const Proportion all = wilson_interval(10, 10);
  EXPECT_NEAR(all.lower, 0.7225, tol);
  EXPECT_NEAR(all.upper, 1.0, 1e-15);
  const Proportion some = wilson_interval(7, 20);
  EXPECT_NEAR(some.p, 0.35, 1e-15);
  EXPECT_NEAR(some.lower, 0.1812, tol);
  EXPECT_NEAR(some.upper, 0.5671, tol);
}

TEST(WilsonInterval, NoTrialsGivesTheWholeRange) {
  const Proportion r = wilson_interval(0, 0);
  EXPECT_TRUE(std::isnan(r.p));
  EXPECT_EQ(r.lower, 0.0);
  EXPECT_EQ(r.upper, 1.0);
}

TEST(Summarize, OrderStatisticsByHand) {
  // {1, 2, 3, 4} (NaN left out): mean 2.5, median 2.5, p90 = x1 + 0.7 (x4 - x3) at h = 2.7.
  const SampleSummary s = summarize({4.0, std::nan(""), 1.0, 3.0, 2.0});
  EXPECT_EQ(s.count, 4);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_NEAR(s.p90, 3.7, 1e-14);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_EQ(summarize({}).count, 0);
}

TEST(Histogram, CountsPerBinLastBinClosed) {
  const std::vector<int> counts = histogram({0.0, 0.5, 0.99, 1.0, 2.0, 3.0, -1.0}, 0.0, 2.0, 2);
  ASSERT_EQ(counts.size(), 2u);
  EXPECT_EQ(counts[0], 3);  // 0, 0.5, 0.99
  EXPECT_EQ(counts[1], 2);  // 1, 2 (the upper end belongs to the last bin); 3 and -1 outside
}

/// The exact coverage of the 95% Wilson interval for n trials at p: the probability, over k ~
/// Binomial(n, p), that the interval of k/n holds p.
double exact_coverage(int n, double p) {
  double coverage = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double log_pmf = std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) +
                           k * std::log(p) + (n - k) * std::log1p(-p);
    const Proportion r = wilson_interval(k, n);
    if (r.lower <= p && p <= r.upper) coverage += std::exp(log_pmf);
  }
  return coverage;
}

// Synthetic ensembles: n members, each blocking with probability p (a Bernoulli draw from the
// members' keyed streams). Over R ensembles the share whose interval holds p must be the exact
// coverage within 4 binomial standard deviations, and that coverage near the nominal 95%.
// Members trapping 0, 1, 3, 4 and 2 bodies and one failed member: at least one trapped in 4 of
// the 5 that ran, at least three in 2; the intervals are Wilson's of those counts.
TEST(EnsembleStatistics, MembersWithBodiesTrappedByHand) {
  EnsembleConfig config;
  config.members = 6;
  std::vector<MemberResult> results;
  for (const int trapped : {0, 1, 3, -1, 4, 2}) {
    MemberResult r;
    r.inputs.member = static_cast<int>(results.size());
    r.failed = trapped < 0;
    r.trapped = std::max(trapped, 0);
    results.push_back(r);
  }
  const EnsembleStatistics e = compute_ensemble_statistics(results, config, JamGeometry{});
  ASSERT_EQ(e.sweep.size(), 1u);
  const SweepStatistics& s = e.sweep.front();
  EXPECT_EQ(s.members, 5);
  EXPECT_EQ(s.failed, 1);
  EXPECT_EQ(s.trapped_any.successes, 4);
  EXPECT_EQ(s.trapped_any.trials, 5);
  EXPECT_EQ(s.trapped_several.successes, 2);
  EXPECT_EQ(s.trapped_several.trials, 5);
  const Proportion any = wilson_interval(4, 5), several = wilson_interval(2, 5);
  EXPECT_EQ(s.trapped_any.lower, any.lower);
  EXPECT_EQ(s.trapped_several.upper, several.upper);
  EXPECT_DOUBLE_EQ(s.trapped, 2.0);  // (0 + 1 + 3 + 4 + 2) / 5
  const std::string summary = format_ensemble_summary(e, config, "by_hand");
  // Wilson at 4/5: centre (0.8 + z^2/10) / (1 + z^2/5) = 0.6697, half 0.2941 (by hand).
  EXPECT_NE(summary.find("  >= 1 trapped               4/5    p 0.800  95% [0.376, 0.964]\n"),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("  >= 3 trapped               2/5    p 0.400  95% [0.118, 0.769]\n"),
            std::string::npos)
      << summary;
}

TEST(WilsonInterval, CoverageOfBernoulliMembersOverManySeeds) {
  const int n = 40, replications = 4000;
  for (const double p : {0.1, 0.3, 0.5}) {
    int covered = 0;
    for (int seed = 0; seed < replications; ++seed) {
      int blocked = 0;
      for (int member = 0; member < n; ++member) {
        KeyedStream stream{static_cast<std::uint64_t>(seed), static_cast<std::uint64_t>(member)};
        blocked += stream.uniform() < p;
      }
      const Proportion r = wilson_interval(blocked, n);
      covered += r.lower <= p && p <= r.upper;
    }
    const double expected = exact_coverage(n, p);
    const double rate = static_cast<double>(covered) / replications;
    const double sd = std::sqrt(expected * (1 - expected) / replications);
    EXPECT_NEAR(rate, expected, 4 * sd) << "p = " << p;
    EXPECT_NEAR(expected, 0.95, 0.025) << "p = " << p;
  }
}

}  // namespace
}  // namespace flotsam
