#include "cordgrasp/jobs/hand_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_fingers.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/shapes.h"
#include "cordgrasp/render/png_io.h"

namespace cordgrasp {
namespace {

// Muted, colour-blind-distinguishable finger colours (thumb first).
const Rgba kFingerPalette[] = {
    Rgba(0.92, 0.58, 0.20, 1.0),  // orange
    Rgba(0.26, 0.53, 0.84, 1.0),  // blue
    Rgba(0.30, 0.68, 0.46, 1.0),  // green
    Rgba(0.66, 0.45, 0.78, 1.0),  // purple
    Rgba(0.86, 0.38, 0.36, 1.0),  // red
    Rgba(0.90, 0.78, 0.28, 1.0),  // yellow
};
const Rgba kPalm(0.42, 0.44, 0.49, 1.0);

std::shared_ptr<const Mesh> geometry_mesh(const Geometry& g) {
  switch (g.kind) {
    case Geometry::Kind::kBox:
      return std::make_shared<const Mesh>(make_box_mesh(g.box_size_m));
    case Geometry::Kind::kCylinder:
      return std::make_shared<const Mesh>(make_cylinder_mesh(g.radius_m, g.length_m, 32));
    case Geometry::Kind::kSphere:
      return std::make_shared<const Mesh>(make_sphere_mesh(g.radius_m, 16, 32));
    case Geometry::Kind::kMesh:
      return g.mesh;
  }
  return nullptr;
}

// Linear blend of two colours, t ∈ [0, 1].
Rgba lerp(const Rgba& a, const Rgba& b, double t) { return a + t * (b - a); }

}  // namespace

std::vector<Rgba> hand_link_colors(const HandModel& hand) {
  std::vector<Rgba> rgba(hand.links.size(), kPalm);
  std::vector<Finger> fingers = hand_fingers(hand);
  // The thumb takes the first palette colour, the other fingers follow in actor order.
  std::stable_partition(fingers.begin(), fingers.end(), [](const Finger& f) { return f.is_thumb; });
  constexpr int kPaletteSize = sizeof(kFingerPalette) / sizeof(kFingerPalette[0]);
  for (size_t i = 0; i < fingers.size(); ++i)
    for (int l : fingers[i].links)
      if (l >= 0 && l < static_cast<int>(rgba.size())) rgba[l] = kFingerPalette[i % kPaletteSize];
  return rgba;
}

Eigen::VectorXd closing_configuration(const HandModel& hand, double fraction) {
  Eigen::VectorXd q = hand.preshape.size() == static_cast<Eigen::Index>(hand.joints.size())
                          ? hand.preshape
                          : Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  const Eigen::VectorXd q0 = q;
  for (const Actor& actor : hand.actors)
    for (const Actor::Entry& e : actor.joints) {
      if (e.joint < 0 || e.joint >= static_cast<int>(hand.joints.size())) continue;
      const Joint& j = hand.joints[e.joint];
      const double limit = e.direction_speed >= 0.0 ? j.upper : j.lower;
      if (std::isfinite(limit)) q[e.joint] = q0[e.joint] + fraction * (limit - q0[e.joint]);
    }
  return clamp_to_limits(hand, apply_couplings(hand, q));
}

HandMeshes make_hand_meshes(const HandModel& hand, const HandStyle& style) {
  const std::vector<Rgba> colors = hand_link_colors(hand);
  HandMeshes out;
  for (size_t l = 0; l < hand.links.size(); ++l) {
    const Link& link = hand.links[l];
    const auto add = [&](const std::vector<Geometry>& geometries, double alpha) {
      for (const Geometry& g : geometries) {
        auto mesh = geometry_mesh(g);
        if (!mesh || mesh->triangles.empty()) continue;
        HandMeshes::Part part;
        part.link = static_cast<int>(l);
        part.mesh = std::move(mesh);
        part.X_LG = g.X_LG;
        part.rgba = colors[l];
        part.rgba[3] = alpha;
        out.parts.push_back(std::move(part));
      }
    };
    if (style.visual) add(link.visuals, 1.0);
    if (style.collision) {
      const size_t first = out.parts.size();
      add(link.collisions, style.visual ? style.collision_alpha : 1.0);
      if (style.visual)  // a distinct translucent tint over the link colours
        for (size_t i = first; i < out.parts.size(); ++i)
          out.parts[i].rgba.head<3>() = Eigen::Vector3d(0.35, 0.85, 0.95);
    }
  }
  return out;
}

void add_hand(Scene& scene, const HandMeshes& hand, const std::vector<Eigen::Isometry3d>& X_WL) {
  for (const HandMeshes::Part& part : hand.parts) {
    if (part.link >= static_cast<int>(X_WL.size()))
      throw std::invalid_argument("add_hand: " + std::to_string(X_WL.size()) +
                                  " link poses for a hand with link " + std::to_string(part.link));
    add_mesh(scene, part.mesh, X_WL[part.link] * part.X_LG, part.rgba, Shading::kSmooth);
  }
}

Rgba object_color() { return Rgba(0.74, 0.74, 0.74, 1.0); }

void add_object(Scene& scene, std::shared_ptr<const Mesh> object, const Eigen::Isometry3d& X_WO) {
  add_mesh(scene, std::move(object), X_WO, object_color(), Shading::kSmooth);
}

void add_region_overlay(Scene& scene, const GraspRegion& region, const Eigen::Isometry3d& X_WO,
                        double object_radius_m, const OverlayStyle& style) {
  if (style.cords) {
    const int count = static_cast<int>(region.front_cords.size());
    const Rgba cool(0.15, 0.45, 0.85, 1.0), warm(0.85, 0.20, 0.45, 1.0);
    const Rgba seed(0.85, 0.10, 0.10, 1.0);
    for (int i = 0; i < count; ++i) {
      ScenePolyline line;
      for (const auto& p : region.front_cords[i]) line.p_W.push_back(X_WO * p);
      const bool is_seed = i == region.n;
      line.width_px = is_seed ? 1.6 * style.cord_width_px : style.cord_width_px;
      line.rgba = is_seed ? seed : lerp(cool, warm, count > 1 ? double(i) / (count - 1) : 0.5);
      scene.polylines.push_back(std::move(line));
    }
  }
  if (style.region_points) {
    const double r = style.point_radius_rel * object_radius_m;
    if (style.p1) scene.points.push_back({X_WO * region.p1, r, Rgba(0.15, 0.15, 0.15, 1.0)});
    scene.points.push_back({X_WO * region.p_l, r, Rgba(0.80, 0.20, 0.70, 1.0)});
    scene.points.push_back({X_WO * region.p_r, r, Rgba(0.10, 0.62, 0.62, 1.0)});
  }
}

void add_contact_overlay(Scene& scene, const std::vector<Contact>& contacts,
                         const Eigen::Isometry3d& X_WO, double object_radius_m,
                         const OverlayStyle& style) {
  if (!style.contacts) return;
  const Rgba contact_rgba(0.95, 0.80, 0.10, 1.0), normal_rgba(0.12, 0.12, 0.12, 1.0);
  const double r = style.contact_radius_rel * object_radius_m;
  const double length = style.normal_length_rel * object_radius_m;
  for (const Contact& c : contacts) {
    const Eigen::Vector3d p_W = X_WO * c.p_O;
    const Eigen::Vector3d n_W = X_WO.linear() * c.n_O;
    scene.points.push_back({p_W, r, contact_rgba, style.contacts_on_top});
    if (n_W.norm() == 0.0) continue;
    if (style.friction_cones) {
      SceneCone cone;
      cone.apex_W = p_W;
      cone.axis_W = n_W;  // opens outward, where the finger is
      cone.height_m = length;
      cone.half_angle_rad = std::atan(style.friction_coefficient);
      cone.rgba = Rgba(0.95, 0.70, 0.10, 0.35);
      cone.on_top = style.contacts_on_top;
      scene.cones.push_back(cone);
    } else {
      SceneArrow arrow;
      arrow.p_W = p_W;
      arrow.direction_W = n_W;
      arrow.length_m = length;
      arrow.shaft_radius_m = 0.2 * r;
      arrow.rgba = normal_rgba;
      arrow.on_top = style.contacts_on_top;
      scene.arrows.push_back(arrow);
    }
  }
}

Scene grasp_scene(const HandModel& hand, const HandMeshes& meshes,
                  std::shared_ptr<const Mesh> object, const Grasp& grasp, const GraspRegion* region,
                  const OverlayStyle& style) {
  if (grasp.q.size() != static_cast<Eigen::Index>(hand.joints.size()))
    throw std::invalid_argument("grasp_scene: joint vector has " + std::to_string(grasp.q.size()) +
                                " entries, hand '" + hand.name + "' has " +
                                std::to_string(hand.joints.size()) + " joints");
  Scene scene;
  double radius = 0.05;
  if (object) {
    radius = bounding_radius(*object, vertex_mean(*object));
    add_object(scene, object);
  }
  add_hand(scene, meshes, link_poses(hand, apply_couplings(hand, grasp.q), grasp.X_OB));
  if (region) add_region_overlay(scene, *region, Eigen::Isometry3d::Identity(), radius, style);
  add_contact_overlay(scene, grasp.contacts, Eigen::Isometry3d::Identity(), radius, style);
  return scene;
}

Camera frame_on_grasp(const HandModel& hand, const HandMeshes& meshes,
                      std::shared_ptr<const Mesh> object, const Eigen::Isometry3d& X_WO,
                      const std::vector<Eigen::Isometry3d>& X_WL, const RenderParams& params,
                      bool captioned) {
  std::vector<bool> finger_link(hand.links.size(), false);
  for (const Finger& f : hand_fingers(hand))
    for (const int l : f.links) finger_link[static_cast<size_t>(l)] = true;
  HandMeshes fingers;
  for (const HandMeshes::Part& part : meshes.parts)
    if (part.link >= 0 && part.link < static_cast<int>(finger_link.size()) &&
        finger_link[static_cast<size_t>(part.link)])
      fingers.parts.push_back(part);
  Scene focus;
  if (object) add_object(focus, std::move(object), X_WO);
  add_hand(focus, fingers.parts.empty() ? meshes : fingers, X_WL);  // no fingers: whole hand
  if (focus.meshes.empty()) add_hand(focus, meshes, X_WL);
  if (focus.meshes.empty()) throw std::invalid_argument("frame_on_grasp: nothing to frame");
  if (captioned) focus.caption = " ";  // the same caption band as the picture's
  return frame_scenes({focus}, params);
}

std::vector<Image> render_snapshots(Renderer& renderer, const HandModel& hand,
                                    std::shared_ptr<const Mesh> object,
                                    const std::vector<SnapshotFrame>& frames,
                                    const RenderParams& params, const HandStyle& style) {
  const HandMeshes meshes = make_hand_meshes(hand, style);
  std::vector<Scene> scenes(frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    Scene& scene = scenes[i];
    if (object) add_object(scene, object, frames[i].X_WO);
    add_hand(scene, meshes, frames[i].X_WL);
    scene.ground = Ground::kShadow;
    scene.caption = frames[i].caption;
  }
  // One floor (the lowest over all frames) and one camera for the whole series.
  if (!scenes.empty()) {
    double floor = std::numeric_limits<double>::infinity();
    for (const Scene& s : scenes)
      for (const auto& p : scene_extent_points(s))
        floor = std::min(floor, s.up_W.normalized().dot(p));
    for (Scene& s : scenes) s.floor_m = floor;
  }
  RenderParams p = params;
  if (!p.camera && !scenes.empty()) p.camera = frame_scenes(scenes, params);
  std::vector<Image> images;
  for (const Scene& s : scenes) images.push_back(renderer.render(s, p));
  return images;
}

std::vector<std::string> write_snapshots(Renderer& renderer, const HandModel& hand,
                                         std::shared_ptr<const Mesh> object,
                                         const std::vector<SnapshotFrame>& frames,
                                         const std::string& dir, const std::string& stem,
                                         const RenderParams& params, const HandStyle& style) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir)) throw InputError("snapshots: '" + dir + "' is not a directory");
  const std::vector<Image> images =
      render_snapshots(renderer, hand, std::move(object), frames, params, style);
  std::vector<std::string> paths;
  for (size_t i = 0; i < images.size(); ++i) {
    std::string name = frames[i].name.empty() ? std::to_string(i) : frames[i].name;
    for (char& c : name)  // "gravity6 -x" → "gravity6_-x": no spaces or slashes in file names
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '+' && c != '.')
        c = '_';
    paths.push_back((fs::path(dir) / (stem + "_" + name + ".png")).string());
    write_png(paths.back(), images[i]);
  }
  return paths;
}

}  // namespace cordgrasp
