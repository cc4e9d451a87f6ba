#include "cordgrasp/collision/bullet_hand_collider.h"

#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <LinearMath/btConvexHullComputer.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "bullet_shapes.h"
#include "cordgrasp/core/mesh_bvh.h"

namespace cordgrasp {

namespace {

using bullet::from_bt;
using bullet::to_bt;

struct Aabb3 {
  btVector3 lo, hi;
  bool overlaps(const Aabb3& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y() &&
           lo.z() <= o.hi.z() && o.lo.z() <= hi.z();
  }
};

// Cheap conservative tests that let most triangles skip GJK: the child's bounding sphere and,
// for polyhedral children, its face planes pushed out by the margin (child frame).
struct ConvexCuller {
  btVector3 lo{0, 0, 0}, hi{0, 0, 0};  // local AABB, margin included
  btVector3 center{0, 0, 0};
  double radius = 0.0;
  std::vector<btVector4> planes;  // n·p ≤ w inside (unit n)
};

ConvexCuller make_culler(const btConvexShape& shape) {
  ConvexCuller c;
  btTransform identity;
  identity.setIdentity();
  shape.getAabb(identity, c.lo, c.hi);
  shape.getBoundingSphere(c.center, c.radius);
  if (shape.getShapeType() == BOX_SHAPE_PROXYTYPE) {
    const btVector3 h = static_cast<const btBoxShape&>(shape).getHalfExtentsWithMargin();
    for (int a = 0; a < 3; ++a) {
      btVector3 n(0, 0, 0);
      n[a] = 1.0;
      c.planes.emplace_back(n.x(), n.y(), n.z(), h[a]);
      c.planes.emplace_back(-n.x(), -n.y(), -n.z(), h[a]);
    }
  } else if (shape.getShapeType() == CONVEX_HULL_SHAPE_PROXYTYPE) {
    const auto& hull_shape = static_cast<const btConvexHullShape&>(shape);
    std::vector<double> coords;
    for (int i = 0; i < hull_shape.getNumPoints(); ++i) {
      const btVector3 p = hull_shape.getScaledPoint(i);
      coords.insert(coords.end(), {p.x(), p.y(), p.z()});
    }
    btConvexHullComputer hull;
    hull.compute(coords.data(), 3 * static_cast<int>(sizeof(double)), hull_shape.getNumPoints(),
                 0.0, 0.0);
    btVector3 centroid(0, 0, 0);
    for (int i = 0; i < hull.vertices.size(); ++i) centroid += hull.vertices[i];
    if (hull.vertices.size() > 0) centroid /= hull.vertices.size();
    for (int f = 0; f < hull.faces.size(); ++f) {
      const btConvexHullComputer::Edge* e0 = &hull.edges[hull.faces[f]];
      const btConvexHullComputer::Edge* e1 = e0->getNextEdgeOfFace();
      const btVector3& a = hull.vertices[e0->getSourceVertex()];
      const btVector3& b = hull.vertices[e1->getSourceVertex()];
      const btVector3& d = hull.vertices[e1->getTargetVertex()];
      btVector3 n = (b - a).cross(d - a);
      if (n.length2() <= 0.0) continue;
      n.normalize();
      double w = n.dot(a);
      if (n.dot(centroid) > w) {
        n = -n;
        w = -w;
      }
      c.planes.emplace_back(n.x(), n.y(), n.z(), w + shape.getMargin());
    }
  }
  return c;
}

// Squared distance from p to triangle (a, b, c) (Ericson, Real-Time Collision Detection 5.1.5).
double point_triangle_distance2(const btVector3& p, const btVector3& a, const btVector3& b,
                                const btVector3& c) {
  const btVector3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.length2();
  const btVector3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.length2();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).length2();
  const btVector3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.length2();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).length2();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).length2();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).length2();
}

