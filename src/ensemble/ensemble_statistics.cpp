#include "ensemble/ensemble_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/csv_writer.hpp"

namespace flotsam {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
}

Proportion wilson_interval(int successes, int trials, double z) {
  Proportion r;
  r.successes = successes;
  r.trials = trials;
  if (trials <= 0) {
    r.p = nan;
    return r;
  }
  const double n = trials, p = successes / n, z2 = z * z;
  const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
  const double half = z / (1 + z2 / n) * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n));
  r.p = p;
  r.lower = std::max(0.0, centre - half);
  r.upper = std::min(1.0, centre + half);
  return r;
}

SampleSummary summarize(std::vector<double> values) {
  std::erase_if(values, [](double v) { return std::isnan(v); });
  SampleSummary s;
  s.count = static_cast<int>(values.size());
  if (values.empty()) {
    s.mean = s.min = s.median = s.p90 = s.max = nan;
    return s;
  }
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double v : values) sum += v;  // in ascending order: the same sum whoever ran what
  s.mean = sum / static_cast<double>(values.size());
  auto quantile = [&](double q) {  // type 7: x[floor(h)] + (h - floor(h)) (x[floor(h)+1] - ...)
    const double h = q * static_cast<double>(values.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (h - static_cast<double>(lo)) * (values[hi] - values[lo]);
  };
  s.min = values.front();
  s.max = values.back();
  s.median = quantile(0.5);
  s.p90 = quantile(0.9);
  return s;
}

std::vector<int> histogram(const std::vector<double>& values, double lower, double upper,
                           int bins) {
  std::vector<int> counts(static_cast<std::size_t>(bins), 0);
  const double width = (upper - lower) / bins;
  for (double v : values) {
    if (std::isnan(v) || v < lower || v > upper) continue;
    const int k = width > 0 ? std::min(bins - 1, static_cast<int>((v - lower) / width)) : 0;
    ++counts[static_cast<std::size_t>(k)];
  }
  return counts;
}

EnsembleStatistics compute_ensemble_statistics(const std::vector<MemberResult>& results,
                                               const EnsembleConfig& config,
                                               const JamGeometry& geometry) {
  EnsembleStatistics e;
  e.sweep.resize(static_cast<std::size_t>(config.sweep_value_count()));
  for (std::size_t s = 0; s < e.sweep.size(); ++s) {
    SweepStatistics& sweep = e.sweep[s];
    sweep.value = config.has_sweep ? config.sweep_values[s] : 0.0;
    std::vector<int> bridge_blocked(geometry.bridges.size(), 0);
    std::vector<std::vector<int>> gap_blocked;
    for (const Bridge& line : geometry.bridges) gap_blocked.emplace_back(line.gaps.size(), 0);
    std::vector<double> jam_size, rise, travel;
    int any_trapped = 0, several = 0;  // members with >= 1, >= several_trapped bodies trapped
    for (const MemberResult& r : results) {
      if (r.inputs.sweep_index != static_cast<int>(s)) continue;
      if (r.failed) {
        ++sweep.failed;
        e.failures.push_back(&r);
        continue;
      }
      ++sweep.members;
      int largest = 0;
      double largest_rise = nan;
      for (std::size_t b = 0; b < r.bridges.size() && b < geometry.bridges.size(); ++b) {
        bridge_blocked[b] += r.bridges[b].blocked;
        largest = std::max(largest, r.bridges[b].largest_jam);
        if (!std::isnan(r.bridges[b].max_rise))
          largest_rise = std::isnan(largest_rise) ? r.bridges[b].max_rise
                                                  : std::max(largest_rise, r.bridges[b].max_rise);
        for (std::size_t g = 0; g < gap_blocked[b].size() && b < r.gaps.size(); ++g)
          gap_blocked[b][g] += r.gaps[b][g].blocked;
      }
      jam_size.push_back(largest);
      rise.push_back(largest_rise);
      for (const BodyOutcome& body : r.bodies) travel.push_back(body.travel());
      sweep.released += r.released;
      sweep.passed += r.passed;
      sweep.left += r.left;
      sweep.trapped += r.trapped;
      any_trapped += r.trapped >= 1;
      several += r.trapped >= several_trapped;
      sweep.stranded += r.stranded;
      sweep.floating += r.floating;
    }
    for (std::size_t b = 0; b < geometry.bridges.size(); ++b) {
      const std::string& name = geometry.bridges[b].name;
      sweep.blocking.push_back(
          {name, static_cast<int>(b), -1, wilson_interval(bridge_blocked[b], sweep.members)});
      for (std::size_t g = 0; g < gap_blocked[b].size(); ++g)
        sweep.blocking.push_back({fmt::format("{} gap {}", name, g + 1), static_cast<int>(b),
                                  static_cast<int>(g),
                                  wilson_interval(gap_blocked[b][g], sweep.members)});
    }
    sweep.trapped_any = wilson_interval(any_trapped, sweep.members);
    sweep.trapped_several = wilson_interval(several, sweep.members);
    sweep.jam_size = summarize(jam_size);
    sweep.backwater_rise = summarize(rise);
    sweep.travel = summarize(travel);
    const double n = std::max(1, sweep.members);
    for (double* mean : {&sweep.released, &sweep.passed, &sweep.left, &sweep.trapped,
                         &sweep.stranded, &sweep.floating})
      *mean /= n;
  }
  return e;
}

