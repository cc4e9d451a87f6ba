#include "cordgrasp/jobs/export_job.h"

#include <filesystem>
#include <optional>
#include <stdexcept>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_volume.h"
#include "cordgrasp/jobs/export_mesh.h"
#include "cordgrasp/jobs/export_mjcf.h"
#include "cordgrasp/jobs/export_moveit.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/sim/convex_decomposition.h"
#include "cordgrasp/sim/validate_grasp.h"

namespace cordgrasp {

namespace fs = std::filesystem;

/// Convex parts at most this large are flat for MuJoCo [m³] (a 0.1 mm cube is 1e-12 m³).
constexpr double kFlatPartVolume_m3 = 1e-12;

const char* to_string(ExportFormat format) {
  switch (format) {
    case ExportFormat::kMjcf: return "mjcf";
    case ExportFormat::kMoveit: return "moveit";
    case ExportFormat::kGlb: return "glb";
    case ExportFormat::kObj: return "obj";
  }
  return "?";
}

ExportFormat parse_export_format(const std::string& text) {
  for (ExportFormat f :
       {ExportFormat::kMjcf, ExportFormat::kMoveit, ExportFormat::kGlb, ExportFormat::kObj})
    if (text == to_string(f)) return f;
  throw std::invalid_argument("'" + text + "' is not mjcf, moveit, glb or obj");
}

ExportOutcome export_job(const ExportJobParams& p) {
  const nlohmann::json json = read_plan_json(p.plan);
  const HandModel hand = load_hand(plan_hand_path(json), p.hand_load);
  const PlanDocument plan = plan_from_json(json, hand, p.plan);
  std::vector<Grasp> grasps = plan.grasps;
  if (p.grasps >= 0 && static_cast<size_t>(p.grasps) < grasps.size()) grasps.resize(p.grasps);

  ExportOutcome out;
  out.grasps = static_cast<int>(grasps.size());
  const fs::path out_path(p.out);
  if (p.format == ExportFormat::kMjcf || p.format == ExportFormat::kMoveit) {
    std::error_code ec;
    if (out_path.has_parent_path() && !fs::is_directory(out_path.parent_path(), ec))
      throw InputError("export: --out '" + p.out + "': folder '" +
                       out_path.parent_path().string() + "' does not exist");
  }
  if (p.format == ExportFormat::kMoveit) {
    write_file_atomically(p.out, moveit_grasps_yaml(hand, grasps));
    out.files.push_back(p.out);
    return out;
  }

  const MeshLoadOptions mesh_opt =
      job_mesh_load_options(parse_length_units(plan.object_units), plan.object_scale);
  const Mesh object = load_mesh(plan.object_path, mesh_opt);
  if (p.format == ExportFormat::kMjcf) {
    // The bounded close of every grasp as `cordgrasp validate` (protocol standard) runs it.
    SimParams sim = sim_params_for(Protocol::kStandard);
    sim.contact = plan_contact_model(plan);
    apply_sim_overrides(sim_overrides_or(p.physics, plan.validation
                                                        ? plan.validation->params.physics
                                                        : SimOverrides{}),
                        &sim);
    sim.decomposition_cache_dir = p.cache_dir;
    std::vector<BoundedClose> closes;
    for (const Grasp& g : grasps) closes.push_back(bounded_close(object, hand, g, sim));
    // The object's shape as Bullet's: one hull where Bullet uses one, else the parts of the
    // convex decomposition.
    std::vector<std::vector<Eigen::Vector3d>> candidate_parts;
    if (!closes.empty() && closes.front().object.shape == ObjectShape::kConvexHull)
      candidate_parts.push_back(object.vertices);
    else
      candidate_parts =
          cached_convex_decomposition(object, DecompositionParams{}, p.cache_dir)->parts;
    // Mass as in Bullet (docs/physics.md §2): density × closed volume (hull volume for open
    // meshes), or the simulated object's mass; MuJoCo sums the parts' hulls, which overlap and
    // fill cavities, so the geoms' density is scaled to give that mass.
    MjcfParams mjcf;
    const std::optional<SolidVolume> closed = closed_mesh_volume(object);
    const double volume_m3 = closed ? closed->volume_m3 : convex_hull_volume(object).volume_m3;
    // Flat parts (a single face, a planar sheet) are dropped: MuJoCo's qhull refuses them.
    std::vector<std::vector<Eigen::Vector3d>> solid_parts;
    double parts_m3 = 0.0;
    for (const auto& part : candidate_parts) {
      Mesh hull;
      hull.vertices = part;
      // convex_hull_volume reads the vertices that triangles use: a fan over all of them.
      for (int i = 2; i < static_cast<int>(part.size()); ++i) hull.triangles.emplace_back(0, 1, i);
      const double v = part.size() >= 4 ? convex_hull_volume(hull).volume_m3 : 0.0;
      if (v <= kFlatPartVolume_m3) continue;
      solid_parts.push_back(part);
      parts_m3 += v;
    }
    if (solid_parts.empty())
      throw InputError("export: '" + plan.object_path +
                       "': the object is flat (no convex part with volume); MuJoCo needs one");
    if (!closes.empty() && parts_m3 > 0.0)
      mjcf.density_kgm3 = closes.front().object.mass_kg / parts_m3;
    else if (volume_m3 > 0.0 && parts_m3 > 0.0)
      mjcf.density_kgm3 *= volume_m3 / parts_m3;
    out.files = write_mjcf_scene(p.out, hand, grasps, plan_contact_model(plan), solid_parts, mjcf,
                                 closes, sim);
    return out;
  }

  std::error_code ec;
  fs::create_directories(out_path, ec);
  if (ec) throw InputError("export: cannot create '" + p.out + "': " + ec.message());
  const bool glb = p.format == ExportFormat::kGlb;
  for (size_t k = 0; k < grasps.size(); ++k) {
    const std::string file =
        (out_path / ("grasp_" + std::to_string(k) + (glb ? ".glb" : ".obj"))).string();
    write_grasp_mesh(file, glb ? "glb2" : "obj", hand, grasps[k], object);
    out.files.push_back(file);
  }
  return out;
}

}  // namespace cordgrasp