// The object's triangles for the queries: core's object BVH (build_object_bvh: median split,
// corner-sum order, so the planner's contacts keep their witnesses, over the non-degenerate
// triangles; shared with the cord exploration), traversed with the oriented box of a link child:
// Bullet's own BVH only offers world-AABB queries, and a rotated phalanx's world AABB takes in
// far more triangles than the phalanx itself.
class ObjectTriangles {
 public:
  ObjectTriangles(const Mesh& object, int threads)
      : bvh_(std::make_shared<const MeshBvh>(build_object_bvh(object, threads))) {}

  /// The BVH, for the cord exploration to share.
  const std::shared_ptr<const MeshBvh>& shared() const { return bvh_; }

  bool empty() const { return bvh_->nodes.empty(); }

  /// Bounds of the usable triangles' corners, widened by `margin_m` (as Bullet's triangle-mesh
  /// shape computes its AABB: centre ± (half extent + margin)). Requires !empty().
  Aabb3 aabb(double margin_m) const {
    const MeshBvh::Node& root = bvh_->nodes.front();
    const btVector3 center = to_bt(root.center());
    const btVector3 half = to_bt(root.half()) + btVector3(margin_m, margin_m, margin_m);
    return {center - half, center + half};
  }

  /// Calls f(a, b, c) (object frame corners) for triangles that may lie within `pad` of the
  /// child box [lo, hi] posed at X_OC (world AABB `w_lo`, `w_hi`); f returns true to stop.
  template <class F>
  void query(const btTransform& X_OC, const btVector3& lo, const btVector3& hi,
             const btVector3& w_lo, const btVector3& w_hi, double pad, F&& f) const {
    if (bvh_->nodes.empty()) return;
    const btTransform X_CO = X_OC.inverse();
    const btMatrix3x3& R = X_CO.getBasis();
    const btMatrix3x3 R_abs = R.absolute();
    const btVector3 vpad(pad, pad, pad);
    const btVector3 qlo = w_lo - vpad, qhi = w_hi + vpad;
    const btVector3 llo = lo - vpad, lhi = hi + vpad;
    int stack[kStackSize];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const int index = stack[--top];
      const MeshBvh::Node& node = bvh_->nodes[static_cast<size_t>(index)];
      if (node.lo.x() > qhi.x() || node.hi.x() < qlo.x() || node.lo.y() > qhi.y() ||
          node.hi.y() < qlo.y() || node.lo.z() > qhi.z() || node.hi.z() < qlo.z())
        continue;
      const btVector3 c = X_CO * to_bt(node.center());
      const btVector3 h = to_bt(node.half());
      bool separated = false;
      for (int i = 0; i < 3 && !separated; ++i) {
        const double r = R_abs[i].dot(h);
        separated = c[i] - r > lhi[i] || c[i] + r < llo[i];
      }
      if (separated) continue;
      if (node.count > 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const Eigen::Vector3i& t = bvh_->triangles[static_cast<size_t>(k)];
          if (f(to_bt(bvh_->vertices[static_cast<size_t>(t[0])]),
                to_bt(bvh_->vertices[static_cast<size_t>(t[1])]),
                to_bt(bvh_->vertices[static_cast<size_t>(t[2])])))
            return;
        }
      } else {
        // Median splits keep the depth <= log2(triangles) + 1, far below the stack size.
        assert(top + 2 <= kStackSize);
        stack[top++] = node.first;  // right child
        stack[top++] = index + 1;   // left child
      }
    }
  }

 private:
  static constexpr int kStackSize = 64;
  std::shared_ptr<const MeshBvh> bvh_;  // corners are read through its vertex indices
};

// Closest points (or first penetration) of one convex child against the object's triangles.
class TriangleQuery {
 public:
  TriangleQuery(const btConvexShape* convex, const ConvexCuller& culler, const btTransform& X_OC,
                double max_distance, bool stop_at_penetration)
      : convex_(convex),
        culler_(culler),
        X_OC_(X_OC),
        X_CO_(X_OC.inverse()),
        stop_(stop_at_penetration) {
    set_reach(max_distance);
  }