namespace {

std::string describe_inputs(const MemberInputs& inputs) {
  std::string s;
  for (const auto& [input, v] : inputs.values)
    s += fmt::format("{}{} = {} {}", s.empty() ? "" : ", ", input_key(input), v, input_unit(input));
  for (std::size_t k = 0; k < inputs.release_seeds.size(); ++k)
    s += fmt::format("{}release[{}] seed {}", s.empty() ? "" : ", ", k, inputs.release_seeds[k]);
  return s;
}

std::string format_sample(const char* what, const SampleSummary& s, const char* unit) {
  if (s.count == 0) return fmt::format("  {:<16}none\n", what);
  return fmt::format(
      "  {:<16}mean {:.4g}  min {:.4g}  median {:.4g}  p90 {:.4g}  max {:.4g} {}"
      "  ({} values)\n",
      what, s.mean, s.min, s.median, s.p90, s.max, unit, s.count);
}

/// One line of a proportion and its interval; with no member to count, no estimate.
std::string format_proportion(const std::string& what, const Proportion& p) {
  if (p.trials <= 0) return fmt::format("  {:<24}{:>4}/{:<4} no member completed\n", what, 0, 0);
  return fmt::format("  {:<24}{:>4}/{:<4} p {:.3f}  95% [{:.3f}, {:.3f}]\n", what, p.successes,
                     p.trials, p.p, p.lower, p.upper);
}

}  // namespace

std::string format_ensemble_summary(const EnsembleStatistics& statistics,
                                    const EnsembleConfig& config, const std::string& case_name) {
  std::string s;
  int failed = 0;
  for (const SweepStatistics& sweep : statistics.sweep) failed += sweep.failed;
  s += fmt::format("ensemble         {}: {} members ({} per value x {} values), {} failed\n",
                   case_name, config.total_members(), config.members, config.sweep_value_count(),
                   failed);
  s += fmt::format(
      "blocking         a gap blocks when jams at its bridge cover >= {:g} of its width for "
      ">= {:g} s (sampled every {:g} s)\n",
      config.blocking.fraction, config.blocking.duration, config.blocking.sample_interval);
  for (const SweepStatistics& sweep : statistics.sweep) {
    if (config.has_sweep)
      s += fmt::format("{} = {:g} {}: {} members, {} failed\n", input_key(config.sweep_input),
                       sweep.value, input_unit(config.sweep_input), sweep.members, sweep.failed);
    else
      s += fmt::format("all members: {} ran, {} failed\n", sweep.members, sweep.failed);
    for (const BlockingEstimate& b : sweep.blocking)
      s += format_proportion("blocked " + b.target, b.blocked);
    s += format_proportion(">= 1 trapped", sweep.trapped_any);
    s += format_proportion(fmt::format(">= {} trapped", several_trapped), sweep.trapped_several);
    s += format_sample("jam size", sweep.jam_size, "bodies");
    s += format_sample("backwater rise", sweep.backwater_rise, "m");
    s += format_sample("travel", sweep.travel, "m");
    s += fmt::format(
        "  per member      released {:.2f}  passed {:.2f}  left {:.2f}  trapped {:.2f}  "
        "stranded {:.2f}  floating {:.2f}\n",
        sweep.released, sweep.passed, sweep.left, sweep.trapped, sweep.stranded, sweep.floating);
  }
  if (!statistics.failures.empty()) s += "failed members\n";
  for (const MemberResult* r : statistics.failures)
    s += fmt::format("  {} ({}): {}\n", member_name(r->inputs.member), describe_inputs(r->inputs),
                     r->message);
  return s;
}

