// The physics validation protocol (docs/physics.md §3): world set-up, the base trajectory, joint
// servos, and the phases settle, close, lift, shake and gravity6.
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/weight_margin.h"
#include "cordgrasp/sim/motion_profiles.h"
#include "cordgrasp/sim/turn_keeps_surface.h"
#include "cordgrasp/sim/validate_grasp.h"
#include "hand_multibody.h"
#include "object_body.h"

namespace cordgrasp {

namespace {

/// Impulse a motor or gear row applied in the last step; 0 for one the solver never ran (its
/// joint's link and base have no collider, so it is in no island, and Bullet allocates its
/// rows only when it first solves them).
double applied_impulse(btMultiBodyConstraint& c) {
  if (c.getIslandIdA() < 0 && c.getIslandIdB() < 0) return 0.0;
  return c.getAppliedImpulse(0);
}

using bullet::from_bt;
using bullet::to_bt;

constexpr int kObjectGroup = 1;
constexpr int kHandGroup = 2;

/// Lever of revolute actor joints of a grasp without planned contacts in the bounded close: a
/// finger's length [m].
constexpr double kFingerLever_m = 0.05;
/// Friction coefficient below which the weight-scaled squeeze stops growing [-].
constexpr double kMinFrictionForForce = 0.1;

double angle_of(const Eigen::Matrix3d& R) { return Eigen::AngleAxisd(R).angle(); }

/// Rotation vector (axis × angle) of R.
Eigen::Vector3d rotation_vector(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.axis() * aa.angle();
}

bool finite(const btVector3& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

}  // namespace

struct GraspSimulation::Impl {
  HandModel hand;
  Grasp grasp;
  SimParams params;
  double dt = 1.0 / 240.0;

  std::unique_ptr<btDefaultCollisionConfiguration> config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<btMultiBodyConstraintSolver> solver;
  std::unique_ptr<btMultiBodyDynamicsWorld> world;
  std::unique_ptr<bullet::HandMultiBody> hand_body;
  std::unique_ptr<bullet::ObjectBody> object;
  const ObjectSurface* surface = nullptr;  ///< for turned_past_limit()

  Eigen::Isometry3d X_WO0 = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d X_WB_cmd = Eigen::Isometry3d::Identity();  ///< commanded root pose
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  double time_s = 0.0;

  // Servo targets and speed caps, per HandModel joint.
  Eigen::VectorXd q_target;
  Eigen::VectorXd speed_cap;
  Eigen::VectorXd qd_feedforward;  ///< added to the servo's commanded speed
  /// Spring gain of compliant servos [N·m/rad or N/m]: the effort is capped at gain × error
  /// (0: rigid servo, capped at the effort limit only).
  Eigen::VectorXd spring_gain;
  /// Effort cap of the bounded squeeze (SimParams::squeeze_travel_m) [N·m or N]; 0: the limit.
  Eigen::VectorXd effort_cap;
  /// Bounded squeeze, once the fingers have reached the plan: +1/−1 for joints that push
  /// toward larger/smaller q, which resist with squeeze_hold_factor × their cap when pushed
  /// back behind the plan; 0: the cap applies both ways.
  Eigen::VectorXd hold_sign;
  /// Levers of the joints on the planned contacts at the plan (contact_levers) [m or -].
  Eigen::VectorXd plan_lever;
  /// Squeeze effort of each joint from the close on (close_push(); 0 before, and for joints
  /// that hold the plan) [N·m or N], signed as it pushes.
  Eigen::VectorXd squeeze_push;
  double squeeze_fraction = 1.0;  ///< ramps the springs' effort in at the start of the squeeze
  std::vector<int> actor_joints;     ///< driven joints of the actors
  std::vector<double> actor_sign;    ///< +1/−1: direction that closes
  std::vector<double> actor_speed;   ///< |direction_speed|

  Eigen::Isometry3d X_BO_ref = Eigen::Isometry3d::Identity();  ///< object in hand root frame
  Eigen::VectorXd q_start;  ///< joints at the reach start (SimParams::reach_start_fraction)
  bool closed = false;
  int last_contact_count = 0;  ///< hand–object contacts after the last step of a phase
  PhaseHook segment_hook;
  int trace_every = 0;  ///< steps between trace samples (SimParams::trace_interval_s); 0: off

  // Per-phase accumulators.
  PhaseResult* current = nullptr;
  bool blew_up = false;

  Impl(const Mesh& mesh, const HandModel& h, const Grasp& g, const SimParams& p);
  ~Impl();

  Eigen::Isometry3d X_WB() const { return bullet::root_pose(*hand_body); }
  Eigen::Isometry3d X_WO() const {
    return from_bt(object->body->getCenterOfMassTransform()) * object->X_OC.inverse();
  }
  Eigen::Isometry3d X_BO() const { return X_WB().inverse() * X_WO(); }

