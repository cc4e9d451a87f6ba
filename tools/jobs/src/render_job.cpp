#include "cordgrasp/jobs/render_job.h"
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/render/contact_sheet.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/region_json.h"
#include "cordgrasp/jobs/render_options.h"

namespace cordgrasp {
namespace {

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

// Writes `image` to `path` and says so: "render: wrote out.png (1024x768, view iso)".
std::string write_picture(const std::string& path, const Image& image,
                          const RenderParams& params) {
  write_png(path, image);
  std::ostringstream line;
  line << "render: wrote " << path << " (" << image.width << "x" << image.height << ", view "
       << view_name(params.view.view) << ")";
  return line.str();
}

// Regions of `cordgrasp explore --json`: the object with one region's front cords and P1, P_l,
// P_r, or with --sheet N the N best regions as a contact sheet.
std::string run_render_regions(const RenderJobParams& opt, const Warn& /*warn*/) {
  std::ifstream in(opt.regions);
  if (!in) throw InputError("render: '" + opt.regions + "': cannot open");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("render: '" + opt.regions + "': not JSON: " + e.what());
  }
  if (!j.is_object() || !j.contains("regions") || !j["regions"].is_array())
    throw InputError("render: '" + opt.regions +
                     "': no \"regions\" list (write it with "
                     "cordgrasp explore --json)");
  std::vector<GraspRegion> regions;
  for (const auto& r : j["regions"]) {
    try {
      regions.push_back(region_from_json(r));
    } catch (const InputError& e) {
      throw InputError("render: '" + opt.regions + "': " + e.what());
    }
  }
  if (regions.empty()) throw InputError("render: '" + opt.regions + "': no regions to show");
  const std::string object_path =
      !opt.objects.empty() ? opt.objects[0] : j.value("object", std::string());
  if (object_path.empty())
    throw InputError("render: '" + opt.regions + "': no object; give --object");
  const MeshLoadOptions load = job_mesh_load_options(parse_length_units(opt.units), opt.scale);
  const auto object = std::make_shared<const Mesh>(load_mesh(object_path, load));
  const double radius = bounding_radius(*object, vertex_mean(*object));

