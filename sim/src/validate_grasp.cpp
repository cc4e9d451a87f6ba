#include "cordgrasp/sim/validate_grasp.h"

#include <chrono>
#include <sstream>
#include <stdexcept>

namespace cordgrasp {

SimTests sim_tests_from_string(const std::string& text) {
  SimTests t{false, false, false};
  std::stringstream in(text);
  std::string item;
  bool any = false;
  while (std::getline(in, item, ',')) {
    if (item == "lift")
      t.lift = true;
    else if (item == "shake")
      t.shake = true;
    else if (item == "gravity6")
      t.gravity6 = true;
    else
      throw std::invalid_argument("test '" + item + "' is not one of lift, shake, gravity6");
    any = true;
  }
  if (!any) throw std::invalid_argument("no test given (lift, shake, gravity6)");
  return t;
}

std::string to_string(const SimTests& tests) {
  std::string out;
  auto add = [&out](bool on, const char* name) {
    if (!on) return;
    if (!out.empty()) out += ',';
    out += name;
  };
  add(tests.lift, "lift");
  add(tests.shake, "shake");
  add(tests.gravity6, "gravity6");
  return out;
}

namespace {

/// Runs settle and close; false when the grasp cannot continue (blown up, nothing touched,
/// or pushed past SimParams::squeeze_shift_limit_m).
bool settle_and_close(GraspSimulation& sim, SimResult& result, const PhaseHook& hook,
                      bool record, double squeeze_shift_limit_m) {
  PhaseResult settle = sim.settle();
  if (hook) hook(sim.snapshot("settle"));
  const bool settled = settle.outcome != Outcome::kUnstable;
  if (record) result.phases.push_back(settle);
  if (!settled) {
    result.outcome = Outcome::kUnstable;
    return false;
  }
  PhaseResult close = sim.close();
  if (hook) hook(sim.snapshot("close"));
  if (close.outcome == Outcome::kHeld && squeeze_shift_limit_m > 0.0 &&
      close.translation_m > squeeze_shift_limit_m) {
    close.outcome = Outcome::kSlipped;
    close.detail = "squeeze shift limit";
    result.rejected_in_close = true;
  }
  const bool closed = close.outcome == Outcome::kHeld;
  if (record) {
    result.phases.push_back(close);
    result.planned_contact_offsets_m = sim.planned_contact_offsets();
  }
  if (!closed) {
    result.outcome = close.outcome;
    return false;
  }
  return true;
}

}  // namespace

SimResult validate_grasp(const Mesh& mesh, const HandModel& hand, const Grasp& grasp,
                         const SimParams& params, const SimTests& tests,
                         const PhaseHook& hook) {
  const auto start = std::chrono::steady_clock::now();
  SimResult result;
  result.outcome = Outcome::kHeld;
  auto fail = [&result](const PhaseResult& p) {
    if (p.outcome != Outcome::kHeld && result.outcome == Outcome::kHeld) result.outcome = p.outcome;
  };
  // After a failed test, for the hook's pictures: where the object goes (no result).
  auto show_failure = [&](GraspSimulation& sim, const PhaseResult& p) {
    if (hook && p.outcome != Outcome::kHeld && p.outcome != Outcome::kUnstable &&
        params.failure_tail_s > 0.0)
      sim.coast(params.failure_tail_s, "after " + p.name);
  };
  {
    GraspSimulation sim(mesh, hand, grasp, params);
    result.object = sim.object_info();
    result.X_WO = sim.X_WO_start();
    if (!grasp.contacts.empty()) result.weight_margin = sim.weight_margin();
    sim.set_segment_hook(hook);
    const bool ready = settle_and_close(sim, result, hook, true, params.squeeze_shift_limit_m);
    const PhaseResult* settle = result.phase("settle");
    result.preshape_overlap =
        settle != nullptr && settle->translation_m > params.settle_shift_tolerance_m;
    if (ready && (tests.lift || tests.shake)) {
      if (tests.lift) {
        result.phases.push_back(sim.lift());
        if (hook) hook(sim.snapshot("lift"));
        fail(result.phases.back());
        show_failure(sim, result.phases.back());
      }
      if (tests.shake && result.outcome == Outcome::kHeld) {
        result.phases.push_back(sim.shake());
        if (hook) hook(sim.snapshot("shake"));
        fail(result.phases.back());
        show_failure(sim, result.phases.back());
      } else if (tests.shake) {
        PhaseResult skipped;
        skipped.name = "shake";
        result.phases.push_back(skipped);
      }
    }
    if (!ready) {
      if (const PhaseResult* close = result.phase("close")) show_failure(sim, *close);
      for (const char* name : {"lift", "shake", "gravity6"}) {
        const bool wanted = (std::string(name) == "lift" && tests.lift) ||
                            (std::string(name) == "shake" && tests.shake) ||
                            (std::string(name) == "gravity6" && tests.gravity6);
        if (!wanted) continue;
        PhaseResult skipped;
        skipped.name = name;
        result.phases.push_back(skipped);
      }
    }
    if (!ready || !tests.gravity6) {
      result.wall_time_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }
    if (!tests.lift && !tests.shake) {
      // The world is still at the closed grasp: run gravity6 in it.
      result.phases.push_back(sim.gravity6());
      if (hook) hook(sim.snapshot("gravity6"));
      fail(result.phases.back());
      show_failure(sim, result.phases.back());
      result.wall_time_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }
  }
  // gravity6 starts from the closed grasp again: a fresh, identical world (deterministic).
  GraspSimulation sim(mesh, hand, grasp, params);
  SimResult scratch;
  const bool closed_again = settle_and_close(sim, scratch, PhaseHook{}, false,
                                             params.squeeze_shift_limit_m);
  sim.set_segment_hook(hook);  // after the repeated close, which the hook has already seen
  if (closed_again) {
    result.phases.push_back(sim.gravity6());
    if (hook) hook(sim.snapshot("gravity6"));
    show_failure(sim, result.phases.back());
  } else {
    PhaseResult failed;
    failed.name = "gravity6";
    failed.outcome = scratch.outcome;
    failed.detail = "re-closing failed";
    result.phases.push_back(failed);
  }
  fail(result.phases.back());
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace cordgrasp