  void step(const Eigen::Isometry3d& X_WB_next);
  void contacts(int& count, double& max_penetration) const;
  bool unstable() const;
  /// Squeeze effort of every actor joint [N·m or N], signed (+: toward larger q).
  Eigen::VectorXd squeeze_efforts() const;
  /// `push` scaled down, all actor joints alike, to the weight-proportional grasp force of
  /// SimParams::squeeze_weight_factor (unchanged when the factor is 0 or the limits are weaker).
  Eigen::VectorXd scaled_to_weight(Eigen::VectorXd push) const;
  /// Current world state labelled `phase` (GraspSimulation::snapshot).
  PhaseSnapshot snapshot(const std::string& phase) const;
  /// Starts phase `name` (its wall clock too) with gravity `g_W` [m/s²].
  void begin(PhaseResult& r, const std::string& name, const Eigen::Vector3d& g_W);
  /// Sets the world's gravity [m/s²].
  void set_gravity(const Eigen::Vector3d& g_W);
  /// Fills the pose change and contacts relative to `X_BO_reference`, classifies.
  void finish(PhaseResult& r, const Eigen::Isometry3d& X_BO_reference);
  /// End of a shake or gravity6 segment of phase `r` (`ran`: run() did not stop it): held so
  /// far relative to X_BO_ref? Otherwise names the segment in r.detail.
  bool segment_holds(PhaseResult& r, const std::string& segment, bool ran) const;
  std::chrono::steady_clock::time_point phase_start;
  /// Held, slipped, dropped or unstable from the phase's measures; `turned_past` as
  /// turned_past_limit() for its rotation.
  Outcome classify(const PhaseResult& r, bool turned_past) const;
  /// Whether the object, turned by `turned` from X_BO_reference, is past the held turn:
  /// turned ≥ held_rotation_rad, unless that turn maps its surface onto itself within
  /// contact_distance_m (a body of revolution spinning about its axis).
  bool turned_past_limit(const Eigen::Isometry3d& X_BO_reference, double turned) const;
  /// Runs `duration` seconds along a root trajectory X_WB(t) (t from 0); returns false when the
  /// phase must stop (blown up, the object drop_distance_m off, or failed:
  /// SimParams::exit_on_failure). With `rest_exit`, returns true early once the object has been
  /// at rest in the hand for SimParams::rest_exit_time_s.
  template <class Trajectory>
  bool run(double duration, const Trajectory& trajectory, bool rest_exit = false);
  /// Largest fraction f ≤ SimParams::reach_start_fraction (f, 3f/4, f/2, f/4, 0) at which the
  /// joints q_preshape + f·(q − q_preshape) keep reach_start_clearance_m from the object.
  double reach_start_fraction_clear();
  /// Joints at the reach start of SimParams::reach_start_gap_m: every actor joint with a planned
  /// contact gap / lever short of the plan toward the preshape, the gap doubling while the
  /// hand is within reach_start_clearance_m of the object; the preshape when none is clear.
  Eigen::VectorXd reach_start_with_gap();
  /// Puts the hand's joints at q (base at X_WB_cmd) and empties the contact manifolds, whose
  /// points would otherwise describe the previous pose.
  void place_hand_at(const Eigen::VectorXd& q);
  /// The bounded squeeze (SimParams::squeeze_travel_m > 0) in use.
  bool bounded() const { return params.squeeze_travel_m > 0.0; }
  /// Lever of joint j in the bounded close: its lever on the planned contacts (prismatic: 1);
  /// without any planned contact every joint's, a finger's length; 0: holds the plan.
  double squeeze_lever(int j) const {
    const bool prismatic = hand.joints[static_cast<size_t>(j)].type == JointType::kPrismatic;
    if (grasp.contacts.empty()) return prismatic ? 1.0 : kFingerLever_m;
    if (!(plan_lever[j] > 0.0)) return 0.0;
    return prismatic ? 1.0 : plan_lever[j];
  }
  /// Reach speed cap of every joint: actor joints close_speed × their speed (at most the
  /// URDF's velocity limit), the others hold_speed (prismatic 0.1×) [rad/s or m/s].
  Eigen::VectorXd close_speed_caps() const;
  /// Duration of the reach from q0 to the plan: the slowest driven joint at its cap [s].
  double reach_time(const Eigen::VectorXd& q0, const Eigen::VectorXd& close_cap) const;
  /// Squeeze effort of the close (squeeze_efforts()); in the bounded close 0 for joints
  /// without a planned contact (they hold the plan).
  Eigen::VectorXd close_push() const;
  /// Bounded squeeze target of joint j pushing with `push`: squeeze_travel_m past the plan at
  /// its lever.
  double bounded_squeeze_target(int j, double push) const {
    return grasp.q[j] + std::copysign(params.squeeze_travel_m / squeeze_lever(j), push);
  }
  /// Smallest hand–object distance reported by Bullet's narrow phase for the current poses
  /// (+inf when no pair is within its contact threshold) [m].
  double hand_object_distance();
  double pose_change(const Eigen::Isometry3d& X_BO_reference, double* rotation) const;
};

GraspSimulation::Impl::Impl(const Mesh& mesh, const HandModel& h, const Grasp& g,
                            const SimParams& p)
    : hand(h), grasp(g), params(p), dt(p.time_step_s) {
  const Eigen::Index n = static_cast<Eigen::Index>(hand.joints.size());
  if (grasp.q.size() != n || grasp.q_preshape.size() != n)
    throw std::invalid_argument("validate_grasp: grasp joint vectors have " +
                                std::to_string(grasp.q.size()) + "/" +
                                std::to_string(grasp.q_preshape.size()) + " entries, hand '" +
                                hand.name + "' has " + std::to_string(n) + " joints");
  if (!(dt > 0.0)) throw std::invalid_argument("validate_grasp: time_step_s must be positive");
  if (params.trace_interval_s > 0.0)
    trace_every = std::max(1, static_cast<int>(std::lround(params.trace_interval_s / dt)));
  grasp.q = clamp_to_limits(hand, apply_couplings(hand, grasp.q));
  grasp.q_preshape = clamp_to_limits(hand, apply_couplings(hand, grasp.q_preshape));

  config = std::make_unique<btDefaultCollisionConfiguration>();
  dispatcher = std::make_unique<btCollisionDispatcher>(config.get());
  btGImpactCollisionAlgorithm::registerAlgorithm(dispatcher.get());
  broadphase = std::make_unique<btDbvtBroadphase>();
  solver = std::make_unique<btMultiBodyConstraintSolver>();
  world = std::make_unique<btMultiBodyDynamicsWorld>(dispatcher.get(), broadphase.get(),
                                                     solver.get(), config.get());
  btContactSolverInfo& si = world->getSolverInfo();
  si.m_numIterations = params.solver_iterations;
  si.m_erp = params.erp;
  si.m_erp2 = params.erp;
  si.m_frictionERP = params.friction_erp;
  si.m_globalCfm = params.cfm;
  si.m_linearSlop = params.linear_slop_m;
  si.m_splitImpulse = false;
  si.m_timeStep = dt;
  si.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  if (!params.cone_friction) si.m_solverMode |= SOLVER_DISABLE_IMPLICIT_CONE_FRICTION;
  if (params.articulated_warmstarting) si.m_solverMode |= SOLVER_USE_ARTICULATED_WARMSTARTING;
  si.m_leastSquaresResidualThreshold = params.solver_residual_threshold;
  world->setGravity(btVector3(0, 0, 0));

  // Object.
  object = bullet::make_object_body(mesh, params);
  surface = &object_surface(mesh, object->mesh_key);
  const Eigen::Isometry3d X_OB = grasp.X_OB;
  if (params.world_frame == WorldFrame::kApproachDown) {
    // GCP frame G: +z_G down, x_G = x_W (R_WG = diag(1, −1, −1)), GCP at the world origin.
    const Eigen::Isometry3d X_OG =
        X_OB * root_pose_for_gcp(hand, grasp.q_preshape, Eigen::Isometry3d::Identity()).inverse();
    Eigen::Isometry3d X_WG = Eigen::Isometry3d::Identity();
    X_WG.linear() = Eigen::Vector3d(1, -1, -1).asDiagonal();
    X_WO0 = X_WG * X_OG.inverse();
  }
  object->body->setCenterOfMassTransform(to_bt(Eigen::Isometry3d(X_WO0 * object->X_OC)));
  object->body->setLinearVelocity(btVector3(0, 0, 0));
  object->body->setAngularVelocity(btVector3(0, 0, 0));
  world->addRigidBody(object->body.get(), kObjectGroup, kHandGroup);

  // Hand.
  bullet::HandBodyParams hp;
  hp.sim = params;
  if (params.lock_passive_joints) {
    // Joints no actor drives (abduction, opposition) stay at their planned values, as in the
    // planner's closing; mimic joints follow their master's fate.
    std::vector<bool> driven(hand.joints.size(), false);
    for (const Actor& actor : hand.actors)
      for (const Actor::Entry& e : actor.joints)
        if (e.joint >= 0 && e.joint < static_cast<int>(n)) driven[static_cast<size_t>(e.joint)] = true;
    hp.locked.assign(hand.joints.size(), false);
    for (size_t j = 0; j < hand.joints.size(); ++j) {
      const Joint& joint = hand.joints[j];
      if (!joint.is_moving()) continue;
      const bool follows = joint.mimic && joint.mimic->master_joint >= 0 &&
                           driven[static_cast<size_t>(joint.mimic->master_joint)];
      hp.locked[j] = !driven[j] && !follows;
    }
    hp.lock_values = grasp.q;
  }
  hand_body = bullet::make_hand_multibody(hand, hp);
  X_WB_cmd = X_WO0 * X_OB;
  bullet::place_hand(*hand_body, X_WB_cmd, grasp.q_preshape);
  bullet::add_hand_to_world(*hand_body, *world, kHandGroup, kObjectGroup);
  // Actor joints (the closing ones) and their closing directions.
  for (const Actor& actor : hand.actors)
    for (const Actor::Entry& e : actor.joints) {
      if (e.joint < 0 || e.joint >= static_cast<int>(n) || e.direction_speed == 0.0) continue;
      actor_joints.push_back(e.joint);
      actor_sign.push_back(e.direction_speed > 0.0 ? 1.0 : -1.0);
      actor_speed.push_back(std::abs(e.direction_speed));
    }
  plan_lever = grasp.contacts.empty()
                   ? Eigen::VectorXd::Zero(n)
                   : contact_levers(hand, grasp.q, grasp.X_OB, grasp.contacts);
  q_start = grasp.q_preshape;
  if (params.reach_start_gap_m > 0.0) {
    q_start = reach_start_with_gap();
    place_hand_at(q_start);
  } else if (params.reach_start_fraction > 0.0) {
    const double f = reach_start_fraction_clear();
    q_start = grasp.q_preshape + f * (grasp.q - grasp.q_preshape);
    place_hand_at(q_start);  // the probes' contact points must not carry into the simulation
  }

  q_target = q_start;
  effort_cap = Eigen::VectorXd::Zero(n);
  hold_sign = Eigen::VectorXd::Zero(n);
  squeeze_push = Eigen::VectorXd::Zero(n);
  qd_feedforward = Eigen::VectorXd::Zero(n);
  spring_gain = Eigen::VectorXd::Zero(n);
  speed_cap = Eigen::VectorXd::Constant(n, params.hold_speed);
  for (Eigen::Index j = 0; j < n; ++j)
    if (hand.joints[static_cast<size_t>(j)].type == JointType::kPrismatic)
      speed_cap[j] = 0.1 * params.hold_speed;
}

double GraspSimulation::Impl::hand_object_distance() {
  world->performDiscreteCollisionDetection();
  double nearest = std::numeric_limits<double>::infinity();
  const btCollisionObject* obj = object->body.get();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* pm = dispatcher->getManifoldByIndexInternal(m);
    if (pm->getBody0() != obj && pm->getBody1() != obj) continue;
    for (int c = 0; c < pm->getNumContacts(); ++c)
      nearest = std::min(nearest, static_cast<double>(pm->getContactPoint(c).getDistance()));
  }
  return nearest;
}

double GraspSimulation::Impl::reach_start_fraction_clear() {
  const double f = std::min(1.0, params.reach_start_fraction);
  for (int quarters = 4; quarters >= 1; --quarters) {
    const double fraction = f * quarters / 4.0;
    place_hand_at(grasp.q_preshape + fraction * (grasp.q - grasp.q_preshape));
    if (hand_object_distance() >= params.reach_start_clearance_m) return fraction;
  }
  return 0.0;
}

void GraspSimulation::Impl::place_hand_at(const Eigen::VectorXd& q) {
  bullet::place_hand(*hand_body, X_WB_cmd, q);
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m)
    dispatcher->getManifoldByIndexInternal(m)->clearManifold();
}

