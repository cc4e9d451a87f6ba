#pragma once
// Planner settings documents (docs/algorithm.md §10c): the planner's and validated planning's
// settings as one JSON or YAML file, merged over the defaults, so that an experiment is a file
// and any plan can be repeated.
//
// Layout (every key optional; nested mappings partially too), the layout of plan.json's
// "parameters" block: planner, every PlanParams field (grasps, time_limit_s, seed, finger,
// quality, roll_retry, max_attempts, diversity), cord: every CordParams field, units and scale
// of the object file, and validation: every ValidationParams field.
#include <string>
#include <utility>

#include "cordgrasp/sim/grasp_validation.h"
#include "cordgrasp/jobs/plan_job.h"

namespace cordgrasp {

/// Merges the planner settings file `path` into `*job` and `*validation`: a JSON (or, named
/// *.yaml / *.yml, YAML) mapping in the layout above, or a plan.json whose settings to repeat
/// (its parameters, inputs.object units and scale, validation.parameters). A soft-finger
/// radius in quality.contact becomes job->soft_finger_radius_m. The result is checked
/// (check_plan_settings).
/// @throws InputError naming the file and the key for an unreadable file, a syntax error, an
/// unknown key, a value of the wrong type or out of range.
void merge_plan_settings_file(const std::string& path, PlanJobParams* job,
                              ValidationParams* validation);

/// Checks every number of the settings: finite, and within its range (plan_settings_range)
/// where it has one; validation.min_held ≤ validation.trials.
/// @throws std::invalid_argument naming the first key out of range ("cord.sets: 0 is not in
/// [1, 100000]").
void check_plan_settings(const PlanJobParams& job, const ValidationParams& validation);

/// The range [lo, hi] of the settings key `key` (its path in the layout above, e.g.
/// "grasps", "quality.contact.mu", "validation.trials"); the command-line options bound to
/// these fields check the same range. @throws std::invalid_argument for a key without one.
std::pair<double, double> plan_settings_range(const std::string& key);

/// The settings as the YAML document merge_plan_settings_file reads back (every field).
std::string plan_settings_yaml(const PlanJobParams& job, const ValidationParams& validation);

}  // namespace cordgrasp
