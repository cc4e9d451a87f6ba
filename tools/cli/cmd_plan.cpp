// `cordgrasp plan`: cord-driven (or generic baseline) grasp planning → plan.json.
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/palm_width.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/core/plan_generic_grasps.h"
#include "cordgrasp/core/version.h"
#include "cordgrasp/sim/bullet_hand_collider.h"
#include "plan_json.h"

namespace cordgrasp::cli {
namespace {

struct PlanOptions {
  std::string hand = default_hand_name();
  std::string object;
  std::string planner = "cord";
  int grasps = 1;
  double time_limit_s = 10.0;
  std::uint64_t seed = 1;
  double mu = kDefaultFrictionCoefficient;
  double soft_finger_radius_m = 0.0;
  std::string side_cords = "empty";
  std::string quality = "textbook";
  std::string units = "m";
  std::string out;
};

std::string absolute(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

nlohmann::json finger_params_json(const FingerParams& f) {
  return {{"approach_step_m", f.approach_step_m},
          {"retreat_step_m", f.retreat_step_m},
          {"max_retreat_steps", f.max_retreat_steps},
          {"close_step", f.close_step},
          {"contact_tolerance_m", f.contact_tolerance_m},
          {"max_close_iterations", f.max_close_iterations},
          {"min_contacts", f.min_contacts}};
}

nlohmann::json cord_params_json(const CordParams& c, double palm_width_m) {
  return {{"palm_width_m", palm_width_m},
          {"r2_margin_m", c.r2_margin_m},
          {"delta_r_m", c.delta_r_m},
          {"xi_min_m", c.xi_min_m},
          {"xi_max_m", c.xi_max_m},
          {"scan_angle_rad", c.scan_angle_rad},
          {"side_cords", c.side_cord_policy == SideCordPolicy::kDiscardSet ? "discard"
                         : c.side_cord_policy == SideCordPolicy::kShrink   ? "shrink"
                                                                           : "empty"},
          {"sphere_points", c.sphere_points},
          {"max_iterations", c.max_iterations},
          {"sets", c.sets},
          {"local_improvement", c.local_improvement},
          {"perturbations_per_set", c.perturbations_per_set},
          {"seed", c.seed},
          {"time_limit_s", c.time_limit_s}};
}

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
  std::cout << format("plan: %s planner, hand %s, object %s (%d triangles)\n", doc.planner.c_str(),
                      hand.name.c_str(), doc.object_name.c_str(), doc.object_triangles);
  if (doc.planner == "cord")
    std::cout << format("  exploration %.3f s: %d regions, %d processed\n", s.exploration_s,
                        s.regions, s.regions_processed);
  std::cout << format(
      "  attempts %d: %d force closure, %d not FC, %d one contact, %d no contact, %d cannot "
      "retreat\n",
      s.attempts, s.force_closure, s.not_force_closure, s.one_contact, s.no_contact,
      s.cannot_retreat);
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
    std::cout << '\n';
  }
  if (doc.grasps.empty()) std::cout << "  no force-closure grasp found\n";
  std::cout << "wrote " << out << '\n';
}

void run_plan(const PlanOptions& opt) {
  MeshLoadOptions load;
  load.units = parse_length_units(opt.units);
  const std::string object_path = absolute(opt.object);
  const Mesh mesh = load_mesh(object_path, load);
  const HandModel hand = load_hand(opt.hand);
  auto collider = make_bullet_hand_collider(hand, mesh);

  PlanParams params;
  params.grasps = opt.grasps;
  params.time_limit_s = opt.time_limit_s;
  params.seed = opt.seed;
  params.quality.contact.mu = opt.mu;
  params.quality.contact.soft_finger_radius_m = opt.soft_finger_radius_m;
  params.quality.mode = quality_mode_from_string(opt.quality);
  params.quality.seed = opt.seed;

  PlanDocument doc;
  doc.cordgrasp_version = version();
  doc.hand_name = hand.name;
  doc.hand_path = absolute(hand.description_path);
  doc.urdf_path = absolute(hand.urdf_path);
  doc.object_path = object_path;
  doc.object_name = mesh.name;
  doc.object_units = opt.units;
  doc.object_triangles = static_cast<int>(mesh.triangles.size());
  doc.planner = opt.planner;
  doc.parameters = {{"planner", opt.planner},
                    {"grasps", opt.grasps},
                    {"time_limit_s", opt.time_limit_s},
                    {"seed", opt.seed},
                    {"mu", opt.mu},
                    {"soft_finger_radius_m", opt.soft_finger_radius_m},
                    {"quality", opt.quality},
                    {"cone_edges", params.quality.contact.cone_edges},
                    {"min_epsilon", params.quality.min_epsilon},
                    {"simox",
                     {{"mu_eff", params.quality.simox_mu_eff},
                      {"fc_tolerance", params.quality.simox_fc_tolerance},
                      {"ows_faces", params.quality.simox_ows_faces}}},
                    {"roll_retry", params.roll_retry},
                    {"max_attempts", params.max_attempts},
                    {"finger", finger_params_json(params.finger)}};

  PlanResult result;
  if (opt.planner == "cord") {
    CordParams cord;
    cord.seed = opt.seed;
    cord.time_limit_s = opt.time_limit_s;
    cord.side_cord_policy = opt.side_cords == "discard"  ? SideCordPolicy::kDiscardSet
                            : opt.side_cords == "shrink" ? SideCordPolicy::kShrink
                                                         : SideCordPolicy::kEmptyWhenMissed;
    doc.parameters["cord"] = cord_params_json(cord, palm_width(hand));
    result = plan_cord_grasps(mesh, hand, *collider, cord, params);
  } else {
    result = plan_generic_grasps(mesh, hand, *collider, params);
  }
  doc.stats = result.stats;
  doc.grasps = std::move(result.grasps);
  write_plan_file(opt.out, doc, hand);
  print_summary(doc, hand, opt.out);
}

}  // namespace

