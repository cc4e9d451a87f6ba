#include "cordgrasp/jobs/validate_plan.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "cordgrasp/core/parallel_for.h"
#include "cordgrasp/jobs/text_format.h"

namespace cordgrasp {
namespace {

/// {shift [m], turn [rad]} of the object in the hand during close; NaN when close did not run.
std::pair<double, double> close_motion(const SimResult& r) {
  const PhaseResult* close = r.phase("close");
  if (close == nullptr) return {std::nan(""), std::nan("")};
  return {close->translation_m, close->rotation_rad};
}

/// Keeps only the grasps of `doc` with keep[k] set (results, grasps, indices, trials).
void keep_grasps(SimDocument& doc, const std::vector<char>& keep) {
  size_t to = 0;
  for (size_t k = 0; k < doc.results.size(); ++k) {
    if (!keep[k]) continue;
    if (to == k) {  // no self-move: it would empty the vectors
      ++to;
      continue;
    }
    doc.results[to] = std::move(doc.results[k]);
    doc.grasps[to] = std::move(doc.grasps[k]);
    doc.grasp_indices[to] = doc.grasp_indices[k];
    if (k < doc.trial_outcomes.size()) doc.trial_outcomes[to] = std::move(doc.trial_outcomes[k]);
    if (k < doc.trial_close_motion.size())
      doc.trial_close_motion[to] = std::move(doc.trial_close_motion[k]);
    if (k < doc.hold_probabilities.size())
      doc.hold_probabilities[to] = std::move(doc.hold_probabilities[k]);
    ++to;
  }
  doc.results.resize(to);
  doc.grasps.resize(to);
  doc.grasp_indices.resize(to);
  if (!doc.trial_outcomes.empty()) doc.trial_outcomes.resize(to);
  if (!doc.trial_close_motion.empty()) doc.trial_close_motion.resize(to);
  if (!doc.hold_probabilities.empty()) doc.hold_probabilities.resize(to);
}

}  // namespace

SimDocument validate_plan(const PlanDocument& plan, const HandModel& hand, const Mesh& mesh,
                          const SimParams& params, const SimTests& tests, int max_grasps,
                          const ValidateProgress& progress, const GraspPhaseHooks& hooks,
                          int jobs, const CancelToken& cancel) {
  const auto start = std::chrono::steady_clock::now();
  SimDocument doc;
  doc.hand_name = plan.hand_name;
  doc.hand_path = plan.hand_path;
  doc.object_path = plan.object_path;
  doc.object_name = plan.object_name;
  doc.object_units = plan.object_units;
  doc.object_scale = plan.object_scale;
  doc.object_triangles = static_cast<int>(mesh.triangles.size());
  doc.plan_seed = plan.params.seed;
  doc.params = params;
  doc.tests = tests;
  const int total = max_grasps < 0 ? static_cast<int>(plan.grasps.size())
                                   : std::min(max_grasps, static_cast<int>(plan.grasps.size()));
  doc.results.resize(static_cast<size_t>(total));
  doc.grasps_asked = total;
  for (int k = 0; k < total; ++k) {
    doc.grasps.push_back(plan.grasps[static_cast<size_t>(k)]);
    doc.grasp_indices.push_back(k);
  }
  // One physics world per grasp and thread: the results do not depend on `jobs`.
  InOrderReporter reporter(total, [&](int k) {
    if (progress) progress(k + 1, total, doc.results[static_cast<size_t>(k)]);
  });
  std::vector<char> done(static_cast<size_t>(total), 0);
  parallel_for(total, jobs, [&](int k) {
    if (cancel.cancelled()) return;  // no new grasp; those in flight finish
    const Grasp& g = plan.grasps[static_cast<size_t>(k)];
    doc.results[static_cast<size_t>(k)] =
        validate_grasp(mesh, hand, g, params, tests, hooks ? hooks(k) : PhaseHook{});
    done[static_cast<size_t>(k)] = 1;
    reporter.finished(k);
  });
  if (std::count(done.begin(), done.end(), 0) > 0) {
    keep_grasps(doc, done);
    doc.interrupted = cancel.reason();
  }
  doc.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return doc;
}

void add_perturbed_trials(SimDocument& doc, const PlanDocument& plan, const HandModel& hand,
                          const Mesh& mesh, int trials, const PerturbationParams& perturbation,
                          std::uint64_t seed, const ValidateProgress& progress, int jobs,
                          const CancelToken& cancel, const TrialWatch& watch) {
  if (trials < 1 || trials > 1000)
    throw std::invalid_argument("add_perturbed_trials: trials must be in [1, 1000], got " +
                                std::to_string(trials));
  const auto start = std::chrono::steady_clock::now();
  doc.trial_perturbation = perturbation;
  doc.trial_seed = seed;
  doc.trials = trials;
  doc.trial_outcomes.assign(doc.results.size(), {});
  const int total = static_cast<int>(doc.results.size());
  const int per_grasp = trials - 1;  // trial 0 is doc.results[k]
  doc.trial_close_motion.assign(doc.results.size(), {});
  for (int k = 0; k < total; ++k) {
    const SimResult& first = doc.results[static_cast<size_t>(k)];
    doc.trial_outcomes[static_cast<size_t>(k)].assign(static_cast<size_t>(trials), first.outcome);
    doc.trial_close_motion[static_cast<size_t>(k)].assign(static_cast<size_t>(trials),
                                                          close_motion(first));
  }
  // Every (grasp, trial) pair is a task of its own; a grasp is reported once all its trials are.
  std::vector<int> trials_left(static_cast<size_t>(total), per_grasp);
  std::mutex left_mutex;
  InOrderReporter reporter(total, [&](int k) {
    if (progress) progress(k + 1, total, doc.results[static_cast<size_t>(k)]);
  });
  if (per_grasp == 0)
    for (int k = 0; k < total; ++k) reporter.finished(k);
  parallel_for(total * per_grasp, jobs, [&](int task) {
    if (cancel.cancelled()) return;  // no new trial; those in flight finish
    const int k = task / per_grasp, t = 1 + task % per_grasp;
    const Grasp& planned = plan.grasps[static_cast<size_t>(doc.grasp_indices[static_cast<size_t>(k)])];
    const Grasp g = perturbed_grasp(planned, perturbation, seed + 1000 * k + t);
    const SimResult r = validate_grasp(mesh, hand, g, doc.params, doc.tests,
                                       watch.hook ? watch.hook(k, t) : PhaseHook{});
    if (watch.done) watch.done(k, t, r);
    doc.trial_outcomes[static_cast<size_t>(k)][static_cast<size_t>(t)] = r.outcome;
    doc.trial_close_motion[static_cast<size_t>(k)][static_cast<size_t>(t)] = close_motion(r);
    bool grasp_done = false;
    {
      const std::lock_guard<std::mutex> lock(left_mutex);
      grasp_done = --trials_left[static_cast<size_t>(k)] == 0;
    }
    if (grasp_done) reporter.finished(k);
  });
  std::vector<char> complete(static_cast<size_t>(total), 0);
  for (size_t k = 0; k < complete.size(); ++k) complete[k] = trials_left[k] == 0;
  if (std::count(complete.begin(), complete.end(), 0) > 0) {
    keep_grasps(doc, complete);
    doc.interrupted = cancel.reason();
  }
  doc.wall_time_s +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void add_hold_probabilities(SimDocument& doc, const PlanDocument& plan, const HandModel& hand,
                            const Mesh& mesh, const UncertaintyParams& uncertainty,
                            const HoldProbabilityParams& test, const ValidateProgress& progress,
                            int jobs, const CancelToken& cancel) {
  check_hold_test(uncertainty, test);
  const auto start = std::chrono::steady_clock::now();
  doc.uncertainty = uncertainty;
  doc.hold_test = test;
  const int total = static_cast<int>(doc.results.size());
  doc.hold_probabilities.assign(doc.results.size(), {});
  InOrderReporter reporter(total, [&](int k) {
    if (progress) progress(k + 1, total, doc.results[static_cast<size_t>(k)]);
  });
  // One re-closure collider for every grasp (where the model moves the hand).
  std::optional<DrawnPoseCloser> closer;
  if (moves_hand(uncertainty) && total > 0) closer.emplace(hand, mesh);
  // One task per grasp: its draws run in order, so where the test stops is deterministic.
  parallel_for(total, jobs, [&](int k) {
    const size_t i = static_cast<size_t>(k);
    const int index = doc.grasp_indices[i];
    doc.hold_probabilities[i] = estimate_hold_probability(
        mesh, hand, plan.grasps[static_cast<size_t>(index)], index, doc.params, doc.tests,
        uncertainty, test, cancel, 1, closer ? &*closer : nullptr);
    reporter.finished(k);
  });
  std::vector<char> complete(static_cast<size_t>(total), 0);
  for (size_t k = 0; k < complete.size(); ++k) complete[k] = doc.hold_probabilities[k].complete;
  if (std::count(complete.begin(), complete.end(), 0) > 0) {
    keep_grasps(doc, complete);
    doc.interrupted = cancel.reason();
  }
  doc.wall_time_s +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string validation_summary(const SimDocument& doc, const std::string& tests,
                               const std::string& out_path) {
  int held = 0;
  for (const SimResult& r : doc.results) held += r.held();
  char head[96];
  std::snprintf(head, sizeof(head), "held %d / %d (tests %s, mu %.3g) -> ", held,
                static_cast<int>(doc.results.size()), tests.c_str(), doc.params.contact.mu);
  std::string text = head + out_path + "\n" + failures_line(doc.results) + "\n";
  if (!doc.trial_outcomes.empty()) {
    std::vector<Outcome> all;
    for (const auto& t : doc.trial_outcomes) all.insert(all.end(), t.begin(), t.end());
    text += trials_line(all) + " of all grasps\n";
  }
  if (!doc.hold_probabilities.empty()) {
    int above = 0;
    std::vector<int> draws;
    for (const HoldProbability& h : doc.hold_probabilities) {
      above += h.verdict == HoldVerdict::kAbove;
      draws.push_back(static_cast<int>(h.draws.size()));
    }
    std::sort(draws.begin(), draws.end());
    char line[128];
    std::snprintf(line, sizeof(line), "P(held) above %.2f: %d of %d grasps, median draws %d\n",
                  doc.hold_test.min_hold_probability, above, static_cast<int>(draws.size()),
                  draws.empty() ? 0 : draws[draws.size() / 2]);
    text += line;
  }
  return text;
}

std::string trials_line(const std::vector<Outcome>& outcomes) {
  return "held in " + std::to_string(count_held(outcomes)) + " / " +
         std::to_string(outcomes.size()) + " trials";
}

FailureCounts count_failures(const std::vector<SimResult>& results) {
  FailureCounts counts;
  for (const char* name : {"settle", "close", "lift", "shake", "gravity6"})
    counts.by_phase.emplace_back(name, 0);
  for (const SimResult& r : results) {
    counts.preshape_overlaps += r.preshape_overlap;
    counts.not_pressing += r.lost_without_pressing();
    if (const PhaseResult* failed = r.held() ? nullptr : r.failed_phase())
      for (auto& [name, count] : counts.by_phase)
        if (name == failed->name) ++count;
  }
  return counts;
}

std::string failures_line(const std::vector<SimResult>& results) {
  const FailureCounts counts = count_failures(results);
  std::string line = "not held by phase:";
  for (size_t i = 0; i < counts.by_phase.size(); ++i)
    line += (i ? ", " : " ") + counts.by_phase[i].first + " " +
            std::to_string(counts.by_phase[i].second);
  line += "; preshape overlaps " + std::to_string(counts.preshape_overlaps);
  if (counts.not_pressing > 0)
    line += "; no finger pressing after the close " + std::to_string(counts.not_pressing);
  return line;
}

std::string sim_result_line(const SimResult& r) {
  std::ostringstream s;
  s << to_string(r.outcome) << " (";
  bool first = true;
  for (const PhaseResult& p : r.phases) {
    if (p.name == "settle" || p.name == "close") {
      if (p.outcome == Outcome::kHeld) continue;
    }
    if (!first) s << ", ";
    first = false;
    s << p.name << ' ' << to_string(p.outcome);
    if (!p.detail.empty() && p.outcome != Outcome::kHeld) s << " at " << p.detail;
  }
  char tail[96];
  std::snprintf(tail, sizeof(tail), ") mass %.3f kg, %.2f s", r.object.mass_kg, r.wall_time_s);
  s << tail;
  if (const PhaseResult* settle = r.preshape_overlap ? r.phase("settle") : nullptr)
    s << "; the preshape hand overlaps the object's collision shape (settle moved it "
      << fixed(1e3 * settle->translation_m, 1) << " mm)";
  return s.str();
}

}  // namespace cordgrasp
