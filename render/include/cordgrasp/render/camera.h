#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace cordgrasp {

/// A pinhole (or orthographic) camera looking from `eye_W` at `target_W`.
struct Camera {
  Eigen::Vector3d eye_W = Eigen::Vector3d(0.0, -1.0, 0.0);  ///< [m]
  Eigen::Vector3d target_W = Eigen::Vector3d::Zero();       ///< [m], on the optical axis
  Eigen::Vector3d up_W = Eigen::Vector3d::UnitZ();          ///< screen up, need not be ⟂ axis
  double fov_y_rad = 0.5235987755982988;  ///< vertical field of view (perspective) [rad]
  bool orthographic = false;
  double ortho_height_m = 1.0;  ///< visible height (orthographic) [m]
  double near_m = 0.01;         ///< near clip distance along the axis [m]
  double far_m = 100.0;         ///< far clip distance along the axis [m]
};

/// Named viewing directions, relative to the scene's up axis (z up: front looks along +y).
enum class View {
  kIso,       ///< from front-right-above, 35.26° elevation (isometric direction (1, −1, 1))
  kFront,     ///< looking along +y (from −y)
  kSide,      ///< looking along −x (from +x)
  kTop,       ///< looking down, screen up = +y
  kApproach,  ///< looking along ViewSpec::approach_dir_W (e.g. the hand's approach axis)
};

/// "iso", "front", "side", "top", "approach" → View. @throws std::invalid_argument otherwise.
View parse_view(const std::string& name);

/// Name of a view, as parse_view accepts it.
std::string view_name(View view);

/// How to frame a scene automatically.
struct ViewSpec {
  View view = View::kIso;
  Eigen::Vector3d approach_dir_W = Eigen::Vector3d::UnitZ();  ///< kApproach: viewing direction
  Eigen::Vector3d up_W = Eigen::Vector3d::UnitZ();            ///< world up
  double fov_y_rad = 0.5235987755982988;  ///< vertical field of view (30°) [rad]
  bool orthographic = false;
  double margin = 0.05;  ///< free border on each side, fraction of the image size, in [0, 0.4]
};

/// World direction the camera looks along for `spec` (unit).
Eigen::Vector3d view_direction(const ViewSpec& spec);

/// Camera looking along the view of `spec` that fits every point of `p_W` into an image of
/// aspect `aspect` (width/height) with the given margin, as tight as possible: the binding
/// image axis is filled, the other centred. @throws std::invalid_argument if `p_W` is empty.
Camera frame_points(const std::vector<Eigen::Vector3d>& p_W, const ViewSpec& spec, double aspect);

/// World-to-camera transform X_CW (OpenGL convention: camera looks along −z, y up).
Eigen::Isometry3d view_transform(const Camera& camera);

/// OpenGL projection matrix for `camera` and aspect (width/height).
Eigen::Matrix4d projection_matrix(const Camera& camera, double aspect);

/// Pixel coordinates (x right, y down, pixel centres at +0.5) of world point p_W in an image
/// of `width_px` × `height_px` rendered with `camera`.
Eigen::Vector2d project_to_pixel(const Camera& camera, int width_px, int height_px,
                                 const Eigen::Vector3d& p_W);

}  // namespace cordgrasp
