#pragma once
// Command-line options shared by several subcommands, bound to the jobs' parameter structs.
#include <CLI/CLI.hpp>

#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/render_options.h"

namespace cordgrasp::cli {

/// Adds the planner options (--planner, --grasps, --time-limit, --seed, --mu,
/// --soft-finger-radius, --side-cords, --quality, --units, --sets, --no-local-improvement) to
/// `cmd`, bound to `p`.
void add_plan_job_options(CLI::App* cmd, PlanJobParams& p);

/// Adds --view, --approach, --size, --supersample, --ground, --caption, --no-caption, --ortho.
void add_picture_options(CLI::App& cmd, PictureOptions& o);

}  // namespace cordgrasp::cli
