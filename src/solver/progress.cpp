#include "animpak/progress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace animpak {
namespace {

// The model's constants (docs/cli.md, "Progress and the time left"), each read off the recorded traces of
// the examples (tests/solver/traces):
// - the share of the container the meshes fill when growth stops: 0.58 (default example), 0.67 (clip art);
constexpr double kDensityAtStop = 0.62;
// - while this share of the slices or more still grow, growth is free and the fits see no end yet;
constexpr double kFreeGrowingShare = 0.8;
// - the settling after growth stops, as a share of the steps before: 4.7 % and 2.5 %;
constexpr double kSettleShare = 0.04;
// - a stall window's rise, relative to the one before, never taken closer to 1 than this (a rise that
//   decays no faster would never stall); 0.5 when the windows do not tell.
constexpr double kMaxWindowDecay = 0.95, kDefaultWindowDecay = 0.5;
// - the steps of the largest gap's fit: two stall windows of the default 1,000 steps, whatever the scene's
//   window (with windows of 400, a line over 800 steps ended the boosted default trace at 0.37 of its
//   real end);
constexpr std::uint64_t kGapFitSteps = 2000;
// - the largest gap the fit of the gap test takes: above it, the largest gap is a lone element's distance
//   to the wall before any neighbour is within the repulsion's reach, which drops at once when one comes
//   (the default example's from 0.39 to 0.09 within 100 steps with the room's boost); with those
//   samples the line put the end at 0.37 of the real one.
constexpr double kMeasuredGap = 0.3;

struct Line {
  double a = 0, b = 0;
};

std::optional<Line> fit_line(const std::vector<double>& xs, const std::vector<double>& ys) {
  const std::size_t n = xs.size();
  if (n < 4) return std::nullopt;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += xs[i], my += ys[i];
  mx /= double(n), my /= double(n);
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) sxx += (xs[i] - mx) * (xs[i] - mx), sxy += (xs[i] - mx) * (ys[i] - my);
  if (!(sxx > 0)) return std::nullopt;
  const Line l{my - sxy / sxx * mx, sxy / sxx};
  if (!std::isfinite(l.a) || !std::isfinite(l.b)) return std::nullopt;
  return l;
}

// The first sample at most `steps` steps before the last.
std::size_t samples_back(const std::vector<ProgressSample>& s, std::uint64_t steps) {
  std::size_t k = s.size() - 1;
  while (k > 0 && s.back().iteration - s[k - 1].iteration <= steps) --k;
  return k;
}

}  // namespace

void StopModel::observe(const ProgressSample& sample) { samples_.push_back(sample); }

