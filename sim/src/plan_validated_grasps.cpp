#include "cordgrasp/sim/plan_validated_grasps.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/grasp_diversity.h"
#include "cordgrasp/core/grasp_perturbation.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/palm_width.h"
#include "cordgrasp/core/parallel_for.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/core/plan_generic_grasps.h"
#include "cordgrasp/sim/hold_probability.h"
#include "cordgrasp/sim/sim_result.h"
#include "cordgrasp/sim/validate_grasp.h"

namespace cordgrasp {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// CPU time of this process, all threads [s].
double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Adds the counts of one planner call to the running total (times add up too).
void add_stats(PlanStats& total, const PlanStats& s) {
  total.regions_processed += s.regions_processed;
  total.attempts += s.attempts;
  total.force_closure += s.force_closure;
  total.no_contact += s.no_contact;
  total.one_contact += s.one_contact;
  total.cannot_retreat += s.cannot_retreat;
  total.not_force_closure += s.not_force_closure;
  total.inside_object += s.inside_object;
  total.similar += s.similar;
  total.setup_s += s.setup_s;
  total.finger_s += s.finger_s;
  total.quality_s += s.quality_s;
}

BulletColliderParams collider_params(int threads) {
  BulletColliderParams p;
  p.threads = threads;
  return p;
}

/// Hands out the planner's force-closure candidates one at a time, best first: the cord planner
/// continues in its region order after the last candidate's region and, once every region is
/// processed, explores again with the next seed (region_rank is then the rank in that
/// exploration), and once the explorations are spent, the cord planner's sampled fallback
/// (plan_cord_fallback_grasps()), in batches of PlanParams::fallback_attempts until the time
/// left is spent, each batch with the next seed (as the generic planner's calls).
class CandidateSource {
 public:
  CandidateSource(const Mesh& mesh, const HandModel& hand, PlannerKind planner,
                  const PlanParams& plan, const std::optional<CordParams>& cord,
                  const CancelToken& cancel, int threads)
      : mesh_(mesh),
        hand_(hand),
        planner_(planner),
        plan_(plan),
        cord_(cord),
        cancel_(cancel),
        threads_(threads),
        collider_(make_bullet_hand_collider(hand, mesh, collider_params(threads))) {}

  /// The hold tests' re-closure at drawn hand poses, on the planner's collider (idle while a
  /// candidate is tested).
  DrawnPoseCloser& closer() {
    if (!closer_)
      closer_.emplace(hand_, *collider_,
                      context_ ? context_->setup : prepare_hand(hand_, *collider_));
    return *closer_;
  }

  /// The next candidate, or nullopt when the planner has none left within `time_left_s` (CPU,
  /// as validated planning counts its budget). The planners' own time limits are wall-clock:
  /// each call gets the CPU time left as its wall limit, and a call that runs out of wall time
  /// first (a busy machine) is followed by others while CPU time is left.
  std::optional<Grasp> next(double time_left_s, PlanStats& stats) {
    const double cpu_start = process_cpu_s();
    const auto cpu_left_s = [&] { return time_left_s - (process_cpu_s() - cpu_start); };
    if (!context_ && time_left_s > 0.0) {  // once for every candidate, of either planner
      const auto start = Clock::now();
      context_ = make_plan_context(mesh_, hand_, *collider_, plan_);
      stats.setup_s += seconds_since(start);
    }
    for (;;) {
      const double left_s = cpu_left_s();
      if (left_s <= 0.0 || cancel_.cancelled()) return std::nullopt;
      PlanParams params = plan_;
      params.grasps = 1;
      params.time_limit_s = std::max(left_s, kMinCallWall_s);
      if (planner_ == PlannerKind::kCord && !sampling_) {
        // Every region processed: explore again with the next seed (new regions), a few times.
        while (order_.empty() && explorations_ < kMaxExplorations) explore(left_s, stats);
        if (order_.empty()) {
          if (plan_.fallback_attempts <= 0) return std::nullopt;
          sampling_ = true;  // then the sampled fallback's surface points
          continue;
        }
        const PlanResult r = plan_cord_grasps_from_regions(
            mesh_, hand_, *collider_, regions_, params, 0.0, &order_, cancel_, &*context_);
        add_stats(stats, r.stats);
        if (r.stats.interrupted) return std::nullopt;
        if (r.grasps.empty()) {
          // Out of wall time: the regions not reached wait for the next call; otherwise the
          // regions (or this exploration's attempts) are spent.
          const size_t processed =
              std::min(order_.size(), static_cast<size_t>(r.stats.regions_processed));
          if (r.stats.timed_out && !r.stats.attempt_budget_reached) {
            order_.erase(order_.begin(), order_.begin() + static_cast<long>(processed));
            offset_ += static_cast<int>(processed);
          } else {
            order_.clear();
          }
          continue;
        }
        Grasp g = r.grasps.front();
        const int rank = *g.region_rank;  // position in order_
        order_.erase(order_.begin(), order_.begin() + rank + 1);
        g.region_rank = offset_ + rank;
        g.times.exploration_s = exploration_s_;
        offset_ += rank + 1;
        return g;
      }
      params.seed = plan_.seed + calls_++;
      params.quality.seed = params.seed;
      if (sampling_) params.max_attempts = plan_.fallback_attempts;
      const PlanResult r =
          sampling_
              ? plan_cord_fallback_grasps(mesh_, hand_, *collider_, params, cancel_, &*context_)
              : plan_generic_grasps(mesh_, hand_, *collider_, params, cancel_, &*context_);
      add_stats(stats, r.stats);
      if (sampling_) stats.sampled_attempts += r.stats.attempts;
      if (!r.grasps.empty()) return r.grasps.front();
      if (r.stats.interrupted) return std::nullopt;
      // cord: a batch of sampled points without a candidate is followed by others while the
      // budget lasts; the generic planner's call that spent its attempts ends it
      if (!sampling_ && !r.stats.timed_out) return std::nullopt;
    }
  }

