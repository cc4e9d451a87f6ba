#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// RGBA colour, components in [0, 1].
using Rgba = Eigen::Vector4d;

/// How a mesh is lit.
enum class Shading {
  kSmooth,  ///< per-vertex normals, split at creases sharper than RenderParams::crease_angle_rad
  kFlat,    ///< one normal per triangle
  kUnlit,   ///< constant colour, no lighting (masks, tests)
};

/// A triangle mesh placed in the world. Meshes are drawn two-sided (soup orientation is
/// unreliable); colours with alpha < 1 are drawn translucent after the opaque ones.
struct SceneMesh {
  std::shared_ptr<const Mesh> mesh;  ///< treated as immutable while the scene is rendered
  Eigen::Isometry3d X_WM = Eigen::Isometry3d::Identity();  ///< mesh frame in world
  Rgba rgba = Rgba(0.72, 0.72, 0.72, 1.0);
  Shading shading = Shading::kSmooth;
  bool on_top = false;  ///< drawn over everything else (overlay layer)
};

/// A thick polyline of constant screen width, depth-tested as a tube of that width.
struct ScenePolyline {
  std::vector<Eigen::Vector3d> p_W;       ///< vertices in world [m]
  double width_px = 3.0;                  ///< on-screen width in output pixels
  Rgba rgba = Rgba(0.85, 0.1, 0.1, 1.0);  ///< alpha is ignored: lines are opaque
  bool closed = false;                    ///< joins the last vertex to the first
  bool on_top = false;                    ///< drawn over everything else (overlay layer)
};

/// A small shaded sphere marking a point.
struct ScenePoint {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();  ///< centre in world [m]
  double radius_m = 0.003;
  Rgba rgba = Rgba(0.1, 0.1, 0.1, 1.0);
  bool on_top = false;  ///< drawn over everything else (overlay layer)
};

/// An arrow from `p_W` along `direction_W` (contact normals): cylinder shaft plus cone head.
struct SceneArrow {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();           ///< tail in world [m]
  Eigen::Vector3d direction_W = Eigen::Vector3d::UnitZ();  ///< need not be unit
  double length_m = 0.02;                                  ///< tail to tip [m]
  double shaft_radius_m = 0.0008;
  Rgba rgba = Rgba(0.1, 0.1, 0.1, 1.0);
  bool on_top = false;  ///< drawn over everything else (overlay layer)
};

/// A circular cone surface without base (friction cones): apex at `apex_W`, opening along
/// `axis_W`, slant making `half_angle_rad` with the axis.
struct SceneCone {
  Eigen::Vector3d apex_W = Eigen::Vector3d::Zero();   ///< [m]
  Eigen::Vector3d axis_W = Eigen::Vector3d::UnitZ();  ///< need not be unit
  double height_m = 0.015;                            ///< apex to base along the axis [m]
  double half_angle_rad = 0.38;                       ///< atan(μ) for a friction cone
  Rgba rgba = Rgba(0.95, 0.6, 0.1, 0.35);
  bool on_top = false;  ///< drawn over everything else (overlay layer)
};

/// What is drawn under the scene.
enum class Ground {
  kNone,
  kShadow,  ///< soft contact shadow on an invisible floor below the scene's lowest point
  kGrid,    ///< light grid on the floor below the scene's lowest point
};

/// Everything one picture shows. Knows nothing of hands or planners.
struct Scene {
  std::vector<SceneMesh> meshes;
  std::vector<ScenePolyline> polylines;
  std::vector<ScenePoint> points;
  std::vector<SceneArrow> arrows;
  std::vector<SceneCone> cones;
  Ground ground = Ground::kNone;
  Eigen::Vector3d up_W = Eigen::Vector3d::UnitZ();  ///< world up: floor normal, screen up
  std::optional<double> floor_m;  ///< floor height along up_W [m]; default: lowest point
  std::string caption;  ///< UTF-8 text under the picture; '\n' separates lines; empty: none
};

/// Adds `mesh` (copied into shared ownership) at pose X_WM; returns the new entry.
SceneMesh& add_mesh(Scene& scene, Mesh mesh,
                    const Eigen::Isometry3d& X_WM = Eigen::Isometry3d::Identity(),
                    const Rgba& rgba = Rgba(0.72, 0.72, 0.72, 1.0),
                    Shading shading = Shading::kSmooth);

/// Adds a shared `mesh` at pose X_WM without copying; returns the new entry.
SceneMesh& add_mesh(Scene& scene, std::shared_ptr<const Mesh> mesh,
                    const Eigen::Isometry3d& X_WM = Eigen::Isometry3d::Identity(),
                    const Rgba& rgba = Rgba(0.72, 0.72, 0.72, 1.0),
                    Shading shading = Shading::kSmooth);

/// Every point the picture must contain: mesh vertices, polyline vertices, sphere, arrow and
/// cone extents, in world [m]; non-finite points are skipped. Used for auto-framing.
std::vector<Eigen::Vector3d> scene_extent_points(const Scene& scene);

/// Total number of mesh triangles in the scene (meshes only).
size_t scene_triangle_count(const Scene& scene);

}  // namespace cordgrasp
