#include "cordgrasp/sim/bullet_hand_collider.h"

#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <limits>
#include <stdexcept>

#include "bullet_shapes.h"

namespace cordgrasp {

namespace {

using bullet::from_bt;
using bullet::to_bt;

struct Aabb3 {
  btVector3 lo, hi;
  bool overlaps(const Aabb3& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() &&
           o.lo.y() <= hi.y() && lo.z() <= o.hi.z() && o.lo.z() <= hi.z();
  }
};

// Closest points of one convex child against the triangles of the object BVH near it.
class TriangleQuery : public btTriangleCallback {
 public:
  TriangleQuery(const btConvexShape* convex, const btTransform& X_OC, double max_distance,
                bool stop_at_penetration)
      : convex_(convex), X_OC_(X_OC), max_distance_(max_distance), stop_(stop_at_penetration) {
    const double reach = max_distance + convex->getMargin();
    max_sq_ = reach * reach;
  }

  void processTriangle(btVector3* tri, int /*part*/, int /*index*/) override {
    if (stop_ && found_ && best_.m_distance < 0.0) return;
    btTriangleShape triangle(tri[0], tri[1], tri[2]);
    triangle.setMargin(0.0);
    btVoronoiSimplexSolver simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector gjk(convex_, &triangle, &simplex, &epa);
    btDiscreteCollisionDetectorInterface::ClosestPointInput input;
    input.m_transformA = X_OC_;
    input.m_transformB.setIdentity();
    input.m_maximumDistanceSquared = max_sq_;
    btPointCollector result;
    gjk.getClosestPoints(input, result, nullptr);
    if (!result.m_hasResult || result.m_distance > max_distance_) return;
    if (!found_ || result.m_distance < best_.m_distance) {
      best_ = result;
      found_ = true;
    }
  }

  bool found() const { return found_; }
  const btPointCollector& best() const { return best_; }

 private:
  const btConvexShape* convex_;
  btTransform X_OC_;
  double max_distance_;
  bool stop_;
  double max_sq_ = 0.0;
  bool found_ = false;
  btPointCollector best_;
};

class BulletHandCollider final : public HandObjectCollider {
 public:
  BulletHandCollider(const HandModel& hand, const Mesh& object,
                     const BulletColliderParams& params) {
    bullet::ShapeParams sp;
    sp.link_margin_m = params.link_margin_m;
    sp.object_margin_m = params.object_margin_m;
    object_ = bullet::make_object_mesh_shape(object, sp);
    if (!object_->shape)
      throw std::invalid_argument("make_bullet_hand_collider: mesh '" + object.name +
                                  "' has no non-degenerate triangle");
    btVector3 lo, hi;
    btTransform identity;
    identity.setIdentity();
    object_->shape->getAabb(identity, lo, hi);
    object_aabb_ = {lo, hi};
    links_.reserve(hand.links.size());
    for (const Link& link : hand.links) links_.push_back(bullet::make_link_shape(link, sp));
    X_OL_.assign(links_.size(), identity);
    child_aabb_.resize(links_.size());
    link_aabb_.resize(links_.size());
    for (size_t i = 0; i < links_.size(); ++i) update_aabbs(static_cast<int>(i));
  }

  int num_links() const override { return static_cast<int>(links_.size()); }

  bool has_geometry(int link) const override { return links_.at(link).compound != nullptr; }

  void set_link_poses(const std::vector<Eigen::Isometry3d>& X_OL) override {
    if (X_OL.size() != links_.size())
      throw std::invalid_argument("HandObjectCollider::set_link_poses: wrong number of poses");
    for (size_t i = 0; i < X_OL.size(); ++i) set_link_pose(static_cast<int>(i), X_OL[i]);
  }

  void set_link_pose(int link, const Eigen::Isometry3d& X_OL) override {
    X_OL_.at(link) = to_bt(X_OL);
    update_aabbs(link);
  }

  bool link_collides_with_object(int link) override {
    const LinkShape& s = links_.at(link);
    if (!s.compound || !link_aabb_[link].overlaps(object_aabb_)) return false;
    for (size_t c = 0; c < s.children.size(); ++c) {
      if (!child_aabb_[link][c].overlaps(object_aabb_)) continue;
      TriangleQuery q(s.children[c].get(), child_pose(link, c), 0.0, true);
      object_->shape->processAllTriangles(&q, child_aabb_[link][c].lo, child_aabb_[link][c].hi);
      if (q.found() && q.best().m_distance < 0.0) return true;
    }
    return false;
  }

  bool links_collide(int a, int b) override {
    const LinkShape& sa = links_.at(a);
    const LinkShape& sb = links_.at(b);
    if (!sa.compound || !sb.compound || !link_aabb_[a].overlaps(link_aabb_[b])) return false;
    for (size_t i = 0; i < sa.children.size(); ++i) {
      for (size_t j = 0; j < sb.children.size(); ++j) {
        if (!child_aabb_[a][i].overlaps(child_aabb_[b][j])) continue;
        btVoronoiSimplexSolver simplex;
        btGjkEpaPenetrationDepthSolver epa;
        btGjkPairDetector gjk(sa.children[i].get(), sb.children[j].get(), &simplex, &epa);
        btDiscreteCollisionDetectorInterface::ClosestPointInput input;
        input.m_transformA = child_pose(a, i);
        input.m_transformB = child_pose(b, j);
        const double reach = sa.children[i]->getMargin() + sb.children[j]->getMargin();
        input.m_maximumDistanceSquared = reach * reach;
        btPointCollector result;
        gjk.getClosestPoints(input, result, nullptr);
        if (result.m_hasResult && result.m_distance < 0.0) return true;
      }
    }
    return false;
  }

  std::optional<LinkObjectProximity> link_object_proximity(int link,
                                                           double max_distance_m) override {
    const LinkShape& s = links_.at(link);
    if (!s.compound) return std::nullopt;
    const btVector3 pad(max_distance_m, max_distance_m, max_distance_m);
    bool found = false;
    btPointCollector best;
    for (size_t c = 0; c < s.children.size(); ++c) {
      const Aabb3 box{child_aabb_[link][c].lo - pad, child_aabb_[link][c].hi + pad};
      if (!box.overlaps(object_aabb_)) continue;
      TriangleQuery q(s.children[c].get(), child_pose(link, c), max_distance_m, false);
      object_->shape->processAllTriangles(&q, box.lo, box.hi);
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

  std::unique_ptr<bullet::ObjectMeshShape> object_;
  Aabb3 object_aabb_;
  std::vector<LinkShape> links_;
  std::vector<btTransform> X_OL_;
  std::vector<std::vector<Aabb3>> child_aabb_;
  std::vector<Aabb3> link_aabb_;
};

}  // namespace

std::unique_ptr<HandObjectCollider> make_bullet_hand_collider(
    const HandModel& hand, const Mesh& object, const BulletColliderParams& params) {
  return std::make_unique<BulletHandCollider>(hand, object, params);
}

}  // namespace cordgrasp
