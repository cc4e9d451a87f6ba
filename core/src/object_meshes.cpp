#include "cordgrasp/core/object_meshes.h"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "cordgrasp/core/shape_builders.h"
#include "cordgrasp/core/shapes.h"

namespace cordgrasp {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Coordinates are rounded to multiples of 1/kGridPerMeter (0.1 µm): coarser than float
/// spacing at these sizes, so vertices stay distinct after assimp's float parse of the OBJ.
constexpr double kGridPerMeter = 1e7;
constexpr double kMaxStep_m = 0.01;  ///< profile points at most this far apart
constexpr int kRevolveSegments = 48;
constexpr int kTubeSegments = 16;

Eigen::Isometry3d translation(double x, double y, double z) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(x, y, z);
  return X;
}

/// Drops unreferenced vertices, rounds coordinates to the 0.1 µm grid (and −0 to +0) so the OBJ
/// text is short, and names the mesh.
Mesh finish(Mesh m, const std::string& name) {
  std::vector<int> remap(m.vertices.size(), -1);
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) remap[t[k]] = 0;
  std::vector<Eigen::Vector3d> kept;
  for (size_t i = 0; i < m.vertices.size(); ++i)
    if (remap[i] == 0) {
      remap[i] = int(kept.size());
      kept.push_back(m.vertices[i]);
    }
  for (auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) t[k] = remap[t[k]];
  m.vertices = std::move(kept);
  for (auto& v : m.vertices)
    for (int k = 0; k < 3; ++k) v[k] = std::round(v[k] * kGridPerMeter) / kGridPerMeter + 0.0;
  m.name = name;
  return m;
}

/// Profile points of an elliptic arc (r, z) = (c_r + a cos θ, c_z + b sin θ), θ0 → θ1.
std::vector<Eigen::Vector2d> arc(double c_r, double c_z, double a, double b, double theta0,
                                 double theta1, int steps) {
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i <= steps; ++i) {
    const double t = theta0 + (theta1 - theta0) * i / steps;
    out.emplace_back(c_r + a * std::cos(t), c_z + b * std::sin(t));
  }
  return out;
}

void append_points(std::vector<Eigen::Vector2d>& to, const std::vector<Eigen::Vector2d>& from,
                   bool skip_first = false) {
  to.insert(to.end(), from.begin() + (skip_first ? 1 : 0), from.end());
}

/// Half-ellipse handle centre line in the x–z plane from z_top to z_bottom through x = x_far,
/// with short straight ends reaching x = x_in (inside the body).
std::vector<Eigen::Vector3d> handle_path(double x_wall, double x_far, double x_in, double z_top,
                                         double z_bottom, int steps) {
  const double zc = 0.5 * (z_top + z_bottom), b = 0.5 * (z_top - z_bottom);
  const double a = x_far - x_wall;  // signed: the handle may point toward −x
  std::vector<Eigen::Vector3d> path;
  path.emplace_back(x_in, 0.0, z_top);
  for (int i = 0; i <= steps; ++i) {
    const double t = 0.5 * kPi - kPi * i / steps;
    path.emplace_back(x_wall + a * std::cos(t), 0.0, zc + b * std::sin(t));
  }
  path.emplace_back(x_in, 0.0, z_bottom);
  return path;
}

}  // namespace

Mesh make_box_object(const BoxObjectParams& p) {
  Mesh m;
  const Mesh box = make_grid_box_mesh(p.size_m, p.max_cell_m);
  append_mesh(m, box, translation(0, 0, 0.5 * p.size_m.z()));
  return finish(m, "box");
}

Mesh make_long_cylinder_object(const CylinderObjectParams& p) {
  const double r = 0.5 * p.diameter_m;
  std::vector<Eigen::Vector2d> profile{{0.0, 0.0}};
  append_points(profile, densify_polyline({{r, 0.0}, {r, p.length_m}}, kMaxStep_m));
  profile.emplace_back(0.0, p.length_m);
  return finish(make_revolved_mesh(profile, kRevolveSegments), "long_cylinder");
}