 private:
  void explore(double time_left_s, PlanStats& stats) {
    const auto start = Clock::now();
    CordParams explore = *cord_;
    explore.seed += static_cast<std::uint64_t>(explorations_);
    if (explore.time_limit_s <= 0.0 || explore.time_limit_s > time_left_s)
      explore.time_limit_s = time_left_s;
    const double w_palm = palm_width(hand_);
    regions_ = explore_cords(mesh_, w_palm, explore, nullptr, collider_->object_bvh(), threads_);
    order_ = cord_region_order(regions_, w_palm, explore);
    exploration_s_ = seconds_since(start);
    offset_ = 0;
    stats.regions += static_cast<int>(regions_.size());
    stats.exploration_s += exploration_s_;
    ++explorations_;
  }

  const Mesh& mesh_;
  const HandModel& hand_;
  PlannerKind planner_;
  const PlanParams& plan_;
  const std::optional<CordParams>& cord_;
  CancelToken cancel_;
  int threads_;  ///< the exploration's scans
  std::unique_ptr<HandObjectCollider> collider_;
  std::optional<PlanContext> context_;        ///< made at the first candidate
  std::optional<DrawnPoseCloser> closer_;     ///< made at the first hold test
  static constexpr int kMaxExplorations = 4;  ///< the first and three with later seeds
  /// Shortest wall-clock limit of a planner call, so that each call makes progress [s].
  static constexpr double kMinCallWall_s = 0.01;
  int explorations_ = 0;
  std::vector<GraspRegion> regions_;
  std::vector<int> order_;  ///< regions not yet processed, in processing order
  int offset_ = 0;          ///< regions processed before order_.front()
  double exploration_s_ = 0.0;
  std::uint64_t calls_ = 0;
  bool sampling_ = false;  ///< cord: every exploration spent, PlanParams::fallback_attempts
};

/// Counts a first trial `first` that lost the object, by the phase that lost it (settle, or
/// none named, counts as close).
void count_loss(ValidationStats& vs, const SimResult& first) {
  const PhaseResult* failed = first.failed_phase();
  const std::string phase = failed ? failed->name : std::string("close");
  vs.lost_not_pressing += first.lost_without_pressing();
  vs.lost_below_weight_margin += first.lost_below_weight_margin();
  if (phase == "lift")
    ++vs.lost_in_lift;
  else if (phase == "shake")
    ++vs.lost_in_shake;
  else if (phase == "gravity6")
    ++vs.lost_in_gravity6;
  else
    ++vs.lost_in_close;
}

Outcome phase_outcome(const SimResult& r, const char* name) {
  const PhaseResult* p = r.phase(name);
  return p ? p->outcome : Outcome::kNotRun;
}

}  // namespace

