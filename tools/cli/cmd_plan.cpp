// `cordgrasp plan`: cord-driven (or generic baseline) grasp planning → plan.json.
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.h"
#include "options.h"
#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/render_options.h"
#include "cordgrasp/jobs/validated_plan_job.h"
#include "validation_options.h"

namespace cordgrasp::cli {
namespace {

struct PlanOptions {
  std::string hand = default_hand_name();
  std::string object;
  PlanJobParams job;
  std::string out;
  bool validate = false;           ///< --validate: only grasps that hold in physics
  ValidationParams validation;
  int jobs = 1;
  bool quiet = false;
};

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
  char buf[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof(buf), fmt, args);
  va_end(args);
  return buf;
}

void print_summary(const PlanDocument& doc, const HandModel& hand, const std::string& out) {
  const PlanStats& s = doc.stats;
  std::cout << format("plan: %s planner, hand %s, object %s (%d triangles)\n", to_string(doc.planner),
                      hand.name.c_str(), doc.object_name.c_str(), doc.object_triangles);
  if (doc.planner == PlannerKind::kCord)
    std::cout << format("  exploration %.3f s: %d regions, %d processed\n", s.exploration_s,
                        s.regions, s.regions_processed);
  std::cout << format(
      "  attempts %d: %d force closure, %d not FC, %d one contact, %d no contact, %d cannot "
      "retreat, %d touched from inside\n",
      s.attempts, s.force_closure, s.not_force_closure, s.one_contact, s.no_contact,
      s.cannot_retreat, s.inside_object);
  if (s.sampled_attempts > 0)
    std::cout << format("  %d of them at sampled surface points, after the regions\n",
                        s.sampled_attempts);
  std::cout << format("  finger stage %.3f s, quality %.3f s, total %.3f s", s.finger_s,
                      s.quality_s, s.total_s);
  if (s.first_force_closure_s)
    std::cout << format(", first force-closure grasp after %.3f s", *s.first_force_closure_s);
  std::cout << (s.timed_out ? " (time limit reached)" : "") << '\n';
  for (size_t i = 0; i < doc.grasps.size(); ++i) {
    const Grasp& g = doc.grasps[i];
    std::cout << format("  grasp %zu: eps %.4g, alpha %.1f deg, %zu contacts", i, g.epsilon,
                        g.alpha_rad * 180.0 / M_PI, g.contacts.size());
    if (g.region_rank && g.chi_m2)
      std::cout << format(", region %d (chi %.3g m^2)", *g.region_rank, *g.chi_m2);
    else if (doc.planner == PlannerKind::kCord)
      std::cout << ", sampled surface point";
    if (doc.validation) {
      const GraspValidation& v = doc.validation->grasps[i];
      std::cout << format("; held in %d / %d trials, squeeze shift %.0f mm", v.held_trials,
                          v.trials, 1e3 * v.squeeze_shift_m);
    }
    std::cout << '\n';
  }
  if (doc.validation)
    std::cout << "  " << validation_stats_line(doc.validation->stats, doc.params.grasps) << '\n';
  else if (doc.grasps.empty())
    std::cout << "  no force-closure grasp found\n";
  std::cout << "wrote " << out << '\n';
}

void run_plan(const PlanOptions& opt) {
  check_output_file(opt.out);  // before minutes of planning, not after
  install_interrupt_handlers();
  const CancelToken cancel = interrupt_token();
  const std::string object_path = resolve_object_path(opt.object);
  const Mesh mesh = load_job_mesh(opt.job, object_path);
  const HandModel hand = load_hand(opt.hand);
  PlanDocument doc;
  if (opt.validate) {
    doc = validated_plan_job(opt.job, opt.validation, mesh, object_path, hand, opt.jobs,
                             [](const std::string& line) {
                               std::cerr << "plan: " << line << '\n';
                             },
                             cancel);
  } else {
    doc = plan_job(opt.job, mesh, object_path, hand, cancel, opt.jobs);
  }
  write_plan_file(opt.out, doc, hand);
  if (!opt.quiet) print_summary(doc, hand, opt.out);
  if (!doc.interrupted.empty()) {
    std::cout << "plan: interrupted by " << doc.interrupted << " after " << doc.grasps.size()
              << " of " << doc.params.grasps << " grasps (" << doc.stats.attempts
              << " attempts); " << opt.out << " holds those, marked incomplete\n";
    throw Interrupted("interrupted by " + doc.interrupted);
  }
  if (doc.grasps.empty())
    throw NoGraspFound(no_accepted_grasp_message("plan", doc, mesh) + ". Wrote " + opt.out);
}

}  // namespace


void add_plan_command(CLI::App& app) {
  auto opt = std::make_shared<PlanOptions>();
  CLI::App* cmd = app.add_subcommand(
      "plan", "Plan force-closure grasps with the cord planner (or the generic baseline)");
  cmd->add_option("--hand", opt->hand, "Hand description file or shipped hand name")
      ->capture_default_str();
  cmd->add_option("--object,-o", opt->object, "Object mesh file or shipped object name")->required();
  add_planner_option(cmd, opt->job);
  add_plan_job_options(cmd, opt->job);
  add_units_option(cmd, opt->job);
  add_plan_settings_option(cmd, opt->job, opt->validation);
  add_validate_option(cmd, &opt->validate, &opt->validation.protocol);
  add_uncertainty_options(cmd, opt->validation);
  cmd->add_option("--physics", opt->validation.physics_file,
                  std::string("--validate: ") + kPhysicsHelp);
  cmd->add_option("--jobs,-j", opt->jobs,
                  "Threads: a scan's set-up, the cord exploration's scans, and with --validate the "
                  "trials simulated at once (one physics world each); results do not depend on it")
      ->check(whole_number_in(1, 256))
      ->capture_default_str();
  cmd->add_option("--out", opt->out, "Output plan.json")->required();
  cmd->add_flag("--quiet,-q", opt->quiet, "No summary on stdout (warnings and errors only)");
  cmd->callback([opt]() { run_plan(*opt); });
}

}  // namespace cordgrasp::cli
