#include "object_body.h"

#include <LinearMath/btConvexHullComputer.h>

#include <Eigen/Eigenvalues>
#include <map>
#include <mutex>
#include <stdexcept>

#include "bullet_shapes.h"
#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/mesh_volume.h"
#include "cordgrasp/core/orient_triangles.h"
#include "cordgrasp/sim/convex_decomposition.h"

namespace cordgrasp::bullet {

namespace {

/// Principal moments are floored at this fraction of the largest (flat objects).
constexpr double kMinInertiaRatio = 1e-3;
/// More parts than this get a dynamic AABB tree in the compound.
constexpr int kCompoundTreeParts = 8;

/// Above this many triangles (raw scans) the convex hull is that of the vertices' column
/// extremes (column_extreme_points) and the convex-hull shape is reduced from its vertices;
/// below it (every shipped and dataset mesh) both are those of every vertex.
constexpr size_t kLargeMeshTriangles = 200000;
/// Grid cells along a large mesh's longest side for its column extremes: ≤ 6 · 128² points,
/// within √2 / 128 of the longest side of the exact hull.
constexpr int kLargeMeshHullCells = 128;

/// The mass bases make_object_body chooses between, and (large meshes) the hull's vertices.
struct MeshVolumes {
  SolidVolume hull;
  std::optional<SolidVolume> closed;
  std::vector<Eigen::Vector3d> hull_vertices;
};

Eigen::Matrix3d shift_inertia(double mass, const Eigen::Vector3d& d) {
  return mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

UnitSolid combine(const std::vector<UnitSolid>& parts) {
  UnitSolid out;
  for (const UnitSolid& p : parts) {
    out.volume_m3 += p.volume_m3;
    out.com += p.volume_m3 * p.com;
  }
  if (!(out.volume_m3 > 0.0)) return UnitSolid{};
  out.com /= out.volume_m3;
  for (const UnitSolid& p : parts)
    out.inertia += p.inertia + shift_inertia(p.volume_m3, p.com - out.com);
  return out;
}

}  // namespace

UnitSolid unit_solid(const std::vector<Eigen::Vector3d>& vertices,
                     const std::vector<Eigen::Vector3i>& triangles) {
  UnitSolid out;
  if (vertices.empty()) return out;
  Eigen::Vector3d o = Eigen::Vector3d::Zero();
  for (const auto& v : vertices) o += v;
  o /= static_cast<double>(vertices.size());
  double six_volume = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();  // ∫ x xᵀ dV about o, × 120 / 6
  for (const Eigen::Vector3i& t : triangles) {
    const Eigen::Vector3d a = vertices[static_cast<size_t>(t[0])] - o;
    const Eigen::Vector3d b = vertices[static_cast<size_t>(t[1])] - o;
    const Eigen::Vector3d c = vertices[static_cast<size_t>(t[2])] - o;
    const double v6 = a.dot(b.cross(c));
    const Eigen::Vector3d s = a + b + c;
    six_volume += v6;
    moment += v6 * s;
    // Tetrahedron (0, a, b, c): ∫ x xᵀ dV = V/20 · (a aᵀ + b bᵀ + c cᵀ + s sᵀ).
    cov += v6 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  double sign = 1.0;
  if (six_volume < 0.0) sign = -1.0;  // inward-wound input: flip everything
  six_volume *= sign;
  if (!(six_volume > 0.0)) return out;
  out.volume_m3 = six_volume / 6.0;
  const Eigen::Vector3d g = sign * moment / (4.0 * six_volume);  // COM relative to o
  const Eigen::Matrix3d C = sign * cov / 120.0;                  // ∫ x xᵀ dV about o
  const Eigen::Matrix3d I_o = C.trace() * Eigen::Matrix3d::Identity() - C;
  out.com = o + g;
  out.inertia = I_o - shift_inertia(out.volume_m3, g);
  return out;
}

UnitSolid convex_hull_solid(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 4) return UnitSolid{};
  std::vector<double> coords;
  coords.reserve(points.size() * 3);
  for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  btConvexHullComputer hull;
  hull.compute(coords.data(), 3 * static_cast<int>(sizeof(double)),
               static_cast<int>(points.size()), 0.0, 0.0);
  std::vector<Eigen::Vector3d> vertices;
  for (int i = 0; i < hull.vertices.size(); ++i) vertices.push_back(from_bt(hull.vertices[i]));
  std::vector<Eigen::Vector3i> triangles;
  for (int f = 0; f < hull.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[f]];
    const int v0 = first->getSourceVertex();
    const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace();
    while (e->getTargetVertex() != v0) {
      triangles.emplace_back(v0, e->getSourceVertex(), e->getTargetVertex());
      e = e->getNextEdgeOfFace();
    }
  }
  return unit_solid(vertices, triangles);
}

std::vector<int> area_triangle_indices(const Mesh& mesh) {
  std::vector<int> indices;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[static_cast<size_t>(t[0])];
    if ((mesh.vertices[static_cast<size_t>(t[1])] - a)
            .cross(mesh.vertices[static_cast<size_t>(t[2])] - a)
            .squaredNorm() <= 0.0)
      continue;
    indices.insert(indices.end(), {t[0], t[1], t[2]});
  }
  return indices;
}