  // Returns true to stop the traversal (penetration found in stop mode).
  bool operator()(const btVector3& t0, const btVector3& t1, const btVector3& t2) {
    // Conservative rejects in the child frame: all three corners beyond one face of the local
    // box or of the hull (widened by max_distance), or outside the bounding sphere.
    const btVector3 a = X_CO_ * t0, b = X_CO_ * t1, c = X_CO_ * t2;
    const double m = max_distance_;
    for (int i = 0; i < 3; ++i) {
      if (a[i] > culler_.hi[i] + m && b[i] > culler_.hi[i] + m && c[i] > culler_.hi[i] + m)
        return false;
      if (a[i] < culler_.lo[i] - m && b[i] < culler_.lo[i] - m && c[i] < culler_.lo[i] - m)
        return false;
    }
    if (point_triangle_distance2(culler_.center, a, b, c) > sphere_reach_sq_) return false;
    for (const btVector4& pl : culler_.planes) {
      const btVector3 n(pl.x(), pl.y(), pl.z());
      const double w = pl.w() + m;
      if (n.dot(a) > w && n.dot(b) > w && n.dot(c) > w) return false;
    }
    btTriangleShape triangle(t0, t1, t2);
    triangle.setMargin(0.0);
    btVoronoiSimplexSolver simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector gjk(convex_, &triangle, &simplex, &epa);
    // Warm start: search from the triangle towards the child's centre.
    const btVector3 axis = X_OC_ * culler_.center - (t0 + t1 + t2) / 3.0;
    if (axis.length2() > 0.0) gjk.setCachedSeparatingAxis(axis);
    btDiscreteCollisionDetectorInterface::ClosestPointInput input;
    input.m_transformA = X_OC_;
    input.m_transformB.setIdentity();
    input.m_maximumDistanceSquared = max_sq_;
    btPointCollector result;
    gjk.getClosestPoints(input, result, nullptr);
    if (!result.m_hasResult || result.m_distance > max_distance_) return false;
    if (!found_ || result.m_distance < best_.m_distance) {
      best_ = result;
      found_ = true;
      // Only nearer triangles matter from now on: tighten every cull and GJK's early exit.
      if (best_.m_distance >= 0.0) set_reach(best_.m_distance);
    }
    return stop_ && best_.m_distance < 0.0;
  }

  bool found() const { return found_; }
  const btPointCollector& best() const { return best_; }

 private:
  void set_reach(double max_distance) {
    max_distance_ = max_distance;
    const double reach = max_distance + convex_->getMargin();
    max_sq_ = reach * reach;
    const double r = culler_.radius + max_distance;
    sphere_reach_sq_ = r * r;
  }

  const btConvexShape* convex_;
  const ConvexCuller& culler_;
  btTransform X_OC_;
  btTransform X_CO_;
  double max_distance_ = 0.0;
  bool stop_;
  double max_sq_ = 0.0;
  double sphere_reach_sq_ = 0.0;
  bool found_ = false;
  btPointCollector best_;
};

class BulletHandCollider final : public HandObjectCollider {
 public:
  BulletHandCollider(const HandModel& hand, const Mesh& object,
                     const BulletColliderParams& params) {
    bullet::ShapeParams sp;
    sp.link_margin_m = params.link_margin_m;
    triangles_ = std::make_unique<ObjectTriangles>(object, params.threads);
    if (triangles_->empty())
      throw std::invalid_argument("make_bullet_hand_collider: mesh '" + object.name +
                                  "' has no non-degenerate triangle");
    object_aabb_ = triangles_->aabb(params.object_margin_m);
    btTransform identity;
    identity.setIdentity();
    object_center_ = btVector3(0, 0, 0);
    for (const auto& v : object.vertices) object_center_ += bullet::to_bt(v);
    object_center_ /= static_cast<double>(object.vertices.size());
    object_radius_ = 0.0;
    for (const auto& v : object.vertices)
      object_radius_ = std::max(object_radius_, (bullet::to_bt(v) - object_center_).length());
    links_.reserve(hand.links.size());
    for (const Link& link : hand.links) links_.push_back(bullet::make_link_shape(link, sp));
    cullers_.resize(links_.size());
    for (size_t l = 0; l < links_.size(); ++l)
      for (const auto& child : links_[l].children) cullers_[l].push_back(make_culler(*child));
    X_OL_.assign(links_.size(), identity);
    motion_.assign(links_.size(), 0.0);
    object_cert_.assign(links_.size(), Certificate{});
    pair_cert_.assign(links_.size() * links_.size(), Certificate{});
    pair_axis_.assign(links_.size() * links_.size(), btVector3(0, 0, 0));
    pair_rel_.assign(links_.size() * links_.size(), RelativeCertificate{});
    child_aabb_.resize(links_.size());
    link_aabb_.resize(links_.size());
    for (size_t i = 0; i < links_.size(); ++i) update_aabbs(static_cast<int>(i));
  }