Eigen::VectorXd GraspSimulation::Impl::reach_start_with_gap() {
  const auto start_for = [&](double gap_m) {
    Eigen::VectorXd q = grasp.q;
    for (const int j : actor_joints) {
      const double lever = squeeze_lever(j);
      if (!(lever > 0.0)) continue;
      const double back = grasp.q_preshape[j] - grasp.q[j];
      const double step = std::min(std::abs(back), gap_m / lever);
      q[j] += back >= 0.0 ? step : -step;
    }
    return clamp_to_limits(hand, apply_couplings(hand, q));
  };
  for (int doubling = 0; doubling < 4; ++doubling) {
    const Eigen::VectorXd q = start_for(params.reach_start_gap_m * std::ldexp(1.0, doubling));
    place_hand_at(q);
    if (hand_object_distance() >= params.reach_start_clearance_m) return q;
  }
  return grasp.q_preshape;
}

GraspSimulation::Impl::~Impl() {
  if (world) {
    if (hand_body) bullet::remove_hand_from_world(*hand_body, *world);
    if (object) world->removeRigidBody(object->body.get());
  }
  world.reset();
}

void GraspSimulation::Impl::step(const Eigen::Isometry3d& X_WB_next) {
  btMultiBody& mb = *hand_body->mb;
  // Base (the arm's flange): heavy, its velocity commanded each step so that it reaches the
  // trajectory's next pose; the solver sees the motion as velocity, never a jump.
  const Eigen::Isometry3d X_CR = hand_body->X_CL[static_cast<size_t>(hand.root_link)];
  const Eigen::Isometry3d X_WC_next = X_WB_next * X_CR.inverse();
  const Eigen::Isometry3d X_WC = bullet::body_pose(*hand_body, 0);
  const Eigen::Vector3d v = (X_WC_next.translation() - X_WC.translation()) / dt;
  const Eigen::Vector3d w =
      rotation_vector(X_WC_next.linear() * X_WC.linear().transpose()) / dt;
  mb.setBaseVel(to_bt(v));
  mb.setBaseOmega(to_bt(w));
  X_WB_cmd = X_WB_next;

  // Joint servos: speed toward the target, capped; the motor's impulse cap is the effort limit.
  for (size_t k = 0; k < hand_body->motors.size(); ++k) {
    const int j = hand_body->motor_joint[k];
    const int i = hand_body->joint_mb_link[static_cast<size_t>(j)];
    const double error = q_target[j] - mb.getJointPos(i);
    const double cap = speed_cap[j];
    const double speed =
        std::clamp(qd_feedforward[j] + params.servo_gain_per_s * error, -cap, cap);
    hand_body->motors[k]->setVelocityTarget(speed, 1.0);
    double effort = hand_body->effort_limit[static_cast<size_t>(j)];
    if (effort_cap[j] > 0.0) {
      // Bounded squeeze: gentle past the plan, stiffer (squeeze_hold_factor) when pushed back.
      const bool behind = hold_sign[j] * (grasp.q[j] - mb.getJointPos(i)) > 0.0;
      const double cap = behind ? params.squeeze_hold_factor * effort_cap[j] : effort_cap[j];
      effort = squeeze_fraction * std::min(effort, cap);
    }
    if (spring_gain[j] > 0.0)
      effort = squeeze_fraction * std::min(effort, spring_gain[j] * std::abs(error));
    hand_body->motors[k]->setMaxAppliedImpulse(effort * dt);
  }

  // Gravity compensation of the hand (the world adds m·g to every link).
  if (params.hand_gravity_compensation && gravity.squaredNorm() > 0.0) {
    mb.addBaseForce(to_bt(Eigen::Vector3d(-mb.getBaseMass() * gravity)));
    for (int i = 0; i < mb.getNumLinks(); ++i)
      mb.addLinkForce(i, to_bt(Eigen::Vector3d(-mb.getLinkMass(i) * gravity)));
  }
  world->stepSimulation(dt, 0, dt);
  time_s += dt;

  if (current) {
    ++current->steps;
    current->sim_time_s += dt;
    int count = 0;
    double penetration = 0.0;
    contacts(count, penetration);
    current->max_contact_count = std::max(current->max_contact_count, count);
    last_contact_count = count;
    current->max_penetration_m = std::max(current->max_penetration_m, penetration);
  }
  if (unstable()) blew_up = true;
  if (trace_every > 0 && segment_hook && current && current->steps % trace_every == 0) {
    PhaseSnapshot sample = snapshot(current->name);
    sample.phase_end = false;
    segment_hook(sample);
  }
}