Mesh make_sphere_object(const SphereObjectParams& p) {
  const double r = 0.5 * p.diameter_m;
  Mesh m;
  append_mesh(m, make_sphere_mesh(r, 16, 32), translation(0, 0, r));
  return finish(m, "sphere");
}

Mesh make_bottle_object(const BottleObjectParams& p) {
  const double r = 0.5 * p.diameter_m, h = p.height_m;
  const double r_neck = 0.386 * r, r_cap = r_neck + 0.0015;
  const double z_shoulder = 0.68 * h, z_neck = 0.86 * h, z_cap = 0.91 * h;
  std::vector<Eigen::Vector2d> profile{{0.0, 0.0}, {r - 0.002, 0.0}};
  append_points(profile, densify_polyline({{r, 0.002}, {r, z_shoulder}}, kMaxStep_m));
  for (int i = 1; i <= 10; ++i) {  // shoulder: cosine blend from the body to the neck
    const double s = i / 10.0;
    profile.emplace_back(r_neck + (r - r_neck) * 0.5 * (1 + std::cos(kPi * s)),
                         z_shoulder + (z_neck - z_shoulder) * s);
  }
  profile.insert(profile.end(), {{r_neck, z_cap}, {r_cap, z_cap}, {r_cap, h}, {0.0, h}});
  return finish(make_revolved_mesh(profile, kRevolveSegments), "bottle");
}

Mesh make_mug_object(const MugObjectParams& p) {
  const double r = 0.5 * p.outer_diameter_m, h = p.height_m, r_in = r - p.wall_m;
  // Closed shell: up the outside, across the rim, down the inside, to the axis on the bottom.
  std::vector<Eigen::Vector2d> profile{{0.0, 0.0}, {r - 0.002, 0.0}};
  append_points(profile, densify_polyline({{r, 0.002}, {r, h}}, kMaxStep_m));
  append_points(profile, densify_polyline({{r_in, h}, {r_in, p.bottom_m}}, kMaxStep_m));
  profile.emplace_back(0.0, p.bottom_m);
  Mesh m = make_revolved_mesh(profile, kRevolveSegments);
  // Handle: its end caps sit inside the wall (between r_in and r), so nothing pokes inside.
  const auto path =
      handle_path(r, r + p.handle_reach_m, r - 0.75 * p.wall_m, 0.82 * h, 0.27 * h, 24);
  append_mesh(m, make_swept_tube_mesh(path, p.handle_radius_m, kTubeSegments));
  return finish(m, "mug");
}

Mesh make_wine_glass_object(const WineGlassObjectParams& p) {
  // Nominal glass: bowl radius 0.042 m, height 0.2 m; radii and heights scale separately.
  const double sr = 0.5 * p.bowl_diameter_m / 0.042, sz = p.height_m / 0.2;
  const double zc = 0.14, a_out = 0.042, b_out = 0.048, a_in = 0.040, b_in = 0.046;
  std::vector<Eigen::Vector2d> nominal{{0.0, 0.0},    {0.035, 0.0},  {0.035, 0.003},
                                       {0.02, 0.005}, {0.01, 0.008}, {0.005, 0.013}};
  append_points(nominal, densify_polyline({{0.004, 0.02}, {0.004, 0.09}}, 0.02));
  // Outer bowl: lower half-ellipse from the stem to the widest point, then a tulip to the rim.
  append_points(nominal, arc(0.0, zc, a_out, b_out, -std::acos(0.006 / a_out), 0.0, 8));
  for (int i = 1; i <= 5; ++i) {
    const double s = i / 5.0;
    nominal.emplace_back(a_out - 0.006 * s * s, zc + 0.06 * s);
  }
  // Inner wall, 2 mm in: tulip down from the rim, then the inner half-ellipse to the axis.
  for (int i = 0; i <= 5; ++i) {
    const double s = 1.0 - i / 5.0;
    nominal.emplace_back(a_in - 0.006 * s * s, zc + 0.06 * s);
  }
  append_points(nominal, arc(0.0, zc, a_in, b_in, 0.0, -0.5 * kPi, 8), true);
  nominal.back() = Eigen::Vector2d(0.0, zc - b_in);  // exactly on the axis
  std::vector<Eigen::Vector2d> profile;
  for (const auto& q : nominal) profile.emplace_back(sr * q.x(), sz * q.y());
  return finish(make_revolved_mesh(profile, 40), "wine_glass");
}