  int num_links() const override { return static_cast<int>(links_.size()); }

  std::shared_ptr<const MeshBvh> object_bvh() const override { return triangles_->shared(); }

  bool has_geometry(int link) const override { return links_.at(link).compound != nullptr; }

  void set_link_poses(const std::vector<Eigen::Isometry3d>& X_OL) override {
    if (X_OL.size() != links_.size())
      throw std::invalid_argument("HandObjectCollider::set_link_poses: wrong number of poses");
    for (size_t i = 0; i < X_OL.size(); ++i) set_link_pose(static_cast<int>(i), X_OL[i]);
  }

  void set_link_pose(int link, const Eigen::Isometry3d& X_OL) override {
    const btTransform X_new = to_bt(X_OL);
    motion_.at(static_cast<size_t>(link)) += displacement_bound(link, X_OL_[link], X_new);
    X_OL_[link] = X_new;
    update_aabbs(link);
  }

  bool link_collides_with_object(int link) override {
    const LinkShape& s = links_.at(link);
    if (!s.compound || !link_aabb_[link].overlaps(object_aabb_)) return false;
    Certificate& cert = object_cert_[static_cast<size_t>(link)];
    if (cert.holds(motion_[link])) return false;
    // Distances up to kCertifyDistance_m are measured too, so that the next queries can be
    // answered from the certificate while the link moves less than the measured clearance.
    double clearance = kCertifyDistance_m;
    for (size_t c = 0; c < s.children.size(); ++c) {
      const btTransform X_OC = child_pose(link, c);
      TriangleQuery q(s.children[c].get(), cullers_[link][c], X_OC, kCertifyDistance_m, true);
      triangles_->query(X_OC, cullers_[link][c].lo, cullers_[link][c].hi, child_aabb_[link][c].lo,
                        child_aabb_[link][c].hi, kCertifyDistance_m, q);
      if (!q.found()) continue;
      if (q.best().m_distance < 0.0) {
        cert = Certificate{};
        return true;
      }
      clearance = std::min(clearance, q.best().m_distance);
    }
    if (clearance > kMinClearance_m) cert = Certificate{clearance, motion_[link]};
    return false;
  }

