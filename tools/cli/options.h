#pragma once
// Command-line options shared by several subcommands, bound to the jobs' parameter structs.
#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/sim/grasp_validation.h"
#include "cordgrasp/jobs/parse_name.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/render_options.h"

namespace cordgrasp::cli {

/// "cm is not one of m, mm, auto" from a parse_name refusal of `text`.
std::string enum_refusal(const std::string& text, const std::string& parse_error);

/// Accepts the to_string names of enum E; refusals read "--units: cm is not one of m, mm, auto".
template <typename E>
std::string enum_name_check(const std::string& text) {
  E value{};
  try {
    parse_name(text, &value);
  } catch (const std::invalid_argument& e) {
    return enum_refusal(text, e.what());
  }
  return std::string();
}

/// An option naming an enumerator of `*field` (its to_string names; parse_name rejects others),
/// with the field's current value as the default shown by --help.
template <typename E>
CLI::Option* add_enum_option(CLI::App* cmd, const std::string& name, E* field,
                             const std::string& help) {
  return cmd
      ->add_option_function<std::string>(
          name, [field](const std::string& text) { parse_name(text, field); }, help)
      ->check(enum_name_check<E>)
      ->default_str(to_string(*field));
}

/// Accepts finite numbers in [lo, hi]; refusals read "--mu: nan is not a finite number in
/// [0, 10]" (CLI11 puts the option's name first).
CLI::Validator number_in(double lo, double hi);

/// Accepts one of `names`; refusals read "--planner: x is not one of cord, generic".
CLI::Validator one_of(const std::vector<std::string>& names);

/// Accepts whole numbers in [lo, hi], written as digits (no "1e3", no "2.5").
CLI::Validator whole_number_in(long long lo, long long hi);

/// Accepts whole numbers ≥ lo written as digits; refusals read "-1 is not a whole number ≥ 0".
CLI::Validator whole_number_at_least(long long lo);

/// Accepts a seed: a whole number in [0, 2^64 − 1] written as digits (no sign, no exponent).
CLI::Validator seed_value();

/// Accepts physics tests "lift,shake,gravity6" (any non-empty subset), and "none" when
/// `allow_none`; refusals read "none is not a comma list of lift, shake, gravity6 (...)".
CLI::Validator physics_tests(bool allow_none);

/// Adds --scale (a uniform object scale after --units, in (0, 1000]) bound to `*scale`.
CLI::Option* add_scale_option(CLI::App* cmd, double* scale, const std::string& extra_help = "");

/// A number check with the range of planner settings key `key` (plan_settings_range).
CLI::Validator settings_number(const std::string& key);

/// A whole-number check with the range of planner settings key `key`.
CLI::Validator settings_whole_number(const std::string& key);

/// Adds --planner (cord or generic), bound to p.planner.
void add_planner_option(CLI::App* cmd, PlanJobParams& p);

/// Adds --grasps, --seed and --mu to `cmd`, bound to `p`.
void add_plan_job_options(CLI::App* cmd, PlanJobParams& p);

/// Adds --units (m, mm or auto), bound to p.units.
void add_units_option(CLI::App* cmd, PlanJobParams& p);

/// Adds --time-limit (the plan's wall-clock safety net, also the generic baseline's budget in
/// comparisons) bound to p.plan.time_limit_s (bench; plan and run take it from --settings).
void add_time_limit_option(CLI::App* cmd, PlanJobParams& p);

/// Adds --settings FILE (merge_plan_settings_file into `p` and `v`), merged while the command
/// line is read, so that the options given with it win.
void add_plan_settings_option(CLI::App* cmd, PlanJobParams& p, ValidationParams& v);

/// Adds --package-path NAME=DIR (repeatable) to `cmd`: the directory of ROS package NAME for
/// package://NAME/... mesh URIs, into o.package_paths (searched before ROS_PACKAGE_PATH and
/// AMENT_PREFIX_PATH; docs/hand-description.md). DIR must be an existing directory; a relative
/// DIR is taken from the working directory.
void add_package_path_option(CLI::App* cmd, HandLoadOptions& o);

/// Adds --view, --approach, --size, --supersample, --ground, --caption, --no-caption, --ortho.
void add_picture_options(CLI::App& cmd, PictureOptions& o);

}  // namespace cordgrasp::cli