PhaseSnapshot GraspSimulation::Impl::snapshot(const std::string& phase) const {
  PhaseSnapshot out;
  out.phase = phase;
  out.sim_time_s = time_s;
  out.X_WO = X_WO();
  out.X_WL = bullet::hand_link_poses(*hand_body);
  out.q = bullet::hand_joint_positions(*hand_body, static_cast<int>(hand.joints.size()));
  const bool planned_reference = !closed || phase == "settle" || phase == "close";
  out.object_shift_m =
      pose_change(planned_reference ? grasp.X_OB.inverse() : X_BO_ref, &out.object_turn_rad);
  double penetration = 0.0;
  contacts(out.contact_count, penetration);
  return out;
}

void GraspSimulation::Impl::contacts(int& count, double& max_penetration) const {
  count = 0;
  max_penetration = 0.0;
  const btCollisionObject* obj = object->body.get();
  const int manifolds = dispatcher->getNumManifolds();
  for (int m = 0; m < manifolds; ++m) {
    const btPersistentManifold* pm = dispatcher->getManifoldByIndexInternal(m);
    if (pm->getBody0() != obj && pm->getBody1() != obj) continue;
    for (int c = 0; c < pm->getNumContacts(); ++c) {
      const double d = pm->getContactPoint(c).getDistance();
      if (d < params.contact_distance_m) ++count;
      max_penetration = std::max(max_penetration, -d);
    }
  }
}

bool GraspSimulation::Impl::unstable() const {
  const btRigidBody& o = *object->body;
  const btMultiBody& mb = *hand_body->mb;
  if (!finite(o.getCenterOfMassPosition()) || !finite(o.getLinearVelocity()) ||
      !finite(o.getAngularVelocity()) || !finite(mb.getBasePos()) || !finite(mb.getBaseVel()))
    return true;
  for (int i = 0; i < mb.getNumLinks(); ++i)
    if (!std::isfinite(mb.getJointPos(i)) || !std::isfinite(mb.getJointVel(i))) return true;
  const double limit = params.unstable_speed_mps;
  if (o.getLinearVelocity().length() > limit || mb.getBaseVel().length() > limit) return true;
  // Link speeds: joint speed × a 0.2 m lever bounds a finger link's speed.
  for (int i = 0; i < mb.getNumLinks(); ++i) {
    const double qd = std::abs(mb.getJointVel(i));
    const bool prismatic = mb.getLink(i).m_jointType == btMultibodyLink::ePrismatic;
    if ((prismatic ? qd : 0.2 * qd) > limit) return true;
  }
  return false;
}

double GraspSimulation::Impl::pose_change(const Eigen::Isometry3d& X_BO_reference,
                                          double* rotation) const {
  // Object motion relative to the hand, measured at the object's centre of mass.
  const Eigen::Isometry3d X_BO_now = X_BO();
  const Eigen::Vector3d com_O = object->X_OC.translation();
  const double translation = ((X_BO_now * com_O) - (X_BO_reference * com_O)).norm();
  if (rotation) *rotation = angle_of(X_BO_reference.linear().transpose() * X_BO_now.linear());
  return translation;
}

void GraspSimulation::Impl::begin(PhaseResult& r, const std::string& name,
                                  const Eigen::Vector3d& g_W) {
  phase_start = std::chrono::steady_clock::now();
  r = PhaseResult{};
  r.name = name;
  current = &r;
  set_gravity(g_W);
}

void GraspSimulation::Impl::set_gravity(const Eigen::Vector3d& g_W) {
  gravity = g_W;
  world->setGravity(to_bt(g_W));
}

bool GraspSimulation::Impl::segment_holds(PhaseResult& r, const std::string& segment,
                                          bool ran) const {
  PhaseResult probe = r;
  if (!blew_up) {
    probe.translation_m = pose_change(X_BO_ref, &probe.rotation_rad);
    double penetration = 0.0;
    contacts(probe.contact_count, penetration);
    probe.in_contact = probe.contact_count > 0;
  }
  if (ran && classify(probe, turned_past_limit(X_BO_ref, probe.rotation_rad)) == Outcome::kHeld)
    return true;
  r.detail = segment;
  return false;
}

Outcome GraspSimulation::Impl::classify(const PhaseResult& r, bool turned_past) const {
  if (blew_up) return Outcome::kUnstable;
  if (!r.in_contact) return Outcome::kDropped;
  if (r.translation_m < params.held_translation_m && !turned_past) return Outcome::kHeld;
  return Outcome::kSlipped;
}

bool GraspSimulation::Impl::turned_past_limit(const Eigen::Isometry3d& X_BO_reference,
                                              double turned) const {
  if (turned < params.held_rotation_rad) return false;
  const Eigen::Matrix3d R_O = X_BO_reference.linear().transpose() * X_BO().linear();
  return !turn_keeps_surface(*surface, R_O, params.contact_distance_m);
}