Mesh make_torus_object(const TorusObjectParams& p) {
  Mesh m;
  append_mesh(m, make_torus_mesh(p.major_radius_m, p.minor_radius_m, 48, 24),
              translation(0, 0, p.minor_radius_m));
  return finish(m, "torus");
}

Mesh make_pliers_object(const PliersObjectParams& p) {
  const double s = p.length_m / 0.2;  // nominal pliers are 0.2 m long
  const double grip_r = 0.0085 * s, z0 = grip_r;
  const double jaw_len = 0.065 * s, handle_len = 0.135 * s;
  Mesh m;
  append_mesh(m, make_cylinder_mesh(0.011 * s, 0.012 * s, 32), translation(0, 0, z0));
  for (int side = -1; side <= 1; side += 2) {
    // Jaw: a bar from just behind the pivot to the tip, opened by 5°.
    Eigen::Isometry3d X = translation(0, 0, z0);
    X.rotate(Eigen::AngleAxisd(side * 5.0 * kPi / 180.0, Eigen::Vector3d::UnitZ()));
    X.translate(Eigen::Vector3d(0.5 * jaw_len - 0.005 * s, 0, 0));
    append_mesh(m, make_grid_box_mesh(Eigen::Vector3d(jaw_len, 0.008 * s, 0.008 * s), 0.01), X);
    // Handle: bows out from the pivot to half the span at the end.
    std::vector<Eigen::Vector3d> path;
    const double y0 = 0.004 * s, y1 = 0.5 * p.handle_span_m;
    const int steps = 20;
    for (int i = 0; i <= steps; ++i) {
      const double u = double(i) / steps;
      path.emplace_back(-0.002 * s - (handle_len - 0.002 * s) * u,
                        side * (y0 + (y1 - y0) * std::sin(0.5 * kPi * u)), z0);
    }
    append_mesh(m, make_swept_tube_mesh(path, 0.006 * s, kTubeSegments));
    // Grip sleeve over the outer part of the handle, a little past its end.
    std::vector<Eigen::Vector3d> grip(path.begin() + 9, path.end());
    grip.push_back(path.back() + 0.003 * s * (path.back() - path[steps - 1]).normalized());
    append_mesh(m, make_swept_tube_mesh(grip, grip_r, kTubeSegments));
  }
  return finish(m, "pliers");
}

Mesh make_kettle_object(const KettleObjectParams& p) {
  // Nominal kettle: base radius 0.06 m, height 0.155 m; radii and heights scale separately.
  const double sr = 0.5 * p.base_diameter_m / 0.06, sz = p.height_m / 0.155;
  std::vector<Eigen::Vector2d> nominal{{0.0, 0.0}, {0.056, 0.0}};
  append_points(nominal, densify_polyline({{0.06, 0.004}, {0.047, 0.122}}, kMaxStep_m));
  nominal.insert(nominal.end(), {{0.044, 0.128},
                                 {0.04, 0.131},
                                 {0.03, 0.135},
                                 {0.018, 0.138},
                                 {0.012, 0.139},
                                 {0.012, 0.15},
                                 {0.009, 0.155},
                                 {0.0, 0.155}});
  std::vector<Eigen::Vector2d> profile;
  for (const auto& q : nominal) profile.emplace_back(sr * q.x(), sz * q.y());
  Mesh m = make_revolved_mesh(profile, kRevolveSegments);
  // Side handle on −x, ends inside the body.
  std::vector<Eigen::Vector3d> handle =
      handle_path(-0.05 * sr, -0.088 * sr, -0.04 * sr, 0.115 * sz, 0.035 * sz, 24);
  append_mesh(m, make_swept_tube_mesh(handle, 0.009 * std::min(sr, sz), kTubeSegments));
  // Spout on +x: quadratic Bézier centre line, radius 13 → 6.5 mm, base inside the body.
  const Eigen::Vector3d b0(0.035 * sr, 0, 0.035 * sz), b1(0.075 * sr, 0, 0.055 * sz),
      b2(0.09 * sr, 0, 0.11 * sz);
  std::vector<Eigen::Vector3d> spout;
  std::vector<double> radii;
  const int steps = 10;
  for (int i = 0; i <= steps; ++i) {
    const double t = double(i) / steps;
    spout.push_back((1 - t) * (1 - t) * b0 + 2 * t * (1 - t) * b1 + t * t * b2);
    radii.push_back((0.013 - 0.0065 * t) * std::min(sr, sz));
  }
  append_mesh(m, make_swept_tube_mesh(spout, radii, kTubeSegments));
  return finish(m, "kettle");
}

