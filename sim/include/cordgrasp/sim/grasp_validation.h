#pragma once
// What validated planning (plan_validated_grasps.h) records: its settings, the physics verdict
// on each accepted grasp and the plan's counts; plan.json holds all three (jobs/plan_json.h).
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/grasp_perturbation.h"
#include "cordgrasp/core/serialize.h"
#include "cordgrasp/sim/grasp_uncertainty.h"
#include "cordgrasp/sim/sim_params.h"
#include "cordgrasp/sim/sim_result.h"

namespace cordgrasp {

/// Settings of validated planning (docs/algorithm.md §10a); the planner's own settings and the
/// number of grasps wanted (PlanParams::grasps) come from PlanJobParams. protocol, physics and
/// physics_file make the SimParams (the job's part, validated_plan_job.h): the algorithm
/// (plan_validated_grasps.h) takes those SimParams and reads the rest.
struct ValidationParams {
  std::string tests = "lift,shake";     ///< physics tests of every trial (validate --tests)
  Protocol protocol = SimParams{}.protocol;  ///< physics protocol preset of every trial
  int trials = 3;                        ///< trials per candidate: as planned, then nudged
  int min_held = 2;                      ///< accepted when held in at least this many trials
  /// ...of which the first, the grasp as planned (the one plan.json stores), must be one:
  /// a grasp that fails as planned fails again in every later `validate` of the plan.
  bool require_held_as_planned = true;
  /// Uncertainty of the P(held) test (docs/physics.md §3b); all 0 (uncertainty_none, the
  /// default): trials and min_held decide. Otherwise a candidate held as planned is accepted
  /// when the Wilson 95 % interval of its P(held) lies above min_hold_probability, within
  /// max_draws draws (seeded by trial_seed and the candidate's index), and the accepted grasps
  /// are ranked by P(held). A candidate decided above is accepted only if a second test on
  /// draws of its own (confirmation_test) is decided above too; its P(held) is recorded.
  UncertaintyParams uncertainty = uncertainty_none();
  double min_hold_probability = 0.8;  ///< acceptance threshold of P(held) [-]
  int max_draws = 20;                 ///< draws per candidate at most
  /// Cap on the CPU time of planning and physics together (all threads of the process) [s];
  /// the planner's own time limit (PlanParams::time_limit_s) is ignored.
  double budget_s = 30.0;
  /// Early rejection (SimParams::squeeze_shift_limit_m): a candidate whose object moves
  /// farther than this while closing is dropped before lift and shake [m]; 0: off.
  double squeeze_shift_limit_m = 0.05;
  PerturbationParams perturbation;  ///< nudge of trials 2..N (as `validate --trials`)
  std::uint64_t trial_seed = 1;     ///< seed of the nudges' directions
  /// Object mass and grip of every trial over the SimParams given (CLI --mass, --density,
  /// --squeeze-weight); `validate --plan` takes them from here unless told otherwise.
  SimOverrides physics;
  /// Physics settings file of every trial, merged last (physics_settings); `validate --plan`
  /// uses it too unless given another. Empty: none.
  std::string physics_file;

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(tests), CORDGRASP_NVP(protocol), CORDGRASP_NVP(trials),
                 CORDGRASP_NVP(min_held), CORDGRASP_NVP(require_held_as_planned),
                 CORDGRASP_NVP(uncertainty), CORDGRASP_NVP(min_hold_probability),
                 CORDGRASP_NVP(max_draws), CORDGRASP_NVP(budget_s),
                 CORDGRASP_NVP(squeeze_shift_limit_m), CORDGRASP_NVP(perturbation),
                 CORDGRASP_NVP(trial_seed), CORDGRASP_NVP(physics), CORDGRASP_NVP(physics_file));
  }
};