void GraspSimulation::Impl::finish(PhaseResult& r, const Eigen::Isometry3d& X_BO_reference) {
  current = nullptr;
  if (!blew_up) {
    r.translation_m = pose_change(X_BO_reference, &r.rotation_rad);
    r.max_translation_m = std::max(r.max_translation_m, r.translation_m);
    double penetration = 0.0;
    contacts(r.contact_count, penetration);
    r.in_contact = r.contact_count > 0;
  }
  r.outcome = classify(r, !blew_up && turned_past_limit(X_BO_reference, r.rotation_rad));
  r.joint_efforts.assign(hand.joints.size(), 0.0);
  for (size_t k = 0; k < hand_body->motors.size(); ++k)
    r.joint_efforts[static_cast<size_t>(hand_body->motor_joint[k])] =
        applied_impulse(*hand_body->motors[k]) / dt;
  for (size_t k = 0; k < hand_body->gears.size(); ++k)
    r.joint_efforts[static_cast<size_t>(hand_body->gear_joint[k])] =
        applied_impulse(*hand_body->gears[k]) / dt;
  r.squeeze_effort_ratio = 0.0;
  for (const int j : actor_joints)
    if (squeeze_push[j] != 0.0)
      r.squeeze_effort_ratio = std::max(r.squeeze_effort_ratio,
                                        r.joint_efforts[static_cast<size_t>(j)] / squeeze_push[j]);
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - phase_start).count();
}

template <class Trajectory>
bool GraspSimulation::Impl::run(double duration, const Trajectory& trajectory, bool rest_exit) {
  const int steps = static_cast<int>(std::lround(duration / dt));
  const bool exit_on_failure = params.exit_on_failure && closed && current;
  const int rest_steps =
      rest_exit && params.rest_exit_time_s > 0.0
          ? std::max(1, static_cast<int>(std::lround(params.rest_exit_time_s / dt)))
          : 0;
  const int no_contact_steps =
      std::max(1, static_cast<int>(std::lround(params.no_contact_exit_time_s / dt)));
  int at_rest = 0;  // steps the object has stayed within the rest drift of X_BO_rest
  Eigen::Isometry3d X_BO_rest = X_BO();
  int without_contact = 0;
  for (int s = 1; s <= steps; ++s) {
    step(trajectory(s * dt));
    if (blew_up) return false;
    if (closed && current) {
      double turned = 0.0;
      const double moved = pose_change(X_BO_ref, exit_on_failure ? &turned : nullptr);
      current->max_translation_m = std::max(current->max_translation_m, moved);
      if (moved > params.drop_distance_m) return false;
      if (exit_on_failure) {
        if (moved >= params.held_translation_m || turned_past_limit(X_BO_ref, turned)) return false;
        without_contact = last_contact_count > 0 ? 0 : without_contact + 1;
        if (without_contact >= no_contact_steps) return false;
      }
    }
    if (rest_steps > 0) {
      double turned = 0.0;
      const double drift = pose_change(X_BO_rest, &turned);
      if (drift < params.rest_drift_m && turned < params.rest_drift_rad) {
        if (++at_rest >= rest_steps) return true;
      } else {
        at_rest = 0;
        X_BO_rest = X_BO();
      }
    }
  }
  return true;
}

GraspSimulation::GraspSimulation(const Mesh& mesh, const HandModel& hand, const Grasp& grasp,
                                 const SimParams& params)
    : impl_(std::make_unique<Impl>(mesh, hand, grasp, params)) {}

GraspSimulation::~GraspSimulation() = default;

PhaseResult GraspSimulation::settle() {
  Impl& s = *impl_;
  PhaseResult r;
  s.begin(r, "settle", Eigen::Vector3d::Zero());
  s.q_target = s.q_start;
  const Eigen::Isometry3d X_WB0 = s.X_WB_cmd;
  const Eigen::Isometry3d X_BO_plan = s.grasp.X_OB.inverse();
  s.run(s.params.settle_time_s, [&](double) { return X_WB0; });
  s.finish(r, X_BO_plan);
  // At rest in preshape the hand need not touch the object: settle only fails by blowing up
  // or by pushing the object away.
  if (r.outcome == Outcome::kDropped || r.outcome == Outcome::kSlipped)
    r.outcome = r.translation_m < s.params.held_translation_m ? Outcome::kHeld : Outcome::kSlipped;
  return r;
}

Eigen::VectorXd GraspSimulation::Impl::squeeze_efforts() const {
  // Every actor joint pushes toward closing with its effort limit, scaled to the weight.
  Eigen::VectorXd push = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  for (size_t a = 0; a < actor_joints.size(); ++a)
    push[actor_joints[a]] =
        actor_sign[a] * hand_body->effort_limit[static_cast<size_t>(actor_joints[a])];
  return scaled_to_weight(push);
}

Eigen::VectorXd GraspSimulation::Impl::scaled_to_weight(Eigen::VectorXd push) const {
  if (params.squeeze_weight_factor <= 0.0 || grasp.contacts.empty()) return push;
  const double force_N = params.squeeze_weight_factor * object->body->getMass() *
                         params.gravity_mps2 / std::max(params.contact.mu, kMinFrictionForForce);
  Eigen::VectorXd lever = contact_levers(hand, grasp.q, grasp.X_OB, grasp.contacts);
  // A coupled set pushes with its master's drive, which carries the mimic joints' torques
  // too (× multiplier, as contact_force_torques pools them).
  for (size_t j = 0; j < hand.joints.size(); ++j)
    if (const auto& m = hand.joints[j].mimic)
      lever[m->master_joint] += std::abs(m->multiplier) * lever[static_cast<Eigen::Index>(j)];
  // One scale for all actors (the hand's own balance of efforts stays): the smallest at which
  // every joint with a planned contact still presses it with force_N.
  double scale = 0.0;
  for (const int j : actor_joints)
    if (push[j] != 0.0 && lever[j] > 0.0)
      scale = std::max(scale, force_N * lever[j] / std::abs(push[j]));
  if (scale > 0.0 && scale < 1.0) push *= scale;
  return push;
}

Eigen::VectorXd GraspSimulation::Impl::close_speed_caps() const {
  const int n = static_cast<int>(hand.joints.size());
  Eigen::VectorXd close_cap = Eigen::VectorXd::Constant(n, params.hold_speed);
  for (int j = 0; j < n; ++j)
    if (hand.joints[static_cast<size_t>(j)].type == JointType::kPrismatic)
      close_cap[j] = 0.1 * params.hold_speed;
  for (size_t a = 0; a < actor_joints.size(); ++a) {
    const int j = actor_joints[a];
    double cap = params.close_speed * actor_speed[a];
    const double limit = hand.joints[static_cast<size_t>(j)].velocity_limit;
    if (limit > 0.0) cap = std::min(cap, limit);
    close_cap[j] = cap;
  }
  return close_cap;
}

