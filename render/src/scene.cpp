#include "cordgrasp/render/scene.h"

#include <algorithm>
#include <cmath>

namespace cordgrasp {
namespace {

// Two unit vectors completing `axis` to an orthonormal frame.
void perpendicular_pair(const Eigen::Vector3d& axis, Eigen::Vector3d& a, Eigen::Vector3d& b) {
  a = axis.unitOrthogonal();
  b = axis.cross(a);
}

}  // namespace

SceneMesh& add_mesh(Scene& scene, Mesh mesh, const Eigen::Isometry3d& X_WM, const Rgba& rgba,
                    Shading shading) {
  return add_mesh(scene, std::make_shared<const Mesh>(std::move(mesh)), X_WM, rgba, shading);
}

SceneMesh& add_mesh(Scene& scene, std::shared_ptr<const Mesh> mesh, const Eigen::Isometry3d& X_WM,
                    const Rgba& rgba, Shading shading) {
  SceneMesh m;
  m.mesh = std::move(mesh);
  m.X_WM = X_WM;
  m.rgba = rgba;
  m.shading = shading;
  scene.meshes.push_back(std::move(m));
  return scene.meshes.back();
}

std::vector<Eigen::Vector3d> scene_extent_points(const Scene& scene) {
  std::vector<Eigen::Vector3d> p;
  for (const SceneMesh& m : scene.meshes) {
    if (!m.mesh) continue;
    p.reserve(p.size() + m.mesh->vertices.size());
    for (const auto& v : m.mesh->vertices) p.push_back(m.X_WM * v);
  }
  for (const ScenePolyline& l : scene.polylines) p.insert(p.end(), l.p_W.begin(), l.p_W.end());
  const auto add_ball = [&p](const Eigen::Vector3d& c, double r) {
    for (int i = 0; i < 3; ++i) {
      p.push_back(c + r * Eigen::Vector3d::Unit(i));
      p.push_back(c - r * Eigen::Vector3d::Unit(i));
    }
  };
  for (const ScenePoint& s : scene.points) add_ball(s.p_W, s.radius_m);
  for (const SceneArrow& a : scene.arrows) {
    if (a.direction_W.norm() == 0.0) continue;
    add_ball(a.p_W, 2.5 * a.shaft_radius_m);
    add_ball(a.p_W + a.length_m * a.direction_W.normalized(), 2.5 * a.shaft_radius_m);
  }
  for (const SceneCone& c : scene.cones) {
    if (c.axis_W.norm() == 0.0) continue;
    const Eigen::Vector3d axis = c.axis_W.normalized();
    Eigen::Vector3d a, b;
    perpendicular_pair(axis, a, b);
    const double r = c.height_m * std::tan(c.half_angle_rad);
    p.push_back(c.apex_W);
    constexpr int kSamples = 16;
    for (int i = 0; i < kSamples; ++i) {
      const double t = 2.0 * M_PI * i / kSamples;
      p.push_back(c.apex_W + c.height_m * axis + r * (std::cos(t) * a + std::sin(t) * b));
    }
  }
  p.erase(
      std::remove_if(p.begin(), p.end(), [](const Eigen::Vector3d& q) { return !q.allFinite(); }),
      p.end());
  return p;
}

size_t scene_triangle_count(const Scene& scene) {
  size_t n = 0;
  for (const SceneMesh& m : scene.meshes)
    if (m.mesh) n += m.mesh->triangles.size();
  return n;
}

}  // namespace cordgrasp
