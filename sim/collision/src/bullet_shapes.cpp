#include "bullet_shapes.h"

#include <LinearMath/btConvexHullComputer.h>

#include <algorithm>
#include <stdexcept>

namespace cordgrasp::bullet {

btTransform to_bt(const Eigen::Isometry3d& X) {
  const Eigen::Matrix3d R = X.linear();
  const btMatrix3x3 basis(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1),
                          R(2, 2));
  return btTransform(basis, to_bt(Eigen::Vector3d(X.translation())));
}

Eigen::Isometry3d from_bt(const btTransform& X) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  const btMatrix3x3& b = X.getBasis();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.linear()(r, c) = b[r][c];
  out.translation() = from_bt(X.getOrigin());
  return out;
}

std::unique_ptr<btConvexHullShape> make_convex_hull_shape(
    const std::vector<Eigen::Vector3d>& points, double margin) {
  if (points.size() < 4) return nullptr;
  std::vector<double> coords;
  coords.reserve(points.size() * 3);
  for (const auto& v : points) coords.insert(coords.end(), {v.x(), v.y(), v.z()});
  btConvexHullComputer hull;
  hull.compute(coords.data(), 3 * static_cast<int>(sizeof(double)),
               static_cast<int>(points.size()), 0.0, 0.0);
  const int nv = hull.vertices.size();
  if (nv < 4) return nullptr;

  // Shrink-wrap: inset every hull vertex so that its incident face planes move in by (about)
  // the margin; hull + margin then matches the authored hull (rounded by the margin at edges).
  // Insetting vertices keeps their number (btConvexHullComputer's own plane shrink multiplies
  // it by ~4, which makes every GJK support call slower).
  btVector3 lo = hull.vertices[0], hi = hull.vertices[0], centroid(0, 0, 0);
  for (int i = 0; i < nv; ++i) {
    lo.setMin(hull.vertices[i]);
    hi.setMax(hull.vertices[i]);
    centroid += hull.vertices[i];
  }
  centroid /= nv;
  const double m = std::min(margin, 0.2 * (hi - lo)[(hi - lo).minAxis()]);
  std::vector<std::vector<btVector3>> incident(static_cast<size_t>(nv));
  for (int f = 0; f < hull.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[f]];
    std::vector<int> corners;
    const btConvexHullComputer::Edge* e = first;
    do {
      corners.push_back(e->getSourceVertex());
      e = e->getNextEdgeOfFace();
    } while (e != first && corners.size() < static_cast<size_t>(nv));
    if (corners.size() < 3) continue;
    btVector3 n(0, 0, 0);  // Newell normal of the face polygon
    for (size_t k = 0; k < corners.size(); ++k) {
      const btVector3& a = hull.vertices[corners[k]];
      const btVector3& b = hull.vertices[corners[(k + 1) % corners.size()]];
      n += a.cross(b);
    }
    if (n.length2() <= 0.0) continue;
    n.normalize();
    if (n.dot(hull.vertices[corners[0]] - centroid) < 0.0) n = -n;
    for (int c : corners) incident[static_cast<size_t>(c)].push_back(n);
  }
  auto shape = std::make_unique<btConvexHullShape>();
  for (int i = 0; i < nv; ++i) {
    btVector3 u(0, 0, 0);
    for (const btVector3& n : incident[static_cast<size_t>(i)]) u += n;
    btVector3 inset(0, 0, 0);
    if (m > 0.0 && u.length2() > 0.0) {
      u.normalize();
      double least = 1.0;
      for (const btVector3& n : incident[static_cast<size_t>(i)]) least = std::min(least, n.dot(u));
      inset = -u * (m / std::max(least, 1.0 / 3.0));  // every incident face moves in by ≥ m
    }
    shape->addPoint(hull.vertices[i] + inset, false);
  }
  // GJK wants some margin; a flat hull gets 1 µm of inflation. Set the margin before the
  // cached local AABB is computed: it includes the margin.
  shape->setMargin(std::max(m, 1e-6));
  shape->recalcLocalAabb();
  return shape;
}

namespace {

std::unique_ptr<btConvexShape> make_hull_shape(const Mesh& mesh, double margin) {
  return make_convex_hull_shape(mesh.vertices, margin);
}

}  // namespace

std::unique_ptr<btConvexShape> make_geometry_shape(const Geometry& g, const ShapeParams& params) {
  const double m = params.link_margin_m;
  std::unique_ptr<btConvexShape> shape;
  switch (g.kind) {
    case Geometry::Kind::kBox: {
      const Eigen::Vector3d half = 0.5 * g.box_size_m;
      if (half.minCoeff() <= 0.0) return nullptr;
      shape = std::make_unique<btBoxShape>(to_bt(half));
      shape->setMargin(std::min(m, 0.5 * half.minCoeff()));  // stays inside the extents
      break;
    }
    case Geometry::Kind::kCylinder: {
      if (g.radius_m <= 0.0 || g.length_m <= 0.0) return nullptr;
      shape =
          std::make_unique<btCylinderShapeZ>(btVector3(g.radius_m, g.radius_m, 0.5 * g.length_m));
      shape->setMargin(std::min(m, 0.5 * std::min(g.radius_m, 0.5 * g.length_m)));
      break;
    }
    case Geometry::Kind::kSphere:
      if (g.radius_m <= 0.0) return nullptr;
      shape = std::make_unique<btSphereShape>(g.radius_m);  // margin = radius: exact
      break;
    case Geometry::Kind::kMesh:
      if (!g.mesh) return nullptr;
      shape = make_hull_shape(*g.mesh, m);
      break;
  }
  return shape;
}

LinkShape make_link_shape(const Link& link, const ShapeParams& params) {
  return make_links_shape({&link}, {Eigen::Isometry3d::Identity()}, params);
}

LinkShape make_links_shape(const std::vector<const Link*>& links,
                           const std::vector<Eigen::Isometry3d>& X_FL,
                           const ShapeParams& params) {
  if (links.size() != X_FL.size())
    throw std::invalid_argument("make_links_shape: links and X_FL differ in size");
  LinkShape out;
  for (size_t l = 0; l < links.size(); ++l) {
    for (const Geometry& g : links[l]->collisions) {
      auto child = make_geometry_shape(g, params);
      if (!child) continue;
      out.children.push_back(std::move(child));
      out.X_LC.push_back(X_FL[l] * g.X_LG);
    }
  }
  if (out.children.empty()) return out;
  out.compound = std::make_unique<btCompoundShape>(/*enableDynamicAabbTree=*/false,
                                                   static_cast<int>(out.children.size()));
  for (size_t i = 0; i < out.children.size(); ++i)
    out.compound->addChildShape(to_bt(out.X_LC[i]), out.children[i].get());
  out.compound->setMargin(params.link_margin_m);
  return out;
}

}  // namespace cordgrasp::bullet
