#include "cordgrasp/render/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cordgrasp {
namespace {

// Right-handed world basis (right, forward, up) with `up` given; forward = +y for z up.
struct WorldBasis {
  Eigen::Vector3d right, forward, up;
};

WorldBasis world_basis(const Eigen::Vector3d& up_W) {
  WorldBasis b;
  b.up = up_W.norm() > 0.0 ? up_W.normalized() : Eigen::Vector3d::UnitZ();
  // Rotate the z-up basis so that z goes to `up` (minimal rotation), keeping the named views
  // meaningful for any up axis.
  const Eigen::Quaterniond R = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), b.up);
  b.right = R * Eigen::Vector3d::UnitX();
  b.forward = R * Eigen::Vector3d::UnitY();
  return b;
}

// Some unit vector not parallel to `d`, preferring `preferred`.
Eigen::Vector3d screen_up_for(const Eigen::Vector3d& d, const Eigen::Vector3d& preferred,
                              const Eigen::Vector3d& fallback) {
  constexpr double kParallelCos = 0.999;
  return std::abs(d.dot(preferred.normalized())) < kParallelCos ? preferred : fallback;
}

}  // namespace

View parse_view(const std::string& name) {
  if (name == "iso") return View::kIso;
  if (name == "front") return View::kFront;
  if (name == "side") return View::kSide;
  if (name == "top") return View::kTop;
  if (name == "approach") return View::kApproach;
  throw std::invalid_argument("unknown view '" + name +
                              "' (expected iso, front, side, top or approach)");
}

std::string view_name(View view) {
  switch (view) {
    case View::kIso:
      return "iso";
    case View::kFront:
      return "front";
    case View::kSide:
      return "side";
    case View::kTop:
      return "top";
    case View::kApproach:
      return "approach";
  }
  return "iso";
}

Eigen::Vector3d view_direction(const ViewSpec& spec) {
  const WorldBasis b = world_basis(spec.up_W);
  switch (spec.view) {
    case View::kIso:
      return (-b.right + b.forward - b.up).normalized();
    case View::kFront:
      return b.forward;
    case View::kSide:
      return -b.right;
    case View::kTop:
      return -b.up;
    case View::kApproach:
      if (spec.approach_dir_W.norm() == 0.0)
        throw std::invalid_argument("view_direction: zero approach direction");
      return spec.approach_dir_W.normalized();
  }
  return b.forward;
}