Mesh make_defective_object() {
  constexpr double kSide = 0.06;
  Mesh box = finish(make_box_object({Eigen::Vector3d::Constant(kSide), 0.01}), "defective");
  Mesh m;
  m.vertices = box.vertices;
  m.name = box.name;
  const double h = 0.5 * kSide;
  std::vector<int> minus_x;  // triangles on the −x face, for flipping
  for (const auto& t : box.triangles) {
    bool top = true, left = true;
    for (int k = 0; k < 3; ++k) {
      top = top && std::abs(box.vertices[t[k]].z() - kSide) < 1e-9;
      left = left && std::abs(box.vertices[t[k]].x() + h) < 1e-9;
    }
    if (top) continue;  // open: no top face
    if (left) minus_x.push_back(int(m.triangles.size()));
    m.triangles.push_back(t);
  }
  // Three flipped faces, not adjacent to each other.
  for (int i : {0, 20, 40}) std::swap(m.triangles[minus_x[i]][1], m.triangles[minus_x[i]][2]);
  // A fin on the (+x, +y) vertical edge between z = 0.02 and 0.03: that edge is then shared by
  // two box faces and the fin (non-manifold).
  const auto find_vertex = [&](const Eigen::Vector3d& q) {
    for (size_t i = 0; i < m.vertices.size(); ++i)
      if ((m.vertices[i] - q).norm() < 1e-9) return int(i);
    throw std::logic_error("make_defective_object: grid vertex not found");
  };
  const int a = find_vertex({h, h, 0.02}), b = find_vertex({h, h, 0.03});
  const int c = int(m.vertices.size());
  m.vertices.emplace_back(h + 0.015, h + 0.015, 0.03);
  m.vertices.emplace_back(h + 0.015, h + 0.015, 0.02);
  m.triangles.emplace_back(a, b, c);
  m.triangles.emplace_back(a, c, c + 1);
  return finish(m, "defective");
}

const std::vector<std::string>& shipped_object_names() {
  static const std::vector<std::string> names{"box",    "long_cylinder", "sphere", "bottle",
                                              "mug",    "wine_glass",    "torus",  "pliers",
                                              "kettle", "defective"};
  return names;
}

std::string default_object_name() { return "mug"; }

Mesh make_object_mesh(const std::string& name) {
  if (name == "box") return make_box_object();
  if (name == "long_cylinder") return make_long_cylinder_object();
  if (name == "sphere") return make_sphere_object();
  if (name == "bottle") return make_bottle_object();
  if (name == "mug") return make_mug_object();
  if (name == "wine_glass") return make_wine_glass_object();
  if (name == "torus") return make_torus_object();
  if (name == "pliers") return make_pliers_object();
  if (name == "kettle") return make_kettle_object();
  if (name == "defective") return make_defective_object();
  throw std::invalid_argument("make_object_mesh: unknown object '" + name + "'");
}

}  // namespace cordgrasp
