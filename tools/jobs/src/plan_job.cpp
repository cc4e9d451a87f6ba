#include "cordgrasp/jobs/plan_job.h"

#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/palm_width.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/core/plan_generic_grasps.h"
#include "cordgrasp/core/version.h"

namespace cordgrasp {
std::string absolute_path(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

std::string mesh_cache_folder() {
  namespace fs = std::filesystem;
  if (const char* dir = std::getenv("CORDGRASP_MESH_CACHE"))
    return std::string(dir) == "off" ? std::string() : std::string(dir);
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg) return (fs::path(xdg) / "cordgrasp" / "meshes").string();
  const char* home = std::getenv("HOME");
  if (home && *home) return (fs::path(home) / ".cache" / "cordgrasp" / "meshes").string();
  return {};
}

MeshLoadOptions job_mesh_load_options(LengthUnits units, double scale) {
  MeshLoadOptions load;
  load.units = units;
  load.scale = scale;
  load.cache_folder = mesh_cache_folder();
  return load;
}

Mesh load_job_mesh(const PlanJobParams& p, const std::string& object_path) {
  const MeshLoadOptions load = job_mesh_load_options(p.units, p.scale);
  MeshLoadReport report;
  Mesh mesh = load_mesh(object_path, load, &report);
  if (report.auto_chose_mm)
    std::cerr << "cordgrasp: note: '" << object_path
              << "': --units auto read the file as millimetres\n";
  const double diagonal_m = mesh_bounds(mesh).size().norm();
  if (load.units == LengthUnits::kMeters && diagonal_m > load.auto_mm_diagonal)
    std::cerr << "cordgrasp: warning: '" << object_path << "' is " << diagonal_m
              << " m across: if the file is in millimetres, give --units mm (or auto; in a "
                 "settings file, units: mm)\n";
  return mesh;
}

namespace {

constexpr double kHugeObjectDiagonal_m = 5.0;  ///< larger: probably a millimetre file read as m

std::string fixed1(double v) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << v;
  return s.str();
}

}  // namespace

std::string no_grasp_message(const std::string& who, const PlanDocument& doc, const Mesh& mesh) {
  const PlanStats& s = doc.stats;
  std::string why = s.timed_out                ? "the --time-limit safety net fired"
                    : s.attempt_budget_reached ? "--max-attempts budget used up"
                                               : "every grasp region tried";
  std::string text = who + ": no force-closure grasp of " + doc.object_name + " with " +
                     doc.hand_name + " (" + to_string(doc.planner) + " planner, " +
                     std::to_string(s.attempts) + " attempts in " + fixed1(s.total_s) + " s, " +
                     why + "); try another --seed, another planner or a larger max_attempts (--settings)";
  const double diagonal_m = mesh_bounds(mesh).size().norm();
  if (diagonal_m > kHugeObjectDiagonal_m)
    text += "; the object is " + fixed1(diagonal_m) +
            " m across: if the file is in millimetres, give --units mm (or auto; in a settings "
            "file, units: mm)";
  return text;
}

ContactModel plan_contact_model(const PlanDocument& plan) { return plan.params.quality.contact; }

PlanDocument plan_document_for(const PlanJobParams& p, const Mesh& mesh,
                               const std::string& object_path, const HandModel& hand) {
  PlanParams params = p.plan;
  params.quality.contact.soft_finger_radius_m =
      p.soft_finger_radius_m.value_or(hand.soft_finger_radius_m);
  params.quality.seed = params.seed;

  PlanDocument doc;
  doc.cordgrasp_version = version();
  doc.hand_name = hand.name;
  doc.hand_path = absolute_path(hand.description_path);
  doc.urdf_path = absolute_path(hand.urdf_path);
  doc.object_path = absolute_path(object_path);
  doc.object_name = mesh.name;
  doc.object_units = to_string(p.units);
  doc.object_scale = p.scale;
  doc.object_triangles = static_cast<int>(mesh.triangles.size());
  doc.planner = p.planner;
  doc.params = params;
  doc.palm_width_m = palm_width(hand);
  if (p.planner == PlannerKind::kCord) {
    CordParams cord = p.cord;
    cord.seed = params.seed;
    cord.time_limit_s = params.time_limit_s;
    doc.cord = cord;
  }
  return doc;
}

PlanDocument plan_job(const PlanJobParams& p, const Mesh& mesh, const std::string& object_path,
                      const HandModel& hand, const CancelToken& cancel, int threads) {
  PlanDocument doc = plan_document_for(p, mesh, object_path, hand);
  BulletColliderParams collider_params;
  collider_params.threads = threads;
  auto collider = make_bullet_hand_collider(hand, mesh, collider_params);
  PlanResult result;
  if (p.planner == PlannerKind::kCord)
    result = plan_cord_grasps(mesh, hand, *collider, *doc.cord, doc.params, nullptr, cancel,
                              threads);
  else
    result = plan_generic_grasps(mesh, hand, *collider, doc.params, cancel);
  if (result.stats.interrupted) doc.interrupted = cancel.reason();
  doc.stats = result.stats;
  doc.grasps = std::move(result.grasps);
  return doc;
}

}  // namespace cordgrasp