void add_plan_command(CLI::App& app);
CORDGRASP_REGISTER_COMMAND(30, add_plan_command);

void add_plan_command(CLI::App& app) {
  auto opt = std::make_shared<PlanOptions>();
  CLI::App* cmd = app.add_subcommand(
      "plan", "Plan force-closure grasps with the cord planner (or the generic baseline)");
  cmd->add_option("--hand", opt->hand, "Hand description file or shipped hand name")
      ->capture_default_str();
  cmd->add_option("--object,-o", opt->object, "Object mesh file")->required();
  cmd->add_option("--planner", opt->planner, "cord (Li et al. 2015) or generic (Simox baseline)")
      ->check(CLI::IsMember({"cord", "generic"}))
      ->capture_default_str();
  cmd->add_option("--grasps,-n", opt->grasps, "Stop after this many force-closure grasps")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--time-limit", opt->time_limit_s, "Wall-clock limit of the plan [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--seed", opt->seed, "Seed of every random choice")->capture_default_str();
  cmd->add_option("--mu", opt->mu, "Friction coefficient of the wrench space (textbook mode)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--soft-finger-radius", opt->soft_finger_radius_m,
                  "Contact patch radius for torsional friction [m]; 0 = point contacts")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--side-cords", opt->side_cords,
                  "Cord: a scanned cord that fails: empty (missed object scores as empty), "
                  "discard (spec 4.5) or shrink (spec 11.6)")
      ->check(CLI::IsMember({"empty", "discard", "shrink"}))
      ->capture_default_str();
  cmd->add_option("--quality", opt->quality,
                  "textbook (real mu, eps = origin to hull) or simox (compat quirks, spec 8)")
      ->check(CLI::IsMember({"textbook", "simox"}))
      ->capture_default_str();
  cmd->add_option("--units", opt->units, "Units of the object file: m, mm or auto")
      ->check(CLI::IsMember({"m", "mm", "auto"}))
      ->capture_default_str();
  cmd->add_option("--out", opt->out, "Output plan.json")->required();
  cmd->callback([opt]() { run_plan(*opt); });
}

}  // namespace cordgrasp::cli