std::optional<StopEstimate> StopModel::estimate() const {
  if (samples_.size() < 8 || stop_.stall_window <= 0) return std::nullopt;
  const ProgressSample& last = samples_.back();
  const auto window = static_cast<std::uint64_t>(stop_.stall_window);
  const double now = double(last.iteration);
  // Replay the stall test over the samples seen (run_simulation's: stall_tests marks per window, each
  // test against the mark a window back), keeping the marks a whole window apart for the model below.
  const std::size_t tests = static_cast<std::size_t>(std::clamp(stop_.stall_tests, 1, 4));
  const std::uint64_t spacing = std::max<std::uint64_t>(1, window / tests);
  std::vector<std::pair<std::uint64_t, double>> marks;
  std::vector<double> recent;  // the mean g at the marks since a window ago, oldest first
  std::uint64_t last_test = 0, secondary_since = 0;
  std::uint64_t contact_since = std::numeric_limits<std::uint64_t>::max();  // the first sample not free
  bool secondary_started = false;
  for (const ProgressSample& s : samples_) {
    if (s.growing_share < kFreeGrowingShare) contact_since = std::min(contact_since, s.iteration);
    if (s.iteration < last_test + spacing) continue;
    const bool stalled = recent.size() == tests && !(s.mean_growth > recent.front() * (1.0 + stop_.stall_growth));
    if (stalled && has_secondary_ && !secondary_started) {
      secondary_started = true, secondary_since = s.iteration, marks.clear(), recent.clear();
    } else if (stalled) {
      return StopEstimate{last.iteration, 0.0, false};  // settling now
    }
    last_test = s.iteration;
    recent.push_back(s.mean_growth);
    if (recent.size() > tests) recent.erase(recent.begin());
    if (marks.empty() || s.iteration >= marks.back().first + window) marks.emplace_back(s.iteration, s.mean_growth);
  }
  const std::uint64_t mark = marks.empty() ? 0 : marks.back().first;
  const double mark_growth = marks.empty() ? 0.0 : marks.back().second;
  const bool secondary_pending = has_secondary_ && !secondary_started;
  const ProgressSample& p = samples_[samples_back(samples_, window / 2)];
  const double pace =
      last.iteration > p.iteration ? (last.seconds - p.seconds) / double(last.iteration - p.iteration) : 0.0;

  // Growth has stopped (the gap test or a stall fired between samples): settling remains.
  if (last.growing_share == 0.0 && !secondary_pending) {
    std::uint64_t since = last.iteration;
    for (std::size_t k = samples_.size(); k-- > 0 && samples_[k].growing_share == 0.0;) since = samples_[k].iteration;
    const double end = std::min(double(since) * (1.0 + kSettleShare), double(since) + double(stop_.settle_iterations));
    const double stop = std::max(now, end);
    return StopEstimate{static_cast<std::uint64_t>(stop), pace * (stop - now), false};
  }

  // The mean g's rise per step now, over the last tenth of a window.
  const std::size_t tenth = samples_back(samples_, window / 10);
  const ProgressSample& r = samples_[tenth > 0 ? tenth - 1 : 0];
  const double rate = now > double(r.iteration) ? (last.mean_growth - r.mean_growth) / (now - double(r.iteration)) : 0;
  double stop = -1, growth_at_stop = last.mean_growth;
  const double into = now - double(mark);
  if (secondary_started && marks.size() < 2 && into < 0.3 * double(window)) {
    // The secondary elements have just started: until their first window tells, their growth is taken to
    // last half as long as the primary elements' did (0.68 in the annulus example's trace).
    stop = double(secondary_since) * 1.5;
  } else if (!secondary_started && (last.growing_share >= kFreeGrowingShare || marks.size() < 2)) {
    // Free growth: the meshes grow until they fill the container to about kDensityAtStop, the rate
    // falling to nothing on the way (linearly in the steps: twice the steps at today's rate). A rate
    // above base_rate is the room's boost, which ends as the elements near each other: the rest is taken
    // at base_rate.
    const double final_growth = unit_density_ > 0 ? std::sqrt(kDensityAtStop / unit_density_) : 0.0;
    const double expected = base_rate_ > 0 && rate > base_rate_ ? base_rate_ : rate;
    if (expected > 0 && final_growth > last.mean_growth) {
      stop = now + 2.0 * (final_growth - last.mean_growth) / expected;
      growth_at_stop = final_growth;
    }
  }
  if (stop < 0 && (marks.size() >= 2 || secondary_started)) {
    // Contact: each stall window's rise of ln g is the last one's times a decay q, stepped forward until
    // one rises by less than stall_growth. The current window counts once it is a third done. q comes
    // from the last two windows once the elements are in contact: a window of free growth rises at the
    // growth rate, not at a rate that decays (with windows of 400 steps, the default example's 0.13.0
    // trace put the end at 1.6 of the real one from the last free windows' ratio).
    std::vector<double> rises;
    std::size_t contact_rises = 0;
    for (std::size_t i = 1; i < marks.size(); ++i) {
      rises.push_back(std::log(marks[i].second / marks[i - 1].second));
      contact_rises = marks[i - 1].first >= contact_since ? contact_rises + 1 : 0;
    }
    const bool current = into >= 0.3 * double(window);
    double q = contact_rises >= 2 && rises[rises.size() - 2] > 0 ? rises.back() / rises[rises.size() - 2] : 0;
    if (!(q > 0)) q = kDefaultWindowDecay;
    q = std::min(q, kMaxWindowDecay);
    double rise = current ? std::log(last.mean_growth / mark_growth) * double(window) / into
                          : (rises.empty() ? 0.0 : rises.back() * q);
    double ln_growth = std::log(mark_growth);
    const double threshold = std::log1p(stop_.stall_growth), limit = double(stop_.max_iterations);
    double at = double(mark) + double(window);
    for (; rise >= threshold && at < limit; at += double(window)) ln_growth += rise, rise *= q;
    stop = std::min(at, limit);
    growth_at_stop = std::exp(ln_growth);
  }
  if (stop < 0) return std::nullopt;
  // §5.3's gap test: the largest gap falls exponentially; where its line over the last kGapFitSteps reaches
  // stop_gap, growth stops if the stall test has not stopped it first. That long, because the largest gap
  // also falls in steps (a gap between two slices closing), which a shorter line takes for a trend: the
  // aquarium's trace gave 0.49 of its real end over 1,000 steps, 0.68 over 2,000. Samples whose largest
  // gap is kMeasuredGap or more are left out (see there).
  std::vector<double> gx, gy;
  for (std::size_t k = samples_back(samples_, kGapFitSteps); k < samples_.size(); ++k)
    if (std::isfinite(samples_[k].max_gap) && samples_[k].max_gap > 0.0 && samples_[k].max_gap < kMeasuredGap)
      gx.push_back(double(samples_[k].iteration)), gy.push_back(std::log(samples_[k].max_gap));
  if (const std::optional<Line> gap = fit_line(gx, gy); gap && gap->b < 0.0)
    stop = std::min(stop, std::max(now, (std::log(stop_.stop_gap) - gap->a) / gap->b));
  stop = std::max(stop, now) * (1.0 + kSettleShare);
  // Secondary elements grow once the primary ones stall: the whole run is taken as 1.35 times the primary
  // stop. The annulus example's trace needs between 1.25 and 1.49 to stay within ±50 % from a fifth of the
  // run on (its secondary phase was 0.68 of its primary one, but the primary stop is overestimated early).
  if (secondary_pending) stop *= 1.35;
  stop = std::min(double(stop_.max_iterations), stop);
  // A step costs more as the elements grow (more neighbours in the collision grid): the pace is scaled by
  // g, its mean over the steps left taken as the mean of now and the stop.
  const double seconds_left = pace * (stop - now) * 0.5 * (1.0 + std::max(1.0, growth_at_stop / last.mean_growth));
  return StopEstimate{static_cast<std::uint64_t>(stop), seconds_left, secondary_pending};
}

}  // namespace animpak