  bool links_collide(int a, int b) override {
    const LinkShape& sa = links_.at(a);
    const LinkShape& sb = links_.at(b);
    if (!sa.compound || !sb.compound || !link_aabb_[a].overlaps(link_aabb_[b])) return false;
    Certificate& cert = pair_cert_[pair_index(a, b)];
    const double motion = motion_[a] + motion_[b];
    if (cert.holds(motion)) return false;
    // Fingers closing side by side move together: bound b's motion relative to a as well.
    const btTransform X_ab = X_OL_[a].inverse() * X_OL_[b];
    RelativeCertificate& rel = pair_rel_[pair_index(a, b)];
    if (rel.clearance > 0.0 && displacement_bound(b, rel.X_ab, X_ab) < rel.clearance) return false;
    double clearance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < sa.children.size(); ++i) {
      for (size_t j = 0; j < sb.children.size(); ++j) {
        if (!child_aabb_[a][i].overlaps(child_aabb_[b][j])) continue;
        btVoronoiSimplexSolver simplex;
        btGjkEpaPenetrationDepthSolver epa;
        btGjkPairDetector gjk(sa.children[i].get(), sb.children[j].get(), &simplex, &epa);
        // Warm start from the last separating axis of this pair (first children only).
        btVector3* axis = i == 0 && j == 0 ? &pair_axis_[pair_index(a, b)] : nullptr;
        if (axis && axis->length2() > 0.0) gjk.setCachedSeparatingAxis(*axis);
        btDiscreteCollisionDetectorInterface::ClosestPointInput input;
        input.m_transformA = child_pose(a, i);
        input.m_transformB = child_pose(b, j);  // default max distance: always measured
        btPointCollector result;
        gjk.getClosestPoints(input, result, nullptr);
        if (axis) *axis = gjk.getCachedSeparatingAxis();
        if (!result.m_hasResult) continue;
        if (result.m_distance < 0.0) {
          cert = Certificate{};
          rel = RelativeCertificate{};
          return true;
        }
        clearance = std::min(clearance, result.m_distance);
      }
    }
    if (std::isfinite(clearance) && clearance > kMinClearance_m) {
      cert = Certificate{clearance, motion};
      rel = RelativeCertificate{clearance, X_ab};
    }
    return false;
  }

  double link_object_distance_lower_bound(int link) override {
    const LinkShape& s = links_.at(link);
    double bound = std::numeric_limits<double>::infinity();
    for (size_t c = 0; c < s.children.size(); ++c) {
      const ConvexCuller& cull = cullers_[link][c];
      const btVector3 center = child_pose(link, c) * cull.center;
      // Distance from the sphere centre to the object's AABB, and to its bounding sphere.
      const btVector3 clamped(std::clamp(center.x(), object_aabb_.lo.x(), object_aabb_.hi.x()),
                              std::clamp(center.y(), object_aabb_.lo.y(), object_aabb_.hi.y()),
                              std::clamp(center.z(), object_aabb_.lo.z(), object_aabb_.hi.z()));
      const double to_box = (center - clamped).length();
      const double to_sphere = (center - object_center_).length() - object_radius_;
      bound = std::min(bound, std::max(to_box, to_sphere) - cull.radius);
    }
    return bound;
  }

  std::optional<LinkObjectProximity> link_object_proximity(int link,
                                                           double max_distance_m) override {
    const LinkShape& s = links_.at(link);
    if (!s.compound) return std::nullopt;
    const Certificate& cert = object_cert_[static_cast<size_t>(link)];
    if (cert.holds(motion_[link] + max_distance_m)) return std::nullopt;
    const btVector3 pad(max_distance_m, max_distance_m, max_distance_m);
    bool found = false;
    btPointCollector best;
    best.m_pointInWorld.setZero();
    best.m_normalOnBInWorld.setValue(0, 0, 1);
    for (size_t c = 0; c < s.children.size(); ++c) {
      const Aabb3 box{child_aabb_[link][c].lo - pad, child_aabb_[link][c].hi + pad};
      if (!box.overlaps(object_aabb_)) continue;
      const btTransform X_OC = child_pose(link, c);
      TriangleQuery q(s.children[c].get(), cullers_[link][c], X_OC, max_distance_m, false);
      triangles_->query(X_OC, cullers_[link][c].lo, cullers_[link][c].hi, child_aabb_[link][c].lo,
                        child_aabb_[link][c].hi, max_distance_m, q);
      if (q.found() && (!found || q.best().m_distance < best.m_distance)) {
        best = q.best();
        found = true;
      }
    }
    if (!found) return std::nullopt;
    LinkObjectProximity out;
    out.distance_m = best.m_distance;
    out.p_object_O = from_bt(best.m_pointInWorld);
    out.n_O = from_bt(best.m_normalOnBInWorld).normalized();
    out.p_link_O = out.p_object_O + best.m_distance * out.n_O;
    return out;
  }

 private:
  using LinkShape = bullet::LinkShape;

  // Clearance certified when the links had accumulated `motion` (sum over the pair): no
  // collision is possible while they have moved less than `clearance` since.
  struct Certificate {
    double clearance = -1.0;  // < 0: none
    double motion = 0.0;
    bool holds(double motion_now) const {
      return clearance > 0.0 && motion_now - motion < clearance;
    }
  };

  // Clearance between two links certified at relative pose X_ab (b in a's frame).
  struct RelativeCertificate {
    double clearance = -1.0;  // < 0: none
    btTransform X_ab = btTransform::getIdentity();
  };

  // Touching pairs are not certified: their verdict is at the mercy of rounding [m].
  static constexpr double kMinClearance_m = 1e-9;

  // Certify link–object clearance up to this distance in boolean queries [m].
  static constexpr double kCertifyDistance_m = 5e-3;

  // Bound on how far any point of the link's geometry moved between two poses: each child's
  // bounding-sphere centre displacement plus its radius times the chord of the rotation angle.
  double displacement_bound(int link, const btTransform& X_old, const btTransform& X_new) const {
    const LinkShape& s = links_[static_cast<size_t>(link)];
    if (!s.compound) return 0.0;
    const btMatrix3x3 dR = X_new.getBasis() * X_old.getBasis().transpose();
    const double cos_angle = std::clamp(0.5 * (dR[0][0] + dR[1][1] + dR[2][2] - 1.0), -1.0, 1.0);
    const double chord = std::sqrt(2.0 * (1.0 - cos_angle));  // 2 sin(angle/2)
    double bound = 0.0;
    for (size_t c = 0; c < s.children.size(); ++c) {
      const ConvexCuller& cull = cullers_[static_cast<size_t>(link)][c];
      const btVector3 center_L =
          links_[static_cast<size_t>(link)].compound->getChildTransform(static_cast<int>(c)) *
          cull.center;
      const double moved = (X_new * center_L - X_old * center_L).length();
      bound = std::max(bound, moved + chord * cull.radius);
    }
    return bound;
  }

  size_t pair_index(int a, int b) const {
    return static_cast<size_t>(a) * links_.size() + static_cast<size_t>(b);
  }

  btTransform child_pose(int link, size_t child) const {
    return X_OL_[link] * links_[link].compound->getChildTransform(static_cast<int>(child));
  }

  void update_aabbs(int link) {
    const LinkShape& s = links_[link];
    child_aabb_[link].resize(s.children.size());
    Aabb3 all{btVector3(1, 1, 1) * std::numeric_limits<double>::max(),
              btVector3(1, 1, 1) * -std::numeric_limits<double>::max()};
    for (size_t c = 0; c < s.children.size(); ++c) {
      btVector3 lo, hi;
      s.children[c]->getAabb(child_pose(link, c), lo, hi);
      child_aabb_[link][c] = {lo, hi};
      all.lo.setMin(lo);
      all.hi.setMax(hi);
    }
    link_aabb_[link] = all;
  }

  std::unique_ptr<ObjectTriangles> triangles_;
  Aabb3 object_aabb_;
  btVector3 object_center_{0, 0, 0};  // vertex mean
  double object_radius_ = 0.0;        // max vertex distance from it
  std::vector<LinkShape> links_;
  std::vector<std::vector<ConvexCuller>> cullers_;
  std::vector<btTransform> X_OL_;
  std::vector<double> motion_;                 // accumulated displacement bound per link [m]
  std::vector<Certificate> object_cert_;       // per link
  std::vector<Certificate> pair_cert_;         // per ordered link pair (a·n + b)
  std::vector<btVector3> pair_axis_;           // last GJK separating axis per pair
  std::vector<RelativeCertificate> pair_rel_;  // per ordered link pair
  std::vector<std::vector<Aabb3>> child_aabb_;
  std::vector<Aabb3> link_aabb_;
};

}  // namespace

std::unique_ptr<HandObjectCollider> make_bullet_hand_collider(const HandModel& hand,
                                                              const Mesh& object,
                                                              const BulletColliderParams& params) {
  return std::make_unique<BulletHandCollider>(hand, object, params);
}

}  // namespace cordgrasp
