#include "plan_job.h"

#include <filesystem>
#include <iostream>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/palm_width.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/core/plan_generic_grasps.h"
#include "cordgrasp/core/version.h"

namespace cordgrasp::cli {
namespace {

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

}  // namespace

std::string absolute_path(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

void add_plan_job_options(CLI::App* cmd, PlanJobParams& p) {
  cmd->add_option("--planner", p.planner, "cord (Li et al. 2015) or generic (Simox baseline)")
      ->check(CLI::IsMember({"cord", "generic"}))
      ->capture_default_str();
  cmd->add_option("--grasps,-n", p.grasps, "Stop after this many force-closure grasps")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--time-limit", p.time_limit_s, "Wall-clock limit of the plan [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--seed", p.seed, "Seed of every random choice")->capture_default_str();
  cmd->add_option("--mu", p.mu, "Friction coefficient of the wrench space and the physics")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--soft-finger-radius", p.soft_finger_radius_m,
                  "Contact patch radius for torsional friction [m]; 0 = point contacts "
                  "(default: the hand's soft_finger_radius_m, 5 mm for the grippers)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--side-cords", p.side_cords,
                  "Cord: a scanned cord that fails: empty (missed object scores as empty), "
                  "discard (spec 4.5) or shrink (spec 11.6)")
      ->check(CLI::IsMember({"empty", "discard", "shrink"}))
      ->capture_default_str();
  cmd->add_option("--quality", p.quality,
                  "textbook (real mu, eps = origin to hull) or simox (compat quirks, spec 8)")
      ->check(CLI::IsMember({"textbook", "simox"}))
      ->capture_default_str();
  cmd->add_option("--units", p.units, "Units of the object file: m, mm or auto")
      ->check(CLI::IsMember({"m", "mm", "auto"}))
      ->capture_default_str();
  cmd->add_option("--sets", p.cord_sets, "Cord: valid sets to sample before local improvement")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_flag_callback(
      "--no-local-improvement", [&p]() { p.cord_local_improvement = false; },
      "Cord: skip the local improvement of the sampled sets");
}

Mesh load_job_mesh(const PlanJobParams& p, const std::string& object_path) {
  MeshLoadOptions load;
  load.units = parse_length_units(p.units);
  MeshLoadReport report;
  Mesh mesh = load_mesh(object_path, load, &report);
  if (report.auto_chose_mm)
    std::cerr << "cordgrasp: note: '" << object_path
              << "': --units auto read the file as millimetres\n";
  const double diagonal_m = mesh_bounds(mesh).size().norm();
  if (load.units == LengthUnits::kMeters && diagonal_m > load.auto_mm_diagonal)
    std::cerr << "cordgrasp: warning: '" << object_path << "' is " << diagonal_m
              << " m across: if the file is in millimetres, give --units mm (or auto)\n";
  return mesh;
}

ContactModel plan_contact_model(const PlanDocument& plan) {
  ContactModel c;
  c.mu = plan.parameters.value("mu", kDefaultFrictionCoefficient);
  c.soft_finger_radius_m = plan.parameters.value("soft_finger_radius_m", 0.0);
  return c;
}

PlanDocument plan_job(const PlanJobParams& p, const Mesh& mesh, const std::string& object_path,
                      const HandModel& hand) {
  auto collider = make_bullet_hand_collider(hand, mesh);

  PlanParams params;
  params.grasps = p.grasps;
  params.time_limit_s = p.time_limit_s;
  params.seed = p.seed;
  params.quality.contact.mu = p.mu;
  const double soft_finger_radius_m = p.soft_finger_radius_m.value_or(hand.soft_finger_radius_m);
  params.quality.contact.soft_finger_radius_m = soft_finger_radius_m;
  params.quality.mode = quality_mode_from_string(p.quality);
  params.quality.seed = p.seed;

  PlanDocument doc;
  doc.cordgrasp_version = version();
  doc.hand_name = hand.name;
  doc.hand_path = absolute_path(hand.description_path);
  doc.urdf_path = absolute_path(hand.urdf_path);
  doc.object_path = absolute_path(object_path);
  doc.object_name = mesh.name;
  doc.object_units = p.units;
  doc.object_triangles = static_cast<int>(mesh.triangles.size());
  doc.planner = p.planner;
  doc.parameters = {{"planner", p.planner},
                    {"grasps", p.grasps},
                    {"time_limit_s", p.time_limit_s},
                    {"seed", p.seed},
                    {"mu", p.mu},
                    {"soft_finger_radius_m", soft_finger_radius_m},
                    {"quality", p.quality},
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
  if (p.planner == "cord") {
    CordParams cord;
    cord.seed = p.seed;
    cord.time_limit_s = p.time_limit_s;
    cord.sets = p.cord_sets;
    cord.local_improvement = p.cord_local_improvement;
    cord.side_cord_policy = p.side_cords == "discard"  ? SideCordPolicy::kDiscardSet
                            : p.side_cords == "shrink" ? SideCordPolicy::kShrink
                                                         : SideCordPolicy::kEmptyWhenMissed;
    doc.parameters["cord"] = cord_params_json(cord, palm_width(hand));
    result = plan_cord_grasps(mesh, hand, *collider, cord, params);
  } else {
    result = plan_generic_grasps(mesh, hand, *collider, params);
  }
  doc.stats = result.stats;
  doc.grasps = std::move(result.grasps);
  return doc;
}

}  // namespace cordgrasp::cli
