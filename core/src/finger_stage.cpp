#include "cordgrasp/core/finger_stage.h"

#include <algorithm>
#include <optional>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cordgrasp/core/kinematics.h"

namespace cordgrasp {

namespace {

// Bisection stops when the remaining interval moves a joint by less than this [rad or m].
constexpr double kMinBisectionStep = 1e-6;
constexpr int kMaxBisections = 60;

std::vector<std::vector<int>> child_joints(const HandModel& hand) {
  std::vector<std::vector<int>> out(hand.links.size());
  for (size_t j = 0; j < hand.joints.size(); ++j)
    out[static_cast<size_t>(hand.joints[j].parent_link)].push_back(static_cast<int>(j));
  return out;
}

void collect_subtree(const HandModel& hand, const std::vector<std::vector<int>>& children, int link,
                     std::vector<char>& in) {
  in[static_cast<size_t>(link)] = 1;
  for (int j : children[static_cast<size_t>(link)])
    collect_subtree(hand, children, hand.joints[static_cast<size_t>(j)].child_link, in);
}

int link_depth(const HandModel& hand, int link) {
  int depth = 0;
  while (hand.links[static_cast<size_t>(link)].parent_joint >= 0) {
    link = hand.joints[static_cast<size_t>(hand.links[static_cast<size_t>(link)].parent_joint)]
               .parent_link;
    ++depth;
  }
  return depth;
}

bool has_collision(const Link& link) { return !link.collisions.empty(); }

// Centre of a link's geometry in its own frame: mean of the element centres (collision, else
// visual, else the link origin).
Eigen::Vector3d geometry_center_L(const Link& link) {
  const auto& elements = link.collisions.empty() ? link.visuals : link.collisions;
  if (elements.empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Geometry& g : elements) {
    Eigen::Vector3d c_G = Eigen::Vector3d::Zero();
    if (g.kind == Geometry::Kind::kMesh && g.mesh && !g.mesh->vertices.empty()) {
      Eigen::Vector3d lo = g.mesh->vertices[0], hi = lo;
      for (const auto& v : g.mesh->vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      c_G = 0.5 * (lo + hi);
    }
    sum += g.X_LG * c_G;
  }
  return sum / static_cast<double>(elements.size());
}

// Moving joints on the tree path between two links.
int moving_joints_between(const HandModel& hand, int a, int b) {
  auto chain = [&](int link) {
    std::vector<int> joints;  // joints from link up to the root
    while (hand.links[static_cast<size_t>(link)].parent_joint >= 0) {
      const int j = hand.links[static_cast<size_t>(link)].parent_joint;
      joints.push_back(j);
      link = hand.joints[static_cast<size_t>(j)].parent_link;
    }
    return joints;
  };
  std::vector<int> ca = chain(a), cb = chain(b);
  while (!ca.empty() && !cb.empty() && ca.back() == cb.back()) {
    ca.pop_back();
    cb.pop_back();
  }
  int moving = 0;
  for (int j : ca) moving += hand.joints[static_cast<size_t>(j)].is_moving() ? 1 : 0;
  for (int j : cb) moving += hand.joints[static_cast<size_t>(j)].is_moving() ? 1 : 0;
  return moving;
}

Eigen::VectorXd coupled(const HandModel& hand, const Eigen::VectorXd& q) {
  return clamp_to_limits(hand, apply_couplings(hand, q));
}

}  // namespace

const char* to_string(FingerStatus status) {
  switch (status) {
    case FingerStatus::kOk:
      return "ok";
    case FingerStatus::kNoContact:
      return "no_contact";
    case FingerStatus::kOneContact:
      return "one_contact";
    case FingerStatus::kCannotRetreat:
      return "cannot_retreat";
  }
  return "unknown";
}

Eigen::Matrix3d thumb_calibration(const HandModel& hand, const Eigen::VectorXd& q_preshape) {
  const auto X_BL = link_poses(hand, q_preshape);
  const Eigen::Isometry3d X_BG = gcp_pose(hand, X_BL);
  const Eigen::Isometry3d X_GB = X_BG.inverse();
  auto tip_G = [&](int link) {
    return Eigen::Vector3d(X_GB * (X_BL[static_cast<size_t>(link)] *
                                   geometry_center_L(hand.links[static_cast<size_t>(link)])));
  };
  auto deepest = [&](const std::vector<int>& links) {
    int best = -1, best_depth = -1;
    for (int l : links) {
      const int d = link_depth(hand, l);
      if (d > best_depth) {
        best = l;
        best_depth = d;
      }
    }
    return best;
  };
  if (hand.thumb_links.empty()) return Eigen::Matrix3d::Identity();
  const int thumb_tip = deepest(hand.thumb_links);

  // Links of the thumb's chains (the named thumb links and everything they carry).
  const auto children = child_joints(hand);
  std::vector<char> thumb(hand.links.size(), 0);
  for (int l : hand.thumb_links) collect_subtree(hand, children, l, thumb);
  // One tip per actor: its outermost non-thumb link (a gripper actor moving both fingers
  // through a mimic joint yields the non-thumb finger).
  std::vector<Eigen::Vector3d> tips;
  for (const Actor& actor : hand.actors) {
    std::vector<char> in(hand.links.size(), 0);
    for (const auto& e : actor.joints)
      collect_subtree(hand, children, hand.joints[static_cast<size_t>(e.joint)].child_link, in);
    for (size_t j = 0; j < hand.joints.size(); ++j) {  // mimic followers move with the actor
      const auto& m = hand.joints[j].mimic;
      if (!m) continue;
      for (const auto& e : actor.joints)
        if (e.joint == m->master_joint)
          collect_subtree(hand, children, hand.joints[j].child_link, in);
    }
    std::vector<int> links, any;
    for (size_t l = 0; l < in.size(); ++l) {
      if (!in[l] || thumb[l]) continue;
      any.push_back(static_cast<int>(l));
      if (has_collision(hand.links[l])) links.push_back(static_cast<int>(l));
    }
    if (links.empty()) links = any;
    if (!links.empty()) tips.push_back(tip_G(deepest(links)));
  }
  if (tips.empty()) return Eigen::Matrix3d::Identity();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& t : tips) centroid += t;
  centroid /= static_cast<double>(tips.size());
  Eigen::Vector3d o = centroid - tip_G(thumb_tip);
  o.z() = 0.0;
  if (o.norm() < 1e-9) return Eigen::Matrix3d::Identity();
  o.normalize();
  Eigen::Matrix3d R;
  R.col(0) = o;
  R.col(1) = Eigen::Vector3d::UnitZ().cross(o);
  R.col(2) = Eigen::Vector3d::UnitZ();
  return R;
}

HandSetup prepare_hand(const HandModel& hand, HandObjectCollider& collider) {
  if (hand.actors.empty())
    throw std::invalid_argument("prepare_hand: hand '" + hand.name + "' has no actor");
  if (collider.num_links() != static_cast<int>(hand.links.size()))
    throw std::invalid_argument("prepare_hand: collider has " +
                                std::to_string(collider.num_links()) + " links, hand '" +
                                hand.name + "' has " + std::to_string(hand.links.size()));
  HandSetup s;
  s.num_links = static_cast<int>(hand.links.size());
  Eigen::VectorXd q0 = hand.preshape;
  if (q0.size() != static_cast<Eigen::Index>(hand.joints.size()))
    q0 = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  s.q_preshape = coupled(hand, q0);

  const auto children = child_joints(hand);
  std::vector<char> in_any(hand.links.size(), 0);
  for (const Actor& actor : hand.actors) {
    std::vector<int> joints;
    std::vector<char> own(hand.joints.size(), 0);
    for (const auto& e : actor.joints) own[static_cast<size_t>(e.joint)] = 1;
    for (size_t j = 0; j < hand.joints.size(); ++j) {
      const auto& m = hand.joints[j].mimic;
      if (own[j] || (m && own[static_cast<size_t>(m->master_joint)]))
        joints.push_back(static_cast<int>(j));
    }
    std::vector<char> in(hand.links.size(), 0);
    for (int j : joints)
      collect_subtree(hand, children, hand.joints[static_cast<size_t>(j)].child_link, in);
    std::vector<int> links;
    for (size_t l = 0; l < in.size(); ++l) {
      if (!in[l]) continue;
      in_any[l] = 1;
      if (collider.has_geometry(static_cast<int>(l))) links.push_back(static_cast<int>(l));
    }
    s.actor_joints.push_back(joints);
    s.actor_links.push_back(links);
  }
  for (size_t l = 0; l < hand.links.size(); ++l)
    if (!in_any[l] && collider.has_geometry(static_cast<int>(l)))
      s.static_links.push_back(static_cast<int>(l));

  const auto X_BL = link_poses(hand, s.q_preshape);
  collider.set_link_poses(X_BL);
  const size_t n = hand.links.size();
  s.ignore_pair.assign(n * n, 0);
  for (size_t a = 0; a < n; ++a) {
    for (size_t b = a + 1; b < n; ++b) {
      const int ia = static_cast<int>(a), ib = static_cast<int>(b);
      bool ignore = !collider.has_geometry(ia) || !collider.has_geometry(ib) ||
                    moving_joints_between(hand, ia, ib) <= 1 || collider.links_collide(ia, ib);
      s.ignore_pair[a * n + b] = s.ignore_pair[b * n + a] = ignore ? 1 : 0;
    }
  }
  s.R_GH = thumb_calibration(hand, s.q_preshape);
  s.X_GB = gcp_pose(hand, X_BL).inverse();
  return s;
}

Eigen::Isometry3d gcp_pose_for_region(const GraspRegion& region, const Eigen::Matrix3d& R_GH,
                                      bool flip_roll) {
  Eigen::Vector3d z = region.p_m - region.p1;
  if (z.norm() <= 0.0) z = -region.p1;  // degenerate: aim at the object frame origin
  z.normalize();
  Eigen::Vector3d o = region.p_r - region.p_l;
  o -= o.dot(z) * z;
  if (o.norm() < 1e-12) {
    // P_l, P_r aligned with the approach: use the guide-plane normal to fix the roll.
    o = region.normal.cross(z);
  }
  o.normalize();
  if (flip_roll) o = -o;
  Eigen::Matrix3d W;
  W.col(0) = o;
  W.col(1) = z.cross(o);
  W.col(2) = z;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = W * R_GH.transpose();
  X.translation() = region.p1;
  return X;
}

void close_fingers(const HandModel& hand, const HandSetup& setup, HandObjectCollider& collider,
                   const Eigen::Isometry3d& X_OB, const Eigen::VectorXd& q_start,
                   const FingerParams& params, FingerResult& result) {
  enum class Hit { kNone, kObject, kLink };
  const size_t n = static_cast<size_t>(setup.num_links);
  const size_t num_actors = setup.actor_links.size();

  Eigen::VectorXd q = q_start;
  collider.set_link_poses(link_poses(hand, q, X_OB));

  auto set_actor_poses = [&](size_t a, const Eigen::VectorXd& qa) {
    const auto X = link_poses(hand, qa, X_OB);
    for (int l : setup.actor_links[a]) collider.set_link_pose(l, X[static_cast<size_t>(l)]);
  };
  // Self-collision pairs each actor checks: its links against every other link with geometry
  // (other actors, static links) except ignored neighbours.
  std::vector<std::vector<std::pair<int, int>>> pairs(num_actors);
  for (size_t a = 0; a < num_actors; ++a) {
    std::vector<char> mine(n, 0);
    for (int l : setup.actor_links[a]) mine[static_cast<size_t>(l)] = 1;
    for (int l : setup.actor_links[a])
      for (size_t m = 0; m < n; ++m)
        if (!mine[m] && !setup.ignore_pair[static_cast<size_t>(l) * n + m])
          pairs[a].emplace_back(l, static_cast<int>(m));
  }
  auto actor_hit = [&](size_t a) {
    for (int l : setup.actor_links[a])
      if (collider.link_collides_with_object(l)) return Hit::kObject;
    for (const auto& [l, m] : pairs[a])
      if (collider.links_collide(l, m)) return Hit::kLink;
    return Hit::kNone;
  };
  auto near_object = [&](size_t a) {
    for (int l : setup.actor_links[a])
      if (collider.link_object_proximity(l, params.contact_tolerance_m)) return true;
    return false;
  };

  // Simox EndEffectorActor::moveActorCheckCollision ([S14]): within an iteration each joint of an
  // actor moves on its own (mimic followers through apply_couplings) and is reverted alone when
  // the actor then collides; the actor is finished when none of its joints can move. A finger
  // whose proximal link touches keeps curling its outer joints (it wraps) instead of freezing.
  struct JointStep {
    Eigen::VectorXd delta;  // one closing step of this joint (and, via couplings, followers)
    double size = 0.0;      // |step| of the joint [rad or m]
    bool blocked = false;   // reverted on collision or at its limit
  };
  std::vector<std::vector<JointStep>> steps(num_actors);
  for (size_t a = 0; a < num_actors; ++a) {
    for (const auto& e : hand.actors[a].joints) {
      JointStep js;
      js.delta = Eigen::VectorXd::Zero(q.size());
      js.delta[e.joint] = params.close_step * e.direction_speed;
      js.size = std::abs(js.delta[e.joint]);
      js.blocked = js.size <= 0.0;
      steps[a].push_back(std::move(js));
    }
  }
  auto actor_moves = [&](size_t a, const Eigen::VectorXd& q_try) {
    for (int j : setup.actor_joints[a])
      if (q_try[j] != q[j]) return true;
    return false;
  };
  // Moves one joint of actor a by its full step; on a hit, bisects down to the last free pose
  // (stopping once a link is within the contact tolerance of the object). Returns true when the
  // joint moved by its full step (it may keep going).
  auto step_joint = [&](size_t a, JointStep& js, bool bisect) {
    const Eigen::VectorXd q_try = coupled(hand, q + js.delta);
    if (!actor_moves(a, q_try)) {  // at its limit
      js.blocked = true;
      return false;
    }
    set_actor_poses(a, q_try);
    Hit hit = actor_hit(a);
    if (hit == Hit::kNone) {
      q = q_try;
      return true;
    }
    set_actor_poses(a, q);
    js.blocked = true;
    if (!bisect) return false;
    double lo = 0.0, hi = 1.0;
    bool done = hit == Hit::kObject && near_object(a);
    for (int it = 0; !done && it < kMaxBisections; ++it) {
      if ((hi - lo) * js.size < kMinBisectionStep) break;
      const double mid = 0.5 * (lo + hi);
      const Eigen::VectorXd q_mid = coupled(hand, q + mid * js.delta);
      set_actor_poses(a, q_mid);
      const Hit h = actor_hit(a);
      if (h != Hit::kNone) {
        hi = mid;
        hit = h;
      } else {
        lo = mid;
        done = hit == Hit::kObject && near_object(a);
      }
    }
    q = coupled(hand, q + lo * js.delta);
    set_actor_poses(a, q);
    return false;
  };
  auto actor_finished = [&](size_t a) {
    for (const JointStep& js : steps[a])
      if (!js.blocked) return false;
    return true;
  };

  int iterations = 0;
  while (iterations < params.max_close_iterations) {
    bool any_open = false;
    for (size_t a = 0; a < num_actors; ++a) any_open = any_open || !actor_finished(a);
    if (!any_open) {
      // Simox re-runs closeActors from the reached joint values until a pass moves nothing
      // (docs/algorithm.md §7.4): a joint stopped by another finger may be free once that finger
      // has stopped. Re-test each blocked joint with one full step, without bisection (no
      // creeping).
      bool reopened = false;
      for (size_t a = 0; a < num_actors; ++a)
        for (JointStep& js : steps[a])
          if (js.size > 0.0 && step_joint(a, js, false)) {
            js.blocked = false;
            reopened = true;
          }
      ++iterations;
      if (!reopened) break;
      continue;
    }
    ++iterations;
    for (size_t a = 0; a < num_actors; ++a)
      for (JointStep& js : steps[a])
        if (!js.blocked) step_joint(a, js, true);
  }
  result.q = q;
  result.close_iterations = iterations;
  result.contacts.clear();
  collider.set_link_poses(link_poses(hand, q, X_OB));
  auto add_contact = [&](int l) {
    const auto prox = collider.link_object_proximity(l, params.contact_tolerance_m);
    if (!prox) return;
    Contact c;
    c.link = l;
    c.p_O = prox->p_object_O;
    c.n_O = prox->n_O;
    result.contacts.push_back(c);
  };
  for (size_t a = 0; a < num_actors; ++a)
    for (int l : setup.actor_links[a]) add_contact(l);
  if (params.static_link_contacts)
    for (int l : setup.static_links) add_contact(l);
  const int count = static_cast<int>(result.contacts.size());
  result.status = count == 0                    ? FingerStatus::kNoContact
                  : count < params.min_contacts ? FingerStatus::kOneContact
                                                : FingerStatus::kOk;
}

namespace {

/// FingerParams::centre_single_actor: one pad touches, the opposite one is short of the object;
/// the hand moves half the difference of their gaps along the opposite pad's way to the object
/// and closes again from preshape.
/// Keeps `r` unless the new closing has more contacts at a collision-free shifted pose.
template <typename Collides>
void centre_single_actor(const HandModel& hand, const HandSetup& setup,
                         HandObjectCollider& collider, const FingerParams& params,
                         const Collides& hand_collides, FingerResult& r) {
  const Contact& touching = r.contacts.front();
  collider.set_link_poses(link_poses(hand, r.q, r.X_OB));
  std::optional<LinkObjectProximity> opposite;
  for (int l : setup.actor_links.front()) {
    if (l == touching.link) continue;
    const auto prox = collider.link_object_proximity(l, params.centre_max_gap_m);
    if (!prox || prox->distance_m <= params.contact_tolerance_m) continue;
    const Eigen::Vector3d way = prox->p_object_O - prox->p_link_O;  // link → object
    if (way.normalized().dot(touching.n_O) < 0.5) continue;  // not across the object
    if (!opposite || prox->distance_m < opposite->distance_m) opposite = prox;
  }
  const auto touching_gap = collider.link_object_proximity(touching.link, params.centre_max_gap_m);
  if (!opposite || !touching_gap) return;
  // Both pads end equally far from the object: the touching one stopped up to the contact
  // tolerance short of it, so split the difference of the two gaps.
  const Eigen::Vector3d shift = 0.5 * (opposite->distance_m - touching_gap->distance_m) *
                                (opposite->p_object_O - opposite->p_link_O).normalized();
  Eigen::Isometry3d X_OG = r.X_OG;
  X_OG.translation() += shift;
  if (hand_collides(X_OG)) return;
  FingerResult centred = r;
  centred.X_OG = X_OG;
  centred.X_OB = X_OG * setup.X_GB;
  close_fingers(hand, setup, collider, centred.X_OB, setup.q_preshape, params, centred);
  if (centred.contacts.size() > r.contacts.size()) r = std::move(centred);
}

}  // namespace

FingerResult run_finger_stage(const HandModel& hand, const HandSetup& setup,
                              HandObjectCollider& collider, const Eigen::Isometry3d& X_OG_start,
                              double approach_travel_m, const FingerParams& params) {
  FingerResult r;
  r.q_preshape = setup.q_preshape;
  r.q = setup.q_preshape;
  const auto X_BL = link_poses(hand, setup.q_preshape);
  std::vector<Eigen::Isometry3d> X_OL(X_BL.size());
  std::vector<int> geometry_links;
  for (int l = 0; l < setup.num_links; ++l)
    if (collider.has_geometry(l)) geometry_links.push_back(l);

  auto hand_collides = [&](const Eigen::Isometry3d& X_OG) {
    const Eigen::Isometry3d X_OB = X_OG * setup.X_GB;
    for (int l : geometry_links) collider.set_link_pose(l, X_OB * X_BL[static_cast<size_t>(l)]);
    for (int l : geometry_links)
      if (collider.link_collides_with_object(l)) return true;
    return false;
  };

  auto hand_lower_bound = [&]() {
    double bound = std::numeric_limits<double>::infinity();
    for (int l : geometry_links)
      bound = std::min(bound, collider.link_object_distance_lower_bound(l));
    return bound;
  };

  // Approach in steps; steps within the hand's conservative distance bound cannot collide and
  // are taken without a query (same result as checking every step).
  Eigen::Isometry3d X_OG = X_OG_start;
  const Eigen::Vector3d z = X_OG.linear().col(2);
  bool colliding = hand_collides(X_OG);
  double travel = 0.0;
  double free_until = colliding ? 0.0 : hand_lower_bound();
  while (!colliding && travel < approach_travel_m - 1e-12) {
    const double step = std::min(params.approach_step_m, approach_travel_m - travel);
    travel += step;
    X_OG.translation() += step * z;
    ++r.approach_steps;
    if (travel <= free_until) continue;
    colliding = hand_collides(X_OG);
    if (!colliding) free_until = travel + hand_lower_bound();
  }
  // Travel at which the hand first collided (approach) or was last seen colliding (retreat).
  double colliding_travel = travel;
  bool refine = colliding && r.approach_steps > 0;  // the previous approach step was free
  while (colliding) {
    if (r.retreat_steps >= params.max_retreat_steps) {
      r.status = FingerStatus::kCannotRetreat;
      r.X_OG = X_OG;
      r.X_OB = X_OG * setup.X_GB;
      return r;
    }
    colliding_travel = travel;
    travel -= params.retreat_step_m;
    X_OG.translation() -= params.retreat_step_m * z;
    ++r.retreat_steps;
    colliding = hand_collides(X_OG);
    refine = true;
  }
  // Finer steps near contact (as when closing): bisect between the free pose and the colliding
  // one so the hand ends within the contact tolerance of the object, not up to a step away.
  if (refine && params.contact_tolerance_m > 0.0) {
    double lo = travel, hi = colliding_travel;
    while (hi - lo > 0.5 * params.contact_tolerance_m) {
      const double mid = 0.5 * (lo + hi);
      if (hand_collides(X_OG_start * Eigen::Translation3d(0, 0, mid)))
        hi = mid;
      else
        lo = mid;
    }
    travel = lo;
    X_OG = X_OG_start * Eigen::Translation3d(0, 0, lo);
  }
  r.X_OG = X_OG;
  r.X_OB = X_OG * setup.X_GB;
  close_fingers(hand, setup, collider, r.X_OB, setup.q_preshape, params, r);
  if (params.centre_single_actor && setup.actor_links.size() == 1 &&
      r.status == FingerStatus::kOneContact && r.contacts.size() == 1)
    centre_single_actor(hand, setup, collider, params, hand_collides, r);
  return r;
}

}  // namespace cordgrasp