double GraspSimulation::Impl::reach_time(const Eigen::VectorXd& q0,
                                         const Eigen::VectorXd& close_cap) const {
  double reach_s = dt;
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const Eigen::Index i = static_cast<Eigen::Index>(j);
    if (hand.joints[j].is_moving() && !hand.joints[j].mimic)
      reach_s = std::max(reach_s, kMinJerkPeakSpeed * std::abs(grasp.q[i] - q0[i]) / close_cap[i]);
  }
  return reach_s;
}

Eigen::VectorXd GraspSimulation::Impl::close_push() const {
  Eigen::VectorXd push = squeeze_efforts();
  if (bounded())
    for (const int j : actor_joints)
      if (!(squeeze_lever(j) > 0.0)) push[j] = 0.0;  // no planned contact: holds the plan
  return push;
}

BoundedClose bounded_close(const Mesh& mesh, const HandModel& hand, const Grasp& grasp,
                           const SimParams& params) {
  if (!(params.squeeze_travel_m > 0.0) || !(params.reach_start_gap_m > 0.0))
    throw std::invalid_argument(
        "bounded_close: squeeze_travel_m and reach_start_gap_m must be positive");
  GraspSimulation::Impl s(mesh, hand, grasp, params);
  const Eigen::Index n = static_cast<Eigen::Index>(hand.joints.size());
  BoundedClose out;
  out.q_start = s.q_start;
  out.q_plan = s.grasp.q;
  out.q_squeeze = s.grasp.q;
  out.effort = Eigen::VectorXd::Zero(n);
  for (Eigen::Index j = 0; j < n; ++j)
    out.effort[j] = s.hand_body->effort_limit[static_cast<size_t>(j)];
  out.hold_effort = out.effort;
  out.push_sign = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd push = s.close_push();
  for (const int j : s.actor_joints) {
    if (push[j] == 0.0) continue;  // holds the plan with its effort limit
    const double limit = out.effort[j];
    out.effort[j] = std::min(limit, std::abs(push[j]));
    out.hold_effort[j] = std::min(limit, params.squeeze_hold_factor * std::abs(push[j]));
    out.push_sign[j] = push[j] > 0.0 ? 1.0 : -1.0;
    out.q_squeeze[j] = s.bounded_squeeze_target(j, push[j]);
  }
  out.reach_time_s = s.reach_time(s.q_start, s.close_speed_caps());
  out.object = s.object->info;
  return out;
}

PhaseResult GraspSimulation::close() {
  Impl& s = *impl_;
  PhaseResult r;
  s.begin(r, "close", Eigen::Vector3d::Zero());
  const int n = static_cast<int>(s.hand.joints.size());
  // Reach: every driven joint follows a minimum-jerk path from where it is to the plan, all
  // arriving together, so the fingers meet the object at once at the planned contacts.
  const Eigen::VectorXd q0 = bullet::hand_joint_positions(*s.hand_body, n);
  const Eigen::VectorXd close_cap = s.close_speed_caps();
  const double reach_s = s.reach_time(q0, close_cap);
  // Tracking needs headroom over the path's peak speed.
  s.speed_cap = 2.0 * close_cap;
  // Bounded close: the fingers push with their squeeze effort already while they reach, so
  // one that meets the object early presses it no harder than the squeeze will.
  const Eigen::VectorXd push = s.close_push();
  s.squeeze_push = push;
  if (s.bounded())
    for (const int j : s.actor_joints) s.effort_cap[j] = std::abs(push[j]);
  const Eigen::Isometry3d X_WB0 = s.X_WB_cmd;
  // Bounded close with failure exits: the close tests the planned grasp, so an object moved or
  // turned past the held limits from its planned pose in the hand ends it, slipped.
  const bool off_plan_exit = s.bounded() && s.params.exit_on_failure;
  const Eigen::Isometry3d X_BO_plan = s.grasp.X_OB.inverse();
  bool off_plan = false;
  const auto moved_off_plan = [&] {
    double turned = 0.0;
    const double moved = s.pose_change(X_BO_plan, &turned);
    off_plan = moved >= s.params.held_translation_m || s.turned_past_limit(X_BO_plan, turned);
    return off_plan;
  };
  const int reach_steps = static_cast<int>(std::ceil(reach_s / s.dt));
  for (int k = 1; k <= reach_steps && !s.blew_up; ++k) {
    const double tau = static_cast<double>(k) / reach_steps;
    s.q_target = q0 + (s.grasp.q - q0) * min_jerk(tau);
    s.qd_feedforward = (s.grasp.q - q0) * (min_jerk_rate(tau) / (reach_steps * s.dt));
    s.step(X_WB0);
    if (off_plan_exit && moved_off_plan()) break;
  }
  s.qd_feedforward.setZero();
  // Squeeze: every pushing actor joint becomes a spring with its rest point `squeeze` past the
  // plan in the direction it pushes (not clamped: the joint limits stop the finger) and
  // stiffness effort / squeeze, so it pushes with its squeeze effort at the planned value and
  // keeps pushing if the object gives way; the other joints hold the plan.
  s.q_target = s.grasp.q;
  s.speed_cap = close_cap;
  for (size_t a = 0; a < s.actor_joints.size(); ++a) {
    const int j = s.actor_joints[a];
    if (push[j] == 0.0) continue;  // holds the plan
    const Joint& joint = s.hand.joints[static_cast<size_t>(j)];
    if (s.bounded()) {
      // Bounded: squeeze_travel_m past the planned contacts at this joint's lever, pushing
      // with the capped effort all the way (no spring whose force fades near its rest point).
      s.q_target[j] = s.bounded_squeeze_target(j, push[j]);
      s.hold_sign[j] = push[j] > 0.0 ? 1.0 : -1.0;
      continue;
    }
    const double squeeze =
        joint.type == JointType::kPrismatic ? s.params.squeeze_m : s.params.squeeze_rad;
    s.q_target[j] = s.grasp.q[j] + (push[j] > 0.0 ? squeeze : -squeeze);
    if (s.params.compliant_squeeze) s.spring_gain[j] = std::abs(push[j]) / squeeze;
  }
  const int max_steps = static_cast<int>(std::lround(s.params.squeeze_max_time_s / s.dt));
  const int min_steps = static_cast<int>(std::lround(s.params.squeeze_min_time_s / s.dt));
  const int stall_steps = std::max(1, static_cast<int>(std::lround(s.params.stall_time_s / s.dt)));
  int stalled = 0;
  // Bounded: the stage also waits for the object to rest in the hand (rest_drift_m / _rad
  // over the stall time), its effort already capped since the reach (no ramp); it ends early
  // once the object, touched in this close, has been out of the hand's contact for
  // no_contact_exit_time_s (lost).
  const bool lost_exit = s.bounded() && s.params.exit_on_failure;
  const int no_contact_steps =
      std::max(1, static_cast<int>(std::lround(s.params.no_contact_exit_time_s / s.dt)));
  int without_contact = 0;
  bool at_rest = false, lost = false;
  Eigen::Isometry3d X_BO_still = s.X_BO();
  Eigen::VectorXd q_still = bullet::hand_joint_positions(*s.hand_body, n);
  for (int k = 1; k <= max_steps && !s.blew_up && !off_plan; ++k) {
    s.squeeze_fraction = s.bounded() ? 1.0
                                     : std::min(1.0, k * s.dt /
                                                         std::max(s.params.squeeze_ramp_s, s.dt));
    s.step(X_WB0);
    bool still = true;
    if (s.bounded()) {
      // At rest over the window: each actor joint within stall_speed × its speed × the stall
      // time of where the window began (a finger pressing the object jitters at contact-solver
      // speeds without going anywhere), and the object within the rest drift.
      const Eigen::VectorXd q = bullet::hand_joint_positions(*s.hand_body, n);
      for (size_t a = 0; a < s.actor_joints.size(); ++a) {
        const int j = s.actor_joints[a];
        if (std::abs(q[j] - q_still[j]) > s.params.stall_speed * s.actor_speed[a] * s.params.stall_time_s)
          still = false;
      }
      double turned = 0.0;
      const double drift = s.pose_change(X_BO_still, &turned);
      still = still && drift < s.params.rest_drift_m && turned < s.params.rest_drift_rad;
      if (!still) q_still = q;
    } else {
      const Eigen::VectorXd qd = bullet::hand_joint_velocities(*s.hand_body, n);
      for (size_t a = 0; a < s.actor_joints.size(); ++a)
        if (std::abs(qd[s.actor_joints[a]]) > s.params.stall_speed * s.actor_speed[a]) still = false;
    }
    stalled = still ? stalled + 1 : 0;
    if (!still) X_BO_still = s.X_BO();
    if (k >= min_steps && stalled >= stall_steps && s.squeeze_fraction >= 1.0) {
      at_rest = true;
      break;
    }
    // Counted once the fingers have touched the object in this close (a finger may reach its
    // contact only in the squeeze's travel).
    if (r.max_contact_count > 0) without_contact = s.last_contact_count > 0 ? 0 : without_contact + 1;
    if (lost_exit && without_contact >= no_contact_steps) {
      lost = true;
      break;
    }
    if (off_plan_exit && moved_off_plan()) break;
  }
  s.squeeze_fraction = 1.0;
  s.finish(r, X_BO_plan);
  if (off_plan && !s.blew_up)
    r.detail = "moved off the plan";
  else if (!at_rest && !s.blew_up)
    r.detail = lost ? "squeeze, out of contact" : "squeeze time limit";
  // The bounded close with failure exits holds the object to its planned pose (the held
  // limits); the other closes are judged by contact only: the object may move while closing.
  if (r.outcome == Outcome::kSlipped && !off_plan_exit) r.outcome = Outcome::kHeld;
  s.X_BO_ref = s.X_BO();
  s.closed = true;
  // From now on the servos keep squeezing toward the same targets.
  return r;
}

