#pragma once
// Turns hands, objects, plans and simulation frames into render Scenes (tools side: the
// render library knows nothing of hands or planners).
#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/grasp_region.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/render/renderer.h"
#include "cordgrasp/render/scene.h"

namespace cordgrasp {

/// Which hand geometry a picture shows.
struct HandStyle {
  bool visual = true;             ///< the links' visual geometry (meshes and primitives)
  bool collision = false;         ///< the collision shapes: translucent over visual, opaque alone
  double collision_alpha = 0.35;  ///< opacity of collision shapes drawn over visual geometry
};

/// Colour of each link: one colour per finger (hand_fingers: the links an actor moves), the
/// thumb's first; palm and other unactuated links dark slate grey.
std::vector<Rgba> hand_link_colors(const HandModel& hand);

/// Joint vector between the preshape (0) and every actor joint at the limit it closes toward
/// (1): q = preshape + fraction · (limit − preshape), the limit being the upper one for a
/// positive actor speed, the lower one otherwise; couplings applied, clamped to limits.
/// For pictures of hands, not a grasp (no contact is sought).
Eigen::VectorXd closing_configuration(const HandModel& hand, double fraction);

/// Render-ready meshes of a hand's geometry: primitives tessellated once, meshes shared, so
/// many frames of one hand reuse the renderer's GPU copies.
struct HandMeshes {
  struct Part {
    int link = -1;
    std::shared_ptr<const Mesh> mesh;                        ///< in the geometry frame [m]
    Eigen::Isometry3d X_LG = Eigen::Isometry3d::Identity();  ///< geometry in link frame
    Rgba rgba;
  };
  std::vector<Part> parts;
};

/// Meshes of `hand` in `style`, coloured by hand_link_colors.
HandMeshes make_hand_meshes(const HandModel& hand, const HandStyle& style = {});

/// Adds the hand at world link poses X_WL (from link_poses) to `scene`.
/// @throws std::invalid_argument when X_WL has the wrong size.
void add_hand(Scene& scene, const HandMeshes& hand, const std::vector<Eigen::Isometry3d>& X_WL);

/// Neutral grey of objects.
Rgba object_color();

/// Adds an object mesh (neutral grey, smooth shading) at pose X_WO.
void add_object(Scene& scene, std::shared_ptr<const Mesh> object,
                const Eigen::Isometry3d& X_WO = Eigen::Isometry3d::Identity());

/// How planner overlays are drawn; sizes relative to the object's bounding radius r.
struct OverlayStyle {
  bool cords = true;                  ///< the region's front cords as thick polylines
  bool region_points = true;          ///< P_l, P_r (and P1) as small spheres
  bool p1 = true;                     ///< P1 too (off when looking along P1 → P_m)
  bool contacts = true;               ///< contact points as spheres
  bool contacts_on_top = true;        ///< contacts drawn over the hand (they lie under fingers)
  bool friction_cones = false;        ///< cones (half-angle atan μ) instead of normal arrows
  double friction_coefficient = 0.5;  ///< μ for the cones
  double cord_width_px = 2.5;         ///< side cords; the seed cord is 1.6× wider
  double point_radius_rel = 0.035;    ///< P_l, P_r, P1 sphere radius / r
  double contact_radius_rel = 0.05;   ///< contact sphere radius / r
  double normal_length_rel = 0.45;    ///< arrow or cone height / r
};

/// Adds a region's front cords (coloured from cool to warm across the scan, the seed cord
/// wider) and P1 (dark), P_l (magenta, thumb side), P_r (teal, index side), all given in the
/// object frame, placed by X_WO. `object_radius_m` sets sphere sizes.
void add_region_overlay(Scene& scene, const GraspRegion& region, const Eigen::Isometry3d& X_WO,
                        double object_radius_m, const OverlayStyle& style = {});

/// Adds a grasp's contacts (object frame) as spheres with normal arrows or friction cones.
void add_contact_overlay(Scene& scene, const std::vector<Contact>& contacts,
                         const Eigen::Isometry3d& X_WO, double object_radius_m,
                         const OverlayStyle& style = {});

/// A planned grasp in the object frame (world = object): the object, the hand at
/// grasp.X_OB with joints grasp.q (couplings applied), the grasp's contacts and, if given, the
/// region's cords and points. Caption and ground are left to the caller.
/// @throws std::invalid_argument when grasp.q does not fit the hand.
Scene grasp_scene(const HandModel& hand, const HandMeshes& meshes,
                  std::shared_ptr<const Mesh> object, const Grasp& grasp,
                  const GraspRegion* region = nullptr, const OverlayStyle& style = {});

/// The camera that frames what matters in a grasp picture: the object at X_WO and the hand's
/// fingers (hand_fingers: the links actors move) at link poses X_WL fill the view of
/// `params` (its view direction, size, margin) in a picture with a caption band when
/// `captioned`; the palm and the arm may be cut.
/// @throws std::invalid_argument when X_WL does not fit the hand.
Camera frame_on_grasp(const HandModel& hand, const HandMeshes& meshes,
                      std::shared_ptr<const Mesh> object, const Eigen::Isometry3d& X_WO,
                      const std::vector<Eigen::Isometry3d>& X_WL, const RenderParams& params,
                      bool captioned);

/// One picture of a simulation or plan: the hand's world link poses and the object's pose.
struct SnapshotFrame {
  std::vector<Eigen::Isometry3d> X_WL;  ///< one pose per HandModel link (from link_poses)
  Eigen::Isometry3d X_WO = Eigen::Isometry3d::Identity();
  std::string caption;  ///< e.g. "settled · mug · schunk_sah"
  std::string name;     ///< file name part, e.g. "settled" (write_snapshots)
};

/// Renders each frame of one hand and object with a single camera framed on all frames
/// together (so lift and shake motions show), ground shadow on. For `validate --snapshots`.
/// `params.camera`, if set, is used as is. @throws as Renderer::render.
std::vector<Image> render_snapshots(Renderer& renderer, const HandModel& hand,
                                    std::shared_ptr<const Mesh> object,
                                    const std::vector<SnapshotFrame>& frames,
                                    const RenderParams& params, const HandStyle& style = {});

/// render_snapshots, then writes frame i to <dir>/<stem>_<frames[i].name>.png (or
/// <stem>_<i>.png when the name is empty; characters other than letters, digits, '-', '+' and
/// '.' become '_'), atomically; returns the paths in frame order.
/// @throws InputError when `dir` does not exist or a file cannot be written.
std::vector<std::string> write_snapshots(Renderer& renderer, const HandModel& hand,
                                         std::shared_ptr<const Mesh> object,
                                         const std::vector<SnapshotFrame>& frames,
                                         const std::string& dir, const std::string& stem,
                                         const RenderParams& params, const HandStyle& style = {});

}  // namespace cordgrasp
