#include "cordgrasp/sim/hold_probability.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <optional>
#include <stdexcept>

#include "cordgrasp/core/enum_names.h"
#include "cordgrasp/core/parallel_for.h"

namespace cordgrasp {
namespace {

constexpr EnumName<HoldVerdict> kVerdictNames[] = {
    {HoldVerdict::kUndecided, "undecided"},
    {HoldVerdict::kAbove, "above"},
    {HoldVerdict::kBelow, "below"},
};

/// CPU time of the calling thread [s].
double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// The spread or σ behind each factor (0: the factor does not vary).
double factor_spread(UncertaintyFactor f, const UncertaintyParams& u) {
  switch (f) {
    case UncertaintyFactor::kHandOffset:
      return u.hand_offset_sigma_m;
    case UncertaintyFactor::kHandTurn:
      return u.hand_turn_sigma_rad;
    case UncertaintyFactor::kFriction:
      return u.mu_relative_spread;
    case UncertaintyFactor::kMass:
      return u.mass_relative_spread;
    case UncertaintyFactor::kComOffset:
      return u.com_offset_sigma_m;
    case UncertaintyFactor::kSqueeze:
      return u.squeeze_relative_spread;
  }
  return 0.0;
}

}  // namespace

const char* to_string(HoldVerdict verdict) { return enum_to_string(verdict, kVerdictNames); }

void check_hold_probability_params(const HoldProbabilityParams& p) {
  if (!(p.min_hold_probability > 0.0 && p.min_hold_probability < 1.0))
    throw std::invalid_argument("min_hold_probability: " + std::to_string(p.min_hold_probability) +
                                " is not in (0, 1)");
  if (p.max_draws < 1 || p.max_draws > 1000)
    throw std::invalid_argument("max_draws: " + std::to_string(p.max_draws) +
                                " is not in [1, 1000]");
  if (p.min_draws < 1 || p.min_draws > p.max_draws)
    throw std::invalid_argument("min_draws: " + std::to_string(p.min_draws) +
                                " is not in [1, max_draws " + std::to_string(p.max_draws) + "]");
}

void check_hold_test(const UncertaintyParams& uncertainty, const HoldProbabilityParams& params) {
  check_uncertainty_params(uncertainty);
  check_hold_probability_params(params);
}

HoldProbabilityParams hold_test_params(double min_hold_probability, int max_draws,
                                       std::uint64_t seed) {
  HoldProbabilityParams out;
  out.min_hold_probability = min_hold_probability;
  out.max_draws = max_draws;
  out.min_draws = std::min(out.min_draws, max_draws);
  out.seed = seed;
  return out;
}

HoldProbabilityParams confirmation_test(const HoldProbabilityParams& test) {
  // Any fixed odd multiplier and offset give draws unrelated to the first test's.
  constexpr std::uint64_t kConfirmationSeedMultiplier = 0x9E3779B97F4A7C15ULL;
  HoldProbabilityParams out = test;
  out.seed = test.seed * kConfirmationSeedMultiplier + 1;
  return out;
}

HoldVerdict hold_verdict(const ProportionInterval& interval, double threshold) {
  if (interval.low > threshold) return HoldVerdict::kAbove;
  if (interval.high < threshold) return HoldVerdict::kBelow;
  return HoldVerdict::kUndecided;
}

bool stop_drawing(int held, int draws, const HoldProbabilityParams& params) {
  if (draws >= params.max_draws) return true;
  const double threshold = params.min_hold_probability;
  const HoldVerdict now = hold_verdict(wilson_interval(held, draws), threshold);
  if (now == HoldVerdict::kUndecided) return false;
  if (draws >= params.min_draws) return true;
  // Before the minimum: stop when the draws left to it cannot change the verdict there (all
  // of them held, or none), so the test ends as it would at the minimum, sooner.
  const int left = params.min_draws - draws;
  return hold_verdict(wilson_interval(held + left, params.min_draws), threshold) == now &&
         hold_verdict(wilson_interval(held, params.min_draws), threshold) == now;
}

FailureSensitivity failure_sensitivity(const std::vector<UncertainDrawResult>& draws,
                                       const UncertaintyParams& uncertainty) {
  FailureSensitivity out;
  int failed = 0;
  for (const UncertainDrawResult& d : draws) failed += d.outcome != Outcome::kHeld;
  const int n = static_cast<int>(draws.size());
  if (failed == 0 || failed == n) return out;
  double best = -1.0;
  for (int i = 0; i < kUncertaintyFactors; ++i) {
    const auto factor = static_cast<UncertaintyFactor>(i);
    if (factor_spread(factor, uncertainty) == 0.0) continue;
    double sum_failed = 0.0, sum_held = 0.0, sum = 0.0, sum_sq = 0.0;
    for (const UncertainDrawResult& d : draws) {
      const double z = d.draw.scores[static_cast<size_t>(i)];
      (d.outcome == Outcome::kHeld ? sum_held : sum_failed) += z;
      sum += z;
      sum_sq += z * z;
    }
    FactorSensitivity s;
    s.factor = factor;
    s.mean_failed = sum_failed / failed;
    s.mean_held = sum_held / (n - failed);
    const double mean = sum / n;
    const double sd = std::sqrt(std::max(0.0, sum_sq / n - mean * mean));
    s.effect = sd > 0.0 ? (s.mean_failed - s.mean_held) / sd : 0.0;
    if (std::abs(s.effect) > best) {
      best = std::abs(s.effect);
      out.most_associated = factor;
    }
    out.factors.push_back(s);
  }
  return out;
}

HoldProbability estimate_hold_probability(const Mesh& mesh, const HandModel& hand,
                                          const Grasp& grasp, int grasp_index, const SimParams& sim,
                                          const SimTests& tests,
                                          const UncertaintyParams& uncertainty,
                                          const HoldProbabilityParams& params,
                                          const CancelToken& cancel, int jobs,
                                          DrawnPoseCloser* closer) {
  check_hold_test(uncertainty, params);
  const auto start = std::chrono::steady_clock::now();
  HoldProbability out;
  out.threshold = params.min_hold_probability;
  std::optional<DrawnPoseCloser> own_closer;
  if (!moves_hand(uncertainty))
    closer = nullptr;
  else if (!closer)
    closer = &own_closer.emplace(hand, mesh);
  const auto simulate = [&](int t) {
    const double cpu_start = thread_cpu_s();
    UncertainDrawResult d;
    d.trial = t;
    d.draw = draw_uncertainty(uncertainty, params.seed, grasp_index, t);
    UncertainTrial trial = apply_uncertainty(grasp, sim, d.draw);
    if (closer) trial.grasp = closer->close(trial.grasp);
    const SimResult r = validate_grasp(mesh, hand, trial.grasp, trial.params, tests);
    d.outcome = r.outcome;
    if (const PhaseResult* failed = r.held() ? nullptr : r.failed_phase())
      d.failed_phase = failed->name;
    d.wall_time_s = r.wall_time_s;
    d.cpu_s = thread_cpu_s() - cpu_start;
    return d;
  };
  const auto drawn = [&] { return static_cast<int>(out.draws.size()); };
  while (!stop_drawing(out.held, drawn(), params)) {
    if (cancel.cancelled()) {
      out.complete = false;
      break;
    }
    // `jobs` draws at once; the test reads them in order and stops where one at a time would.
    const int from = drawn();
    const int batch = std::min(std::max(1, jobs), params.max_draws - from);
    std::vector<UncertainDrawResult> more(static_cast<size_t>(batch));
    parallel_for(batch, jobs, [&](int i) { more[static_cast<size_t>(i)] = simulate(from + i); });
    out.simulations += batch;
    for (const UncertainDrawResult& d : more) out.cpu_s += d.cpu_s;
    for (UncertainDrawResult& d : more) {
      if (stop_drawing(out.held, drawn(), params)) break;
      out.held += d.outcome == Outcome::kHeld;
      out.draws.push_back(std::move(d));
    }
  }
  out.interval = wilson_interval(out.held, static_cast<int>(out.draws.size()));
  out.verdict = hold_verdict(out.interval, out.threshold);
  out.sensitivity = failure_sensitivity(out.draws, uncertainty);
  out.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string hold_probability_text(const HoldProbability& h) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.2f [%.2f, %.2f]", h.interval.p, h.interval.low,
                h.interval.high);
  return text;
}

std::string hold_probability_line(const HoldProbability& h) {
  char text[96];
  std::snprintf(text, sizeof(text), " in %d draws, %s %.2f", static_cast<int>(h.draws.size()),
                to_string(h.verdict), h.threshold);
  std::string line = "P(held) " + hold_probability_text(h) + text;
  if (h.sensitivity.most_associated)
    for (const FactorSensitivity& f : h.sensitivity.factors)
      if (f.factor == *h.sensitivity.most_associated)
        line += std::string("; failures go with ") + (f.effect < 0.0 ? "low " : "high ") +
                to_string(f.factor);
  return line;
}

}  // namespace cordgrasp