Camera frame_points(const std::vector<Eigen::Vector3d>& p_W, const ViewSpec& spec, double aspect) {
  if (p_W.empty()) throw std::invalid_argument("frame_points: no points to frame");
  if (!(aspect > 0.0)) throw std::invalid_argument("frame_points: aspect must be > 0");
  const WorldBasis b = world_basis(spec.up_W);
  const Eigen::Vector3d f = view_direction(spec);
  const Eigen::Vector3d up_hint =
      spec.view == View::kTop ? b.forward : screen_up_for(f, b.up, b.forward);
  const Eigen::Vector3d r = f.cross(up_hint).normalized();
  const Eigen::Vector3d u = r.cross(f);
  const double margin = std::clamp(spec.margin, 0.0, 0.4);

  Camera cam;
  cam.up_W = u;
  cam.orthographic = spec.orthographic;
  cam.fov_y_rad = spec.fov_y_rad;
  double z_min = std::numeric_limits<double>::infinity(), z_max = -z_min;
  for (const auto& p : p_W) {
    z_min = std::min(z_min, f.dot(p));
    z_max = std::max(z_max, f.dot(p));
  }
  const double depth = std::max(z_max - z_min, 1e-6);

  if (spec.orthographic) {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const auto& p : p_W) {
      x0 = std::min(x0, r.dot(p));
      x1 = std::max(x1, r.dot(p));
      y0 = std::min(y0, u.dot(p));
      y1 = std::max(y1, u.dot(p));
    }
    const double fill = 1.0 - 2.0 * margin;
    cam.ortho_height_m = std::max({(y1 - y0) / fill, (x1 - x0) / (fill * aspect), 1e-6});
    const Eigen::Vector3d center = 0.5 * (x0 + x1) * r + 0.5 * (y0 + y1) * u;
    const double standoff = depth + cam.ortho_height_m;
    cam.eye_W = center + (z_min - standoff) * f;
    cam.target_W = center + 0.5 * (z_min + z_max) * f;
    cam.near_m = standoff - 0.05 * depth;
    cam.far_m = standoff + 1.05 * depth;
    return cam;
  }

  // Perspective: camera at c = cx·r + cy·u + cz·f sees p iff |x − cx| ≤ tx·(z − cz) (and y).
  // For each axis the largest admissible cz is max over cx of min over p of
  // (z − |x − cx|/tx) = (a + b)/2 at cx = tx·(b − a)/2, with a = min(z − x/tx),
  // b = min(z + x/tx). The binding axis is tight, the other one is centred.
  const double ty = std::tan(0.5 * spec.fov_y_rad) * (1.0 - 2.0 * margin);
  const double tx = std::tan(0.5 * spec.fov_y_rad) * aspect * (1.0 - 2.0 * margin);
  if (!(ty > 0.0)) throw std::invalid_argument("frame_points: field of view must be > 0");
  double ax = std::numeric_limits<double>::infinity(), bx = ax, ay = ax, by = ax;
  for (const auto& p : p_W) {
    const double x = r.dot(p), y = u.dot(p), z = f.dot(p);
    ax = std::min(ax, z - x / tx);
    bx = std::min(bx, z + x / tx);
    ay = std::min(ay, z - y / ty);
    by = std::min(by, z + y / ty);
  }
  double cx = 0.5 * tx * (bx - ax), cy = 0.5 * ty * (by - ay);
  const double czx = 0.5 * (ax + bx), czy = 0.5 * (ay + by);
  // (Kept a little in front of the nearest point so degenerate inputs still have depth.)
  const double cz = std::min({czx, czy, z_min - 1e-6 * depth});
  // The camera now stands back further than the other axis needs: re-centre that axis so its
  // extreme rays are symmetric, max (c − x)/(z − cz) = max (x − c)/(z − cz), by bisection
  // (the difference is increasing in c).
  const auto recentre = [&](const Eigen::Vector3d& axis, double& c) {
    std::vector<double> x(p_W.size()), inv_depth(p_W.size());
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (size_t i = 0; i < p_W.size(); ++i) {
      x[i] = axis.dot(p_W[i]);
      inv_depth[i] = 1.0 / (f.dot(p_W[i]) - cz);
      lo = std::min(lo, x[i]);
      hi = std::max(hi, x[i]);
    }
    for (int it = 0; it < 60 && hi - lo > 1e-12 * (1.0 + std::abs(hi)); ++it) {
      const double mid = 0.5 * (lo + hi);
      double left = -std::numeric_limits<double>::infinity(), right = left;
      for (size_t i = 0; i < x.size(); ++i) {
        left = std::max(left, (mid - x[i]) * inv_depth[i]);
        right = std::max(right, (x[i] - mid) * inv_depth[i]);
      }
      (left < right ? lo : hi) = mid;
    }
    c = 0.5 * (lo + hi);
  };
  if (czx > cz) recentre(r, cx);
  if (czy > cz) recentre(u, cy);
  cam.eye_W = cx * r + cy * u + cz * f;
  const double dist_near = z_min - cz, dist_far = z_max - cz;
  cam.target_W = cam.eye_W + 0.5 * (dist_near + dist_far) * f;
  cam.near_m = std::max(0.5 * dist_near, 1e-4 * dist_far);
  cam.far_m = dist_far * 1.05 + 1e-6;
  return cam;
}

Eigen::Isometry3d view_transform(const Camera& camera) {
  const Eigen::Vector3d f = (camera.target_W - camera.eye_W).normalized();
  const Eigen::Vector3d up =
      screen_up_for(f, camera.up_W.normalized(),
                    std::abs(f.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY());
  const Eigen::Vector3d r = f.cross(up).normalized();
  const Eigen::Vector3d u = r.cross(f);
  Eigen::Matrix3d R_CW;
  R_CW.row(0) = r.transpose();
  R_CW.row(1) = u.transpose();
  R_CW.row(2) = -f.transpose();
  Eigen::Isometry3d X_CW = Eigen::Isometry3d::Identity();
  X_CW.linear() = R_CW;
  X_CW.translation() = -R_CW * camera.eye_W;
  return X_CW;
}

Eigen::Matrix4d projection_matrix(const Camera& camera, double aspect) {
  const double n = camera.near_m, f = camera.far_m;
  Eigen::Matrix4d P = Eigen::Matrix4d::Zero();
  if (camera.orthographic) {
    const double h = 0.5 * camera.ortho_height_m, w = h * aspect;
    P(0, 0) = 1.0 / w;
    P(1, 1) = 1.0 / h;
    P(2, 2) = -2.0 / (f - n);
    P(2, 3) = -(f + n) / (f - n);
    P(3, 3) = 1.0;
  } else {
    const double t = 1.0 / std::tan(0.5 * camera.fov_y_rad);
    P(0, 0) = t / aspect;
    P(1, 1) = t;
    P(2, 2) = -(f + n) / (f - n);
    P(2, 3) = -2.0 * f * n / (f - n);
    P(3, 2) = -1.0;
  }
  return P;
}

Eigen::Vector2d project_to_pixel(const Camera& camera, int width_px, int height_px,
                                 const Eigen::Vector3d& p_W) {
  const double aspect = static_cast<double>(width_px) / height_px;
  const Eigen::Vector4d clip =
      projection_matrix(camera, aspect) * (view_transform(camera) * p_W).homogeneous();
  const double x_ndc = clip.x() / clip.w(), y_ndc = clip.y() / clip.w();
  return {0.5 * (x_ndc + 1.0) * width_px, 0.5 * (1.0 - y_ndc) * height_px};
}

}  // namespace cordgrasp