PhaseResult GraspSimulation::lift() {
  Impl& s = *impl_;
  PhaseResult r;
  s.begin(r, "lift", Eigen::Vector3d(0, 0, -s.params.gravity_mps2));
  const Eigen::Isometry3d X_WB0 = s.X_WB_cmd;
  const double h = s.params.lift_height_m;
  const double T = s.params.lift_time_s;
  const auto rise = [&](double t) {
    Eigen::Isometry3d X = X_WB0;
    X.translation().z() += h * min_jerk(t / T);
    return X;
  };
  if (s.params.rest_exit_time_s > 0.0) {
    // Rise, then hold until the object rests in the hand (or lift_hold_s).
    if (s.run(T, rise)) {
      const Eigen::Isometry3d X_WB_top = rise(T);
      s.run(s.params.lift_hold_s, [&](double) { return X_WB_top; }, true);
    }
  } else {
    s.run(T + s.params.lift_hold_s, rise);
  }
  s.finish(r, s.X_BO_ref);
  return r;
}

void GraspSimulation::coast(double duration_s, const std::string& label) {
  Impl& s = *impl_;
  PhaseResult tail;  // only counts the steps for the trace samples
  tail.name = label;
  PhaseResult* const was = s.current;
  s.current = &tail;
  const Eigen::Isometry3d X_WB_hold = s.X_WB_cmd;
  const int steps = static_cast<int>(std::lround(duration_s / s.dt));
  for (int k = 0; k < steps && !s.blew_up; ++k) {
    s.step(X_WB_hold);
    if (s.closed && s.pose_change(s.X_BO_ref, nullptr) > s.params.drop_distance_m) break;
  }
  if (s.segment_hook && steps > 0) s.segment_hook(s.snapshot(label));
  s.current = was;
}