std::unique_ptr<ObjectBody> make_object_body(const Mesh& mesh, const SimParams& params) {
  if (mesh.triangles.empty())
    throw std::invalid_argument("make_object_body: mesh '" + mesh.name + "' has no triangles");
  auto out = std::make_unique<ObjectBody>();
  SimObjectInfo& info = out->info;

  // Mass basis (docs/physics.md §2): the closed volume; for an open mesh a shell of
  // open_mesh_shell_m over its surface, at most the convex hull's volume.
  const std::string& mesh_key = out->mesh_key = mesh_hash(mesh);
  const bool large = mesh.triangles.size() > kLargeMeshTriangles;
  const MeshVolumes& volumes = once_per_key<MeshVolumes>(mesh_key, [&]() {
    MeshVolumes v;
    // A scan's hull from its column extremes: within √2 cell widths of the exact one, at a
    // bounded cost (Qhull on a 2.4 M-triangle scan's 1.2 M vertices takes seconds).
    v.hull = large ? convex_hull_volume(
                         column_extreme_points(referenced_vertices(mesh), kLargeMeshHullCells),
                         &v.hull_vertices)
                   : convex_hull_volume(mesh);
    v.closed = closed_mesh_volume(mesh);
    return v;
  });
  const SolidVolume& hull_volume = volumes.hull;
  const std::optional<SolidVolume>& closed = volumes.closed;
  info.closed = closed.has_value();
  SolidVolume basis = closed ? *closed : hull_volume;
  if (!closed && params.open_mesh_shell_m > 0.0) {
    const PrincipalAxes surface = principal_axes(mesh);
    const double shell_m3 = surface.area_m2 * params.open_mesh_shell_m;
    if (shell_m3 < hull_volume.volume_m3) {
      basis.volume_m3 = shell_m3;
      basis.center_of_mass_m = surface.centroid;
    }
  }
  if (!(basis.volume_m3 > 0.0))
    throw std::invalid_argument("make_object_body: mesh '" + mesh.name + "' bounds no volume");
  info.volume_m3 = basis.volume_m3;
  info.mass_kg = params.mass_kg ? *params.mass_kg : params.density_kgm3 * basis.volume_m3;
  if (!(info.mass_kg > 0.0))
    throw std::invalid_argument("make_object_body: object mass must be positive");

  // Collision shape.
  ObjectShape shape = params.object_shape;
  std::vector<std::vector<Eigen::Vector3d>> parts;
  if (shape == ObjectShape::kAuto) {
    if (closed && hull_volume.volume_m3 > 0.0 &&
        closed->volume_m3 / hull_volume.volume_m3 >= params.convex_volume_ratio) {
      shape = ObjectShape::kConvexHull;
    } else {
      auto d = cached_convex_decomposition(mesh, params.decomposition,
                                           params.decomposition_cache_dir);
      info.decomposition_s = d->compute_s;
      parts = d->parts;
      shape = parts.size() == 1 ? ObjectShape::kConvexHull : ObjectShape::kDecomposition;
    }
  } else if (shape == ObjectShape::kDecomposition) {
    auto d = cached_convex_decomposition(mesh, params.decomposition,
                                         params.decomposition_cache_dir);
    info.decomposition_s = d->compute_s;
    parts = d->parts;
  }
  if (shape == ObjectShape::kConvexHull && parts.empty()) {
    const int max_vertices = params.decomposition.max_hull_vertices;
    parts.push_back(once_per_key<std::vector<Eigen::Vector3d>>(
        mesh_key + "-hull-" + std::to_string(max_vertices),
        [&]() {
          return large && volumes.hull_vertices.size() >= 4
                     ? reduced_convex_hull(volumes.hull_vertices, max_vertices)
                     : simplified_convex_hull(mesh.vertices, max_vertices);
        }));
  }
  info.shape = shape;

  // Inertia of the collision shape (unit density), scaled to the mass about the mass's COM.
  UnitSolid solid;
  if (shape == ObjectShape::kGImpact) {
    if (closed) {
      Mesh oriented = mesh;
      orient_triangles(oriented);
      solid = unit_solid(oriented.vertices, oriented.triangles);
    }
    if (!(solid.volume_m3 > 0.0)) solid = convex_hull_solid(mesh.vertices);
  } else {
    std::vector<UnitSolid> solids;
    for (const auto& part : parts) solids.push_back(convex_hull_solid(part));
    solid = combine(solids);
  }
  if (!(solid.volume_m3 > 0.0))
    throw std::invalid_argument("make_object_body: mesh '" + mesh.name +
                                "': collision shape bounds no volume");
  const Eigen::Vector3d com =
      basis.center_of_mass_m +
      Eigen::Vector3d(params.com_offset_x_m, params.com_offset_y_m, params.com_offset_z_m);
  Eigen::Matrix3d I = info.mass_kg / solid.volume_m3 * solid.inertia +
                      shift_inertia(info.mass_kg, com - solid.com);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (I + I.transpose()));
  Eigen::Matrix3d V = eig.eigenvectors();
  if (V.determinant() < 0.0) V.col(2) = -V.col(2);
  Eigen::Vector3d lambda = eig.eigenvalues();
  for (int a = 0; a < 3; ++a) lambda[a] = std::max(lambda[a], kMinInertiaRatio * lambda.maxCoeff());
  out->X_OC.linear() = V;
  out->X_OC.translation() = com;
  info.com_O = com;
  info.principal_inertia_kgm2 = lambda;
  const Eigen::Isometry3d X_CO = out->X_OC.inverse();

  if (shape == ObjectShape::kGImpact) {
    for (const auto& v : mesh.vertices) {
      const Eigen::Vector3d p = X_CO * v;
      out->vertices.insert(out->vertices.end(), {p.x(), p.y(), p.z()});
    }
    out->indices = area_triangle_indices(mesh);
    out->mesh_interface = std::make_unique<btTriangleIndexVertexArray>(
        static_cast<int>(out->indices.size() / 3), out->indices.data(), 3 * sizeof(int),
        static_cast<int>(mesh.vertices.size()), out->vertices.data(), 3 * sizeof(btScalar));
    out->gimpact = std::make_unique<btGImpactMeshShape>(out->mesh_interface.get());
    out->gimpact->setMargin(params.object_margin_m);
    out->gimpact->updateBound();
    out->shape = out->gimpact.get();
    info.parts = static_cast<int>(out->indices.size() / 3);
  } else {
    for (const auto& part : parts) {
      std::vector<Eigen::Vector3d> points;
      points.reserve(part.size());
      for (const auto& p : part) points.push_back(X_CO * p);
      auto hull = make_convex_hull_shape(points, params.object_margin_m);
      if (!hull) continue;
      if (params.polyhedral_contacts) hull->initializePolyhedralFeatures();
      out->hulls.push_back(std::move(hull));
    }
    if (out->hulls.empty())
      throw std::invalid_argument("make_object_body: mesh '" + mesh.name +
                                  "': no usable convex part");
    if (out->hulls.size() == 1) {
      out->shape = out->hulls.front().get();
    } else {
      const int n = static_cast<int>(out->hulls.size());
      out->compound = std::make_unique<btCompoundShape>(n > kCompoundTreeParts, n);
      for (auto& h : out->hulls) out->compound->addChildShape(btTransform::getIdentity(), h.get());
      out->shape = out->compound.get();
    }
    info.parts = static_cast<int>(out->hulls.size());
  }

  btRigidBody::btRigidBodyConstructionInfo ci(info.mass_kg, nullptr, out->shape, to_bt(lambda));
  ci.m_friction = params.contact.mu;
  ci.m_restitution = 0.0;
  ci.m_rollingFriction = 0.0;
  // Soft-finger contacts (ContactModel): torsional friction up to μ·radius·normal force; Bullet
  // combines spinning friction as object spin × link friction (1) + link spin (0) × μ.
  ci.m_spinningFriction = params.contact.mu * params.contact.soft_finger_radius_m;
  ci.m_linearDamping = 0.0;
  ci.m_angularDamping = 0.0;
  out->body = std::make_unique<btRigidBody>(ci);
  out->body->setCollisionFlags(out->body->getCollisionFlags() |
                               btCollisionObject::CF_HAS_FRICTION_ANCHOR);
  if (params.contact_stiffness_Npm > 0.0)
    out->body->setContactStiffnessAndDamping(params.contact_stiffness_Npm,
                                             params.contact_damping_Nspm);
  out->body->setActivationState(DISABLE_DEACTIVATION);
  out->body->setSleepingThresholds(0.0, 0.0);
  return out;
}

}  // namespace cordgrasp::bullet