ValidatedPlan plan_validated_grasps(const Mesh& mesh, const HandModel& hand, PlannerKind planner,
                                    const PlanParams& plan, const std::optional<CordParams>& cord,
                                    const ValidationParams& rules, const SimParams& sim,
                                    int jobs, const ValidatedPlanProgress& progress,
                                    const CancelToken& cancel) {
  const ValidationParams& v = rules;
  if (v.trials < 1 || v.trials > 1000)
    throw std::invalid_argument("plan_validated_grasps: trials must be in [1, 1000], got " +
                                std::to_string(v.trials));
  if (v.min_held < 1 || v.min_held > v.trials)
    throw std::invalid_argument("plan_validated_grasps: min_held must be in [1, trials = " +
                                std::to_string(v.trials) + "], got " +
                                std::to_string(v.min_held));
  const bool uncertain = !is_none(v.uncertainty);
  const HoldProbabilityParams hold_test =
      hold_test_params(v.min_hold_probability, v.max_draws, v.trial_seed);
  if (uncertain) check_hold_test(v.uncertainty, hold_test);
  if (planner == PlannerKind::kCord && !cord)
    throw std::invalid_argument("plan_validated_grasps: the cord planner needs CordParams");
  const auto start = Clock::now();
  const double cpu_start = process_cpu_s();
  const auto cpu_used = [&] { return process_cpu_s() - cpu_start; };
  const auto say = [&](const std::string& line) { if (progress) progress(line); };
  ValidatedPlan out;
  PlanValidation& record = out.validation;
  record.params = v;
  ValidationStats& vs = record.stats;
  const SimTests tests = sim_tests_from_string(v.tests);

  const int wanted = std::max(1, plan.grasps);
  const double radius_m = bounding_radius(mesh, vertex_mean(mesh));
  CandidateSource source(mesh, hand, planner, plan, cord, cancel, jobs);
  PlanStats& stats = out.stats;
  std::vector<Grasp>& accepted_grasps = out.grasps;
  int candidate = -1;
  bool& interrupted = out.interrupted;  // stopped by `cancel` before the other rules
  while (static_cast<int>(accepted_grasps.size()) < wanted) {
    if (cancel.cancelled()) {
      interrupted = true;
      break;
    }
    const double left_s = v.budget_s - cpu_used();
    if (left_s <= 0.0) {
      vs.budget_spent = true;
      break;
    }
    const auto plan_start = Clock::now();
    std::optional<Grasp> g = source.next(left_s, stats);
    vs.planning_s += seconds_since(plan_start);
    if (!g) {
      interrupted = cancel.cancelled();
      vs.budget_spent = !interrupted && v.budget_s - cpu_used() <= 0.0;
      break;
    }
    ++candidate;
    if (!stats.first_force_closure_s) stats.first_force_closure_s = seconds_since(start);
    if (!differs_from_all(*g, accepted_grasps, plan.diversity, radius_m)) {
      ++vs.similar;
      say("candidate " + std::to_string(candidate) + ": a near copy of an accepted grasp");
      continue;
    }
    // Trial 1 as planned: the cheap rejection happens here.
    const auto physics_start = Clock::now();
    ++vs.simulated;
    const SimResult first = validate_grasp(mesh, hand, *g, sim, tests);
    ++vs.trials_run;
    vs.object_mass_kg = first.object.mass_kg;
    if (first.rejected_in_close) {
      ++vs.rejected_early;
      vs.physics_s += seconds_since(physics_start);
      const PhaseResult* close = first.phase("close");
      char shift_mm[32];
      std::snprintf(shift_mm, sizeof shift_mm, "%.0f",
                    1e3 * (close ? close->translation_m : 0.0));
      say("candidate " + std::to_string(candidate) + ": rejected early, squeeze shift " +
          shift_mm + " mm");
      continue;
    }
    if (v.require_held_as_planned && !first.held()) {
      vs.physics_s += seconds_since(physics_start);
      const PhaseResult* failed = first.failed_phase();
      count_loss(vs, first);
      say("candidate " + std::to_string(candidate) + ": not held as planned (" +
          to_string(first.outcome) + (failed ? " in " + failed->name : std::string()) + ")");
      continue;
    }
    vs.held_as_planned += first.held() ? 1 : 0;
    GraspValidation gv;
    if (uncertain) {
      // P(held) under uncertainty: draws until the Wilson interval is decided (`jobs` at a
      // time; the test stops where one at a time would).
      const HoldProbability h =
          estimate_hold_probability(mesh, hand, *g, candidate, sim, tests, v.uncertainty, hold_test,
                                    cancel, jobs, &source.closer());
      vs.trials_run += h.simulations;
      vs.physics_s += seconds_since(physics_start);
      if (!h.complete) {  // cancelled between draws: abandon the candidate
        interrupted = true;
        break;
      }
      if (h.verdict != HoldVerdict::kAbove) {
        ++vs.lost_in_later_trials;
        say("candidate " + std::to_string(candidate) + ": " + hold_probability_line(h));
        continue;
      }
      // Confirmation with draws of its own: among many candidates, some pass the first test
      // on lucky draws (the winner's curse); the second test's draws do not know the first's
      // selection, and its P(held) is the one recorded and ranked.
      const auto confirmation_start = Clock::now();
      const HoldProbability c =
          estimate_hold_probability(mesh, hand, *g, candidate, sim, tests, v.uncertainty,
                                    confirmation_test(hold_test), cancel, jobs, &source.closer());
      vs.trials_run += c.simulations;
      vs.physics_s += seconds_since(confirmation_start);
      if (!c.complete) {
        interrupted = true;
        break;
      }
      const bool accepted = c.verdict == HoldVerdict::kAbove;
      say("candidate " + std::to_string(candidate) + ": " + hold_probability_line(h) +
          "; confirmation: " + hold_probability_line(c) +
          (accepted ? ", accepted (" + std::to_string(accepted_grasps.size() + 1) + " / " +
                          std::to_string(wanted) + ")"
                    : std::string()));
      if (!accepted) {
        ++vs.lost_in_later_trials;
        continue;
      }
      gv.held_trials = c.held;
      gv.trials = static_cast<int>(c.draws.size());
    } else {
      // Nudged trials, `jobs` at a time, until the verdict is decided; the record keeps the
      // trials a one-at-a-time run would have made, so it does not depend on `jobs`.
      std::vector<Outcome> outcomes{first.outcome};
      const auto decided = [&](const std::vector<Outcome>& o) {
        const int held = count_held(o);
        return held >= v.min_held || held + (v.trials - static_cast<int>(o.size())) < v.min_held;
      };
      while (!decided(outcomes) && !cancel.cancelled()) {
        const int from = static_cast<int>(outcomes.size());
        const int batch = std::min(std::max(1, jobs), v.trials - from);
        std::vector<Outcome> more(static_cast<size_t>(batch), Outcome::kNotRun);
        parallel_for(batch, jobs, [&](int i) {
          const int t = from + i;
          const Grasp nudged = perturbed_grasp(
              *g, v.perturbation, v.trial_seed + 1000 * static_cast<std::uint64_t>(candidate) + t);
          more[static_cast<size_t>(i)] = validate_grasp(mesh, hand, nudged, sim, tests).outcome;
        });
        vs.trials_run += batch;
        for (Outcome o : more) {
          if (decided(outcomes)) break;
          outcomes.push_back(o);
        }
      }
      vs.physics_s += seconds_since(physics_start);
      if (!decided(outcomes)) {  // cancelled between trial batches: abandon the candidate
        interrupted = true;
        break;
      }
      const int held = count_held(outcomes);
      const bool accepted = held >= v.min_held;
      say("candidate " + std::to_string(candidate) + ": held in " + std::to_string(held) + " / " +
          std::to_string(outcomes.size()) + " trials" +
          (accepted ? ", accepted (" + std::to_string(accepted_grasps.size() + 1) + " / " +
                          std::to_string(wanted) + ")"
                    : std::string()));
      if (!accepted) {
        ++vs.lost_in_later_trials;
        continue;
      }
      gv.held_trials = held;
      gv.trials = static_cast<int>(outcomes.size());
    }
    gv.settle = phase_outcome(first, "settle");
    gv.close = phase_outcome(first, "close");
    gv.lift = phase_outcome(first, "lift");
    gv.shake = phase_outcome(first, "shake");
    gv.gravity6 = phase_outcome(first, "gravity6");
    if (const PhaseResult* close = first.phase("close")) gv.squeeze_shift_m = close->translation_m;
    gv.mass_kg = first.object.mass_kg;
    record.grasps.push_back(gv);
    accepted_grasps.push_back(std::move(*g));
    ++vs.accepted;
    if (!vs.first_accepted_s) {
      vs.first_accepted_s = seconds_since(start);
      vs.first_accepted_cpu_s = cpu_used();
    }
  }
  if (uncertain) {
    // Rank the accepted grasps by P(held) (held / draws), most likely first; ties keep the
    // planner's order.
    std::vector<size_t> order(accepted_grasps.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    const auto p_held = [&](size_t i) {
      const GraspValidation& r = record.grasps[i];
      return r.trials > 0 ? static_cast<double>(r.held_trials) / r.trials : 0.0;
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return p_held(a) > p_held(b); });
    std::vector<Grasp> grasps;
    std::vector<GraspValidation> verdicts;
    for (const size_t i : order) {
      grasps.push_back(std::move(accepted_grasps[i]));
      verdicts.push_back(record.grasps[i]);
    }
    accepted_grasps = std::move(grasps);
    record.grasps = std::move(verdicts);
  }
  vs.attempts = stats.attempts;
  vs.force_closure = stats.force_closure;
  vs.total_s = seconds_since(start);
  vs.cpu_s = cpu_used();
  stats.total_s = vs.total_s;
  stats.timed_out = vs.budget_spent;
  if (interrupted) stats.interrupted = true;
  return out;
}

}  // namespace cordgrasp