  const int count = static_cast<int>(regions.size());
  const int first = opt.sheet > 0 ? 1 : opt.region;
  const int last = opt.sheet > 0 ? std::min(count, opt.sheet) : opt.region;
  if (first < 1 || first > count)
    throw InputError("render: --region " + std::to_string(opt.region) + ": '" + opt.regions +
                     "' has regions 1.." + std::to_string(count));
  PictureOptions picture = opt.picture;
  if (picture.view.empty()) picture.view = "approach";  // shows the cords best
  OverlayStyle style;
  style.p1 = picture.view != "approach";  // P1 would sit in front of the camera
  Renderer renderer;
  std::vector<Image> tiles;
  std::vector<std::string> captions;
  RenderParams params;
  for (int k = first; k <= last; ++k) {
    const GraspRegion& r = regions[k - 1];
    Scene scene;
    add_object(scene, object);
    add_region_overlay(scene, r, Eigen::Isometry3d::Identity(), radius, style);
    const std::string chi = "χ = " + fixed(r.chi_m2 * 1e6, 1) + " mm²";
    const std::string kind = std::string("case ") + (r.cord_case == CordCase::kI ? "I" : "II") +
                             " · n = " + std::to_string(r.n);
    const std::string what = "region " + std::to_string(k) + "/" + std::to_string(count) + " · " +
                             chi + " · " + kind + " · ξ = " + fixed(r.xi_m * 1e3, 1) + " mm";
    const std::string tile = "#" + std::to_string(k) + " · " + chi + " · " + kind;
    scene.caption = opt.sheet > 0 ? "" : object->name + " · " + what;
    params = render_params(picture, scene, r.p_m - r.p1);  // approach: P1 → P_m (§7.2)
    if (opt.sheet > 0) {
      captions.push_back(opt.picture.no_caption ? "" : tile);
      scene.caption.clear();
    }
    tiles.push_back(renderer.render(scene, params));
  }
  ContactSheetParams sheet;
  if (!opt.picture.no_caption)
    sheet.title = object->name + " · cord exploration · " + std::to_string(count) +
                  " regions, best " + std::to_string(tiles.size()) + " by χ";
  const Image image = opt.sheet > 0 ? compose_contact_sheet(tiles, captions, sheet) : tiles[0];
  return write_picture(opt.out, image, params);
}

// Objects: one picture, or with several --object a contact sheet of one tile (--size) each.
std::string run_render_objects(const RenderJobParams& opt, const Warn& /*warn*/) {
  const MeshLoadOptions load = job_mesh_load_options(parse_length_units(opt.units), opt.scale);
  Renderer renderer;
  std::vector<Image> tiles;
  std::vector<std::string> captions;
  RenderParams params;
  for (const std::string& path : opt.objects) {
    auto object = std::make_shared<const Mesh>(load_mesh(path, load));
    Scene scene;
    add_object(scene, object);
    const std::string caption =
        object->name + " · " + std::to_string(object->triangles.size()) + " triangles";
    scene.caption = opt.objects.size() == 1 ? caption : "";
    params = render_params(opt.picture, scene);
    if (opt.objects.size() > 1) {
      captions.push_back(scene.caption.empty() && !opt.picture.no_caption ? caption : "");
      scene.caption.clear();
    }
    tiles.push_back(renderer.render(scene, params));
  }
  const Image image = tiles.size() == 1 ? tiles[0] : compose_contact_sheet(tiles, captions);
  return write_picture(opt.out, image, params);
}

// A hand alone at a configuration: preshape, partly closed (--close) and/or --joint values.
std::string run_render_hand(const RenderJobParams& opt, const Warn& /*warn*/) {
  const HandModel hand = load_hand(opt.hand, opt.hand_load);
  Eigen::VectorXd q = closing_configuration(hand, opt.close);
  for (const std::string& text : opt.joints) {
    const size_t eq = text.find('=');
    const std::string name = text.substr(0, eq);
    const int j = find_joint(hand, name);
    double value = 0.0;
    try {
      if (eq == std::string::npos) throw std::invalid_argument("no '='");
      size_t used = 0;
      value = std::stod(text.substr(eq + 1), &used);
      if (used != text.size() - eq - 1) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
      throw InputError("--joint '" + text + "': expected NAME=VALUE (rad or m)");
    }
    if (j < 0)
      throw InputError("--joint '" + text + "': hand '" + hand.name + "' has no joint '" + name +
                       "'");
    q[j] = value;
  }
  q = clamp_to_limits(hand, apply_couplings(hand, q));
  HandStyle style;
  style.collision = opt.collision;
  style.visual = !opt.no_visual;
  if (!style.visual && !style.collision)
    throw InputError("render: --no-visual needs --collision (nothing would be drawn)");
  const auto X_WL = link_poses(hand, q);
  Scene scene;
  add_hand(scene, make_hand_meshes(hand, style), X_WL);
  std::ostringstream caption;
  caption << hand.name << " · " << degrees_of_freedom(hand) << " DOF · "
          << (opt.close > 0.0 ? "closed " + std::to_string(int(std::lround(100 * opt.close))) + " %"
                              : std::string("preshape"))
          << (opt.joints.empty() ? "" : " + --joint") << (style.collision ? " · collision" : "");
  scene.caption = caption.str();
  const Eigen::Vector3d approach_W = gcp_pose(hand, X_WL).linear().col(2);
  const RenderParams params = render_params(opt.picture, scene, approach_W);
  Renderer renderer;
  write_png(opt.out, renderer.render(scene, params));
  std::ostringstream line;
  line << "render: wrote " << opt.out << " (" << params.width_px << "x" << params.height_px
            << ", view " << view_name(params.view.view) << ")";
  return line.str();
}

// The cord planner's regions, recomputed from the parameters a plan recorded (exploration is
// deterministic for a seed unless its time limit was hit), in the planner's processing order.
// Empty, with a warning, when they cannot be rebuilt.
std::vector<GraspRegion> replay_exploration(const PlanDocument& plan, const Mesh& mesh,
                                           const Warn& warn) {
  if (plan.planner != PlannerKind::kCord || !plan.cord) return {};
  try {
    const CordParams& cord = *plan.cord;  // every field as planned
    std::vector<GraspRegion> regions = explore_cords(mesh, plan.palm_width_m, cord);
    std::vector<GraspRegion> ordered;
    for (int i : cord_region_order(regions, plan.palm_width_m, cord))
      ordered.push_back(regions[i]);
    return ordered;
  } catch (const std::exception& e) {
    if (warn)
      warn(std::string("cannot replay the cord exploration of the plan (") + e.what() +
           "); cords are not drawn");
    return {};
  }
}

// The region grasp `g` came from, if the replayed exploration reproduces its χ exactly.
const GraspRegion* region_of(const Grasp& g, const std::vector<GraspRegion>& regions) {
  if (!g.region_rank || *g.region_rank < 0 || *g.region_rank >= static_cast<int>(regions.size()))
    return nullptr;
  const GraspRegion& r = regions[*g.region_rank];
  constexpr double kChiRelTol = 1e-9;
  if (g.chi_m2 && std::abs(r.chi_m2 - *g.chi_m2) > kChiRelTol * std::abs(*g.chi_m2)) return nullptr;
  return &r;
}

// A plan: grasp K (object frame as world) with the hand, contacts and the cords of its region,
// or with --sheet N the first N grasps as a contact sheet.
std::string run_render_plan(const RenderJobParams& opt, const Warn& warn) {
  const nlohmann::json json = read_plan_json(opt.plan);
  const HandModel hand = load_hand(plan_hand_path(json), opt.hand_load);
  const PlanDocument plan = plan_from_json(json, hand, opt.plan);  // errors name the file
  const int count = static_cast<int>(plan.grasps.size());
  if (count == 0) throw InputError("render: '" + opt.plan + "': the plan holds no grasp");
  const int first = opt.sheet > 0 ? 0 : opt.grasp;
  const int last = opt.sheet > 0 ? std::min(count, opt.sheet) - 1 : opt.grasp;
  if (first < 0 || first >= count)
    throw InputError("render: --grasp " + std::to_string(opt.grasp) + ": '" + opt.plan +
                     "' has grasps 0.." + std::to_string(count - 1));
  const MeshLoadOptions load =
      job_mesh_load_options(parse_length_units(plan.object_units), plan.object_scale);
  const auto object = std::make_shared<const Mesh>(load_mesh(plan.object_path, load));
  bool stored_regions = true;  // every grasp carries its region: no need to replay
  for (int k = first; k <= last; ++k) stored_regions &= plan.grasps[k].region.has_value();
  const std::vector<GraspRegion> regions = opt.no_cords || stored_regions
                                               ? std::vector<GraspRegion>{}
                                               : replay_exploration(plan, *object, warn);

  HandStyle hand_style;
  hand_style.collision = opt.collision;
  hand_style.visual = !opt.no_visual;
  if (!hand_style.visual && !hand_style.collision)
    throw InputError("render: --no-visual needs --collision (nothing would be drawn)");
  const HandMeshes meshes = make_hand_meshes(hand, hand_style);
  OverlayStyle overlay;
  overlay.friction_cones = opt.cones;
  overlay.friction_coefficient = plan_contact_model(plan).mu;
  overlay.cords = !opt.no_cords;
  overlay.p1 = opt.picture.view != "approach";
  const std::string who = plan.object_name + " · " + plan.hand_name + " · " + to_string(plan.planner);

  Renderer renderer;
  std::vector<Image> tiles;
  std::vector<std::string> captions;
  RenderParams params;
  int missing_cords = 0;
  for (int k = first; k <= last; ++k) {
    const Grasp& g = plan.grasps[k];
    // A region stored with the grasp wins over the replayed exploration.
    const GraspRegion* region =
        opt.no_cords ? nullptr : g.region ? &*g.region : region_of(g, regions);
    missing_cords += g.region_rank && !region && !opt.no_cords;
    Scene scene = grasp_scene(hand, meshes, object, g, region, overlay);
    const std::string quality = "α = " + fixed(g.alpha_rad, 3) +
                                " rad · ε = " + fixed(g.epsilon, 4) +
                                (g.force_closure ? " · force closure" : " · not force closure");
    scene.caption =
        who + " · grasp " + std::to_string(k) + " of " + std::to_string(count) + " · " + quality;
    params = render_params(opt.picture, scene, g.X_OG.linear().col(2));  // approach: GCP +z
    if (opt.sheet > 0) {
      captions.push_back(opt.picture.no_caption
                             ? ""
                             : "#" + std::to_string(k) + " · α = " + fixed(g.alpha_rad, 2) +
                                   " rad · ε = " + fixed(g.epsilon, 4));
      scene.caption.clear();
    }
    tiles.push_back(renderer.render(scene, params));
  }
  if (missing_cords > 0)
    if (warn)
      warn("the replayed exploration did not reproduce the region of " +
           std::to_string(missing_cords) +
           " grasp(s) (time limit hit while planning?); their cords are not drawn");
  ContactSheetParams sheet;
  if (!opt.picture.no_caption)
    sheet.title = who + " · first " + std::to_string(tiles.size()) + " of " +
                  std::to_string(count) + " grasps";
  const Image image = opt.sheet > 0 ? compose_contact_sheet(tiles, captions, sheet) : tiles[0];
  return write_picture(opt.out, image, params);
}

}  // namespace