/// Physics verdict on one accepted grasp.
struct GraspValidation {
  int held_trials = 0;  ///< trials (with uncertainty: draws after the as-planned one) held
  int trials = 0;       ///< trials run (with uncertainty: draws; P(held) = held / draws)
  /// Outcome of each phase in the first trial (the grasp as planned).
  Outcome settle = Outcome::kNotRun;
  Outcome close = Outcome::kNotRun;
  Outcome lift = Outcome::kNotRun;
  Outcome shake = Outcome::kNotRun;
  Outcome gravity6 = Outcome::kNotRun;
  double squeeze_shift_m = 0.0;  ///< object moved in the hand while closing, first trial [m]
  double mass_kg = 0.0;          ///< object mass as simulated [kg]

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(held_trials), CORDGRASP_NVP(trials), CORDGRASP_NVP(settle),
                 CORDGRASP_NVP(close), CORDGRASP_NVP(lift), CORDGRASP_NVP(shake),
                 CORDGRASP_NVP(gravity6), CORDGRASP_NVP(squeeze_shift_m),
                 CORDGRASP_NVP(mass_kg));
  }
};

/// Counts of one validated plan; times from the plan's start, wall clock unless named CPU [s].
struct ValidationStats {
  int attempts = 0;          ///< finger-stage runs of the planner
  int force_closure = 0;     ///< force-closure candidates the planner gave
  int similar = 0;           ///< candidates skipped as near copies of an accepted grasp
  int simulated = 0;         ///< candidates given to physics
  int rejected_early = 0;    ///< of those, dropped by the squeeze shift before lift
  int held_as_planned = 0;   ///< of those, held in the first trial (the grasp as planned)
  /// Of those simulated, not held in the first trial (other than rejected early), by the phase
  /// that lost the object (settle counts as close).
  int lost_in_close = 0;
  int lost_in_lift = 0;
  int lost_in_shake = 0;
  int lost_in_gravity6 = 0;
  int lost_in_later_trials = 0;  ///< went on to the later trials and was not accepted
  /// Of those lost in lift, shake or gravity6, the ones whose fingers did not press the object
  /// at the end of the close (SimResult::lost_without_pressing): lost for want of a squeeze,
  /// not for the hand's strength.
  int lost_not_pressing = 0;
  /// Of those lost in lift, shake or gravity6, the ones whose planned contacts cannot carry the
  /// object's weight within the hand's effort limits (SimResult::lost_below_weight_margin):
  /// too weak a hand at those contacts, whatever its grip.
  int lost_below_weight_margin = 0;
  double object_mass_kg = 0.0;   ///< object mass as simulated (0: nothing simulated) [kg]
  int trials_run = 0;        ///< physics trials run in all
  int accepted = 0;          ///< candidates held in ≥ min_held trials
  std::optional<double> first_accepted_s;  ///< time to the first accepted grasp
  double planning_s = 0.0;   ///< exploration and finger stage
  double physics_s = 0.0;    ///< physics trials
  double total_s = 0.0;      ///< the whole plan
  std::optional<double> first_accepted_cpu_s;  ///< CPU time to the first accepted grasp
  double cpu_s = 0.0;        ///< CPU time of the whole plan (all threads)
  bool budget_spent = false;  ///< stopped by budget_s before enough grasps were accepted

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(
        a, CORDGRASP_NVP(attempts), CORDGRASP_NVP(force_closure), CORDGRASP_NVP(similar),
        CORDGRASP_NVP(simulated), CORDGRASP_NVP(rejected_early), CORDGRASP_NVP(held_as_planned),
        CORDGRASP_NVP(lost_in_close), CORDGRASP_NVP(lost_in_lift), CORDGRASP_NVP(lost_in_shake),
        CORDGRASP_NVP(lost_in_gravity6), CORDGRASP_NVP(lost_in_later_trials),
        CORDGRASP_NVP(lost_not_pressing), CORDGRASP_NVP(lost_below_weight_margin),
        CORDGRASP_NVP(object_mass_kg), CORDGRASP_NVP(trials_run), CORDGRASP_NVP(accepted),
        CORDGRASP_NVP(first_accepted_s), CORDGRASP_NVP(planning_s), CORDGRASP_NVP(physics_s),
        CORDGRASP_NVP(total_s), CORDGRASP_NVP(first_accepted_cpu_s), CORDGRASP_NVP(cpu_s),
        CORDGRASP_NVP(budget_spent));
  }
};

/// Validated planning's record in a plan: settings, counts, one verdict per grasp.
struct PlanValidation {
  ValidationParams params;
  ValidationStats stats;
  std::vector<GraspValidation> grasps;  ///< one per plan grasp, in the same order
};

}  // namespace cordgrasp