PhaseResult GraspSimulation::shake() {
  Impl& s = *impl_;
  PhaseResult r;
  s.begin(r, "shake", Eigen::Vector3d(0, 0, -s.params.gravity_mps2));
  static const char* kAxes[3] = {"x", "y", "z"};
  // Ends a segment: hook, then held or not (the phase stops at the first failing segment).
  auto segment_held = [&](const std::string& name, bool ran) {
    if (s.segment_hook) s.segment_hook(s.snapshot("shake " + name));
    return s.segment_holds(r, "shake " + name, ran);
  };
  bool ok = true;
  if (s.params.shake_all_axes_at_once) {
    // One translation segment and one rotation segment along / about all three axes.
    const Eigen::Isometry3d X_WB0 = s.X_WB_cmd;
    const double A = s.params.shake_amplitude_m;
    const double T = s.params.shake_time_s;
    const double f = std::max(s.params.shake_frequency_hz, 1.0 / T);
    const bool ran = s.run(T, [&](double t) {
      Eigen::Isometry3d X = X_WB0;
      X.translation() += A * faded_lissajous(t, f, T);
      return X;
    });
    ok = segment_held("xyz", ran);
    if (ok) {
      const Eigen::Isometry3d X_WB1 = s.X_WB_cmd;
      const Eigen::Vector3d pivot =
          gcp_pose(s.hand, link_poses(s.hand, s.grasp.q, X_WB1)).translation();
      const double Theta = s.params.rock_angle_rad;
      const double T_rock = s.params.rock_time_s;
      const double f_rock = std::max(s.params.rock_frequency_hz, 1.0 / T_rock);
      const bool rock_ran = s.run(T_rock, [&](double t) {
        const Eigen::Vector3d theta = Theta * faded_lissajous(t, f_rock, T_rock);
        Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
        if (theta.norm() > 0.0) {
          const Eigen::Matrix3d R =
              Eigen::AngleAxisd(theta.norm(), theta.normalized()).toRotationMatrix();
          M.linear() = R;
          M.translation() = pivot - R * pivot;
        }
        return Eigen::Isometry3d(M * X_WB1);
      });
      ok = segment_held("rock xyz", rock_ran);
    }
    s.finish(r, s.X_BO_ref);
    return r;
  }
  for (int a = 0; a < 3 && ok; ++a) {
    const Eigen::Isometry3d X_WB0 = s.X_WB_cmd;
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(a);
    const double A = s.params.shake_amplitude_m;
    const double T = s.params.shake_time_s;
    const double f = std::max(s.params.shake_frequency_hz, 1.0 / T);  // both ways
    const bool ran = s.run(T, [&](double t) {
      Eigen::Isometry3d X = X_WB0;
      X.translation() += A * faded_sine(t, f, T) * axis;
      return X;
    });
    ok = segment_held(kAxes[a], ran);
  }
  for (int a = 0; a < 3 && ok; ++a) {
    const Eigen::Isometry3d X_WB0 = s.X_WB_cmd;
    // Rock about the GCP (the held object sits around it).
    const Eigen::Vector3d pivot =
        gcp_pose(s.hand, link_poses(s.hand, s.grasp.q, X_WB0)).translation();
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(a);
    const double Theta = s.params.rock_angle_rad;
    const double T = s.params.rock_time_s;
    const double f = std::max(s.params.rock_frequency_hz, 1.0 / T);  // tilts both ways
    const bool ran = s.run(T, [&](double t) {
      const Eigen::Matrix3d R =
          Eigen::AngleAxisd(Theta * faded_sine(t, f, T), axis).toRotationMatrix();
      Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
      M.linear() = R;
      M.translation() = pivot - R * pivot;
      return Eigen::Isometry3d(M * X_WB0);
    });
    ok = segment_held(std::string("rock ") + kAxes[a], ran);
  }
  s.finish(r, s.X_BO_ref);
  return r;
}

PhaseResult GraspSimulation::gravity6() {
  Impl& s = *impl_;
  PhaseResult r;
  s.begin(r, "gravity6", Eigen::Vector3d::Zero());
  static const char* kNames[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  const Eigen::Isometry3d X_WB0 = s.X_WB_cmd;
  for (int d = 0; d < 6; ++d) {
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    g[d / 2] = (d % 2 == 0 ? 1.0 : -1.0) * s.params.gravity_mps2;
    s.set_gravity(g);
    const bool ran = s.run(s.params.gravity6_time_s, [&](double) { return X_WB0; }, true);
    if (s.segment_hook) s.segment_hook(s.snapshot(std::string("gravity6 ") + kNames[d]));
    if (!s.segment_holds(r, std::string("gravity ") + kNames[d], ran)) break;
  }
  s.finish(r, s.X_BO_ref);
  s.set_gravity(Eigen::Vector3d::Zero());
  return r;
}

PhaseSnapshot GraspSimulation::snapshot(const std::string& phase) const {
  return impl_->snapshot(phase);
}

std::vector<double> GraspSimulation::planned_contact_offsets() const {
  const Impl& s = *impl_;
  // Simulated contact points on the object's surface, in the object frame.
  std::vector<Eigen::Vector3d> touched_O;
  const Eigen::Isometry3d X_OW = s.X_WO().inverse();
  const btCollisionObject* obj = s.object->body.get();
  for (int m = 0; m < s.dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* pm = s.dispatcher->getManifoldByIndexInternal(m);
    const bool object_is_a = pm->getBody0() == obj;
    if (!object_is_a && pm->getBody1() != obj) continue;
    for (int c = 0; c < pm->getNumContacts(); ++c) {
      const btManifoldPoint& p = pm->getContactPoint(c);
      if (p.getDistance() >= s.params.contact_distance_m) continue;
      touched_O.push_back(X_OW * from_bt(object_is_a ? p.getPositionWorldOnA()
                                                     : p.getPositionWorldOnB()));
    }
  }
  std::vector<double> offsets;
  for (const Contact& planned : s.grasp.contacts) {
    double nearest = std::numeric_limits<double>::quiet_NaN();
    for (const Eigen::Vector3d& p_O : touched_O) {
      const double d = (p_O - planned.p_O).norm();
      if (!(d >= nearest)) nearest = d;
    }
    offsets.push_back(nearest);
  }
  return offsets;
}

const SimObjectInfo& GraspSimulation::object_info() const { return impl_->object->info; }

Eigen::Isometry3d GraspSimulation::X_WO_start() const { return impl_->X_WO0; }

double GraspSimulation::weight_margin() const {
  const Impl& s = *impl_;
  const Eigen::Index n = static_cast<Eigen::Index>(s.hand.joints.size());
  // What each servo resists once pushed back: its effort limit, or for a pushing joint of the
  // bounded close squeeze_hold_factor × its squeeze effort (at most the limit). Joints the
  // physics locks have no servo (0): rigid.
  Eigen::VectorXd caps(n);
  for (Eigen::Index j = 0; j < n; ++j) caps[j] = s.hand_body->effort_limit[static_cast<size_t>(j)];
  if (s.bounded()) {
    const Eigen::VectorXd push = s.close_push();
    for (const int j : s.actor_joints)
      if (push[j] != 0.0)
        caps[j] = std::min(caps[j], s.params.squeeze_hold_factor * std::abs(push[j]));
  }
  StaticLoad load;
  load.com_O_m = s.object->X_OC.translation();
  load.weight_O_N = s.object->info.mass_kg * s.params.gravity_mps2 *
                    (s.X_WO0.linear().transpose() * -Eigen::Vector3d::UnitZ());
  return cordgrasp::weight_margin(s.hand, s.grasp, s.params.contact, load, caps);
}

void GraspSimulation::set_segment_hook(PhaseHook hook) { impl_->segment_hook = std::move(hook); }

std::vector<Eigen::Isometry3d> multibody_link_poses(const HandModel& hand,
                                                    const Eigen::VectorXd& q,
                                                    const Eigen::Isometry3d& X_WB,
                                                    const std::vector<bool>& locked) {
  if (q.size() != static_cast<Eigen::Index>(hand.joints.size()))
    throw std::invalid_argument("multibody_link_poses: q has the wrong size");
  bullet::HandBodyParams params;
  params.locked = locked;
  params.lock_values = q;
  auto body = bullet::make_hand_multibody(hand, params);
  bullet::place_hand(*body, X_WB, q);
  return bullet::hand_link_poses(*body);
}

}  // namespace cordgrasp