void write_ensemble_tables(const std::string& directory, const std::vector<MemberResult>& results,
                           const EnsembleStatistics& statistics, const EnsembleConfig& config,
                           const JamGeometry& geometry) {
  // ensemble_members.csv: one row per member.
  std::vector<EnsembleInput> inputs;
  for (int k = 0; k < static_cast<int>(EnsembleInput::count); ++k) {
    const auto input = static_cast<EnsembleInput>(k);
    bool used = config.has_sweep && config.sweep_input == input;
    for (const VariedInput& v : config.vary) used = used || v.input == input;
    if (used) inputs.push_back(input);
  }
  std::vector<std::string> columns = {"member", "sweep index", "draw"};
  for (EnsembleInput input : inputs)
    columns.push_back(fmt::format("{} [{}]", input_key(input), input_unit(input)));
  for (const char* c : {"failed", "released", "passed", "left", "trapped", "stranded", "floating"})
    columns.emplace_back(c);
  for (const Bridge& line : geometry.bridges) {
    for (const char* c :
         {"blocked {}", "blocking time {} [s]", "blocking bodies {}", "largest jam {}",
          "max blockage {} [-]", "max backwater rise {} [m]", "max opening closed {} [-]"})
      columns.push_back(fmt::format(fmt::runtime(c), line.name));
    for (std::size_t g = 0; g < line.gaps.size(); ++g)
      for (const char* c : {"blocked {} gap {}", "blocking time {} gap {} [s]",
                            "max cover {} gap {} [-]", "max opening closed {} gap {} [-]"})
        columns.push_back(fmt::format(fmt::runtime(c), line.name, g + 1));
  }
  CsvWriter members(directory + "/ensemble_members.csv", columns);
  for (const MemberResult& r : results) {
    std::vector<double> row = {double(r.inputs.member), double(r.inputs.sweep_index),
                               double(r.inputs.draw)};
    for (EnsembleInput input : inputs) row.push_back(r.inputs.value(input));
    row.push_back(r.failed ? 1 : 0);
    for (int c : {r.released, r.passed, r.left, r.trapped, r.stranded, r.floating})
      row.push_back(r.failed ? nan : c);
    for (std::size_t b = 0; b < geometry.bridges.size(); ++b) {
      const bool ok = !r.failed && b < r.bridges.size();
      const BridgeOutcome o = ok ? r.bridges[b] : BridgeOutcome{};
      for (double v : {double(o.blocked), o.blocking_time, double(o.blocking_bodies),
                       double(o.largest_jam), o.max_blockage, o.max_rise, o.max_opening_closed})
        row.push_back(ok ? v : nan);
      for (std::size_t g = 0; g < geometry.bridges[b].gaps.size(); ++g) {
        const bool gap_ok = ok && b < r.gaps.size() && g < r.gaps[b].size();
        const GapOutcome go = gap_ok ? r.gaps[b][g] : GapOutcome{};
        for (double v : {double(go.blocked), go.blocking_time, go.max_cover, go.max_opening_closed})
          row.push_back(gap_ok ? v : nan);
      }
    }
    members.row(row);
  }
  // ensemble_blocking.csv: one row per sweep value and bridge or gap.
  CsvWriter blocking(directory + "/ensemble_blocking.csv",
                     {"sweep value", "bridge", "gap (0: the bridge)", "members", "blocked",
                      "probability [-]", "lower 95% [-]", "upper 95% [-]"});
  for (const SweepStatistics& sweep : statistics.sweep)
    for (const BlockingEstimate& b : sweep.blocking)
      blocking.row({sweep.value, double(b.bridge + 1), double(b.gap + 1), double(b.blocked.trials),
                    double(b.blocked.successes), b.blocked.p, b.blocked.lower, b.blocked.upper});
  // ensemble_bodies.csv: every body of every member that ran.
  CsvWriter bodies(directory + "/ensemble_bodies.csv",
                   {"member", "id", "x start [m]", "y start [m]", "x end [m]", "y end [m]",
                    "travel [m]", "fate (0 floating 1 trapped 2 stranded 3 left)", "passed"});
  for (const MemberResult& r : results)
    for (const BodyOutcome& b : r.bodies)
      bodies.row({double(r.inputs.member), double(b.id), b.start.x(), b.start.y(), b.end.x(),
                  b.end.y(), b.travel(), double(static_cast<int>(b.fate)), b.passed ? 1.0 : 0.0});
}

}  // namespace flotsam