std::string render_job(const RenderJobParams& opt, const Warn& warn) {
  const int modes = !opt.plan.empty() + !opt.regions.empty() + !opt.hand.empty() +
                    (opt.plan.empty() && opt.regions.empty() && !opt.objects.empty());
  if (modes != 1)
    throw InputError(
        "render: give one of --plan FILE, --object FILE..., --hand HAND or --regions FILE");
  if (opt.plan.empty() && opt.regions.empty() && opt.sheet > 0)
    throw InputError("render: --sheet needs --plan or --regions");
  if (opt.regions.empty() && opt.region != 1) throw InputError("render: --region needs --regions");
  if (opt.plan.empty() && opt.grasp != 0) throw InputError("render: --grasp needs --plan");
  if (!opt.plan.empty() && !opt.objects.empty())
    throw InputError("render: --plan names its object; drop --object");
  if (!opt.regions.empty() && opt.objects.size() > 1)
    throw InputError("render: --regions takes at most one --object");
  check_output_file(opt.out);
  if (!opt.plan.empty()) return run_render_plan(opt, warn);
  if (!opt.regions.empty()) return run_render_regions(opt, warn);
  if (!opt.hand.empty()) return run_render_hand(opt, warn);
  return run_render_objects(opt, warn);
}


}  // namespace cordgrasp
