#include "standard_check.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <functional>
#include <stdexcept>
#include <vector>

#include "cordgrasp/sim/motion_profiles.h"

namespace cordgrasp::mujoco_check {
namespace {

Eigen::Isometry3d body_pose(const mjData* d, int body) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() << d->xpos[3 * body], d->xpos[3 * body + 1], d->xpos[3 * body + 2];
  X.linear() = Eigen::Quaterniond(d->xquat[4 * body], d->xquat[4 * body + 1],
                                  d->xquat[4 * body + 2], d->xquat[4 * body + 3])
                   .toRotationMatrix();
  return X;
}

/// The scene's numeric `name` of `size` values. @throws std::runtime_error when missing.
const mjtNum* numeric(const mjModel* m, const std::string& name, int size) {
  const int id = mj_name2id(m, mjOBJ_NUMERIC, name.c_str());
  if (id < 0)
    throw std::runtime_error("scene has no custom numeric '" + name +
                             "' (the bounded close and its physics settings): export it again "
                             "with this version's `cordgrasp export`");
  if (m->numeric_size[id] != size)
    throw std::runtime_error("custom numeric '" + name + "' has " +
                             std::to_string(m->numeric_size[id]) + " values, expected " +
                             std::to_string(size));
  return m->numeric_data + m->numeric_adr[id];
}

/// The fields read_scene_protocol() takes from the scene, by their SimParams name.
struct SceneField {
  const char* name;
  double StandardCheckParams::*value;
};
using P = StandardCheckParams;
constexpr SceneField kSceneFields[] = {
    {"gravity_mps2", &P::gravity_mps2},
    {"settle_time_s", &P::settle_time_s},
    {"servo_gain_per_s", &P::servo_gain_per_s},
    {"squeeze_max_time_s", &P::squeeze_max_time_s},
    {"squeeze_min_time_s", &P::squeeze_min_time_s},
    {"stall_speed", &P::stall_speed},
    {"stall_time_s", &P::stall_time_s},
    {"lift_height_m", &P::lift_height_m},
    {"lift_time_s", &P::lift_time_s},
    {"lift_hold_s", &P::lift_hold_s},
    {"shake_amplitude_m", &P::shake_amplitude_m},
    {"shake_frequency_hz", &P::shake_frequency_hz},
    {"shake_time_s", &P::shake_time_s},
    {"rock_angle_rad", &P::rock_angle_rad},
    {"rock_frequency_hz", &P::rock_frequency_hz},
    {"rock_time_s", &P::rock_time_s},
    {"rest_exit_time_s", &P::rest_exit_time_s},
    {"rest_drift_m", &P::rest_drift_m},
    {"rest_drift_rad", &P::rest_drift_rad},
    {"no_contact_exit_time_s", &P::no_contact_exit_time_s},
    {"held_translation_m", &P::held_translation_m},
    {"held_rotation_rad", &P::held_rotation_rad},
    {"contact_distance_m", &P::contact_distance_m},
    {"unstable_speed_mps", &P::unstable_speed_mps},
};

/// A base pose for the mocap target: position and rotation in the scene's world (object frame).
struct Pose {
  Eigen::Vector3d p;
  Eigen::Quaterniond q;
};

/// The world of one grasp's run: servos, the object in the hand, the phases' step loop.
class StandardRun {
 public:
  StandardRun(mjModel* m, mjData* d, int key, const StandardCheckParams& p)
      : m_(m), d_(d), p_(p) {
    object_ = mj_name2id(m, mjOBJ_BODY, "object");
    const int target = mj_name2id(m, mjOBJ_BODY, "hand_target");
    const int site = mj_name2id(m, mjOBJ_SITE, "gcp");
    if (object_ < 0 || target < 0 || m->body_mocapid[target] < 0 || site < 0 || m->njnt < 1 ||
        m->jnt_type[0] != mjJNT_FREE || m->nuser_actuator < 2)
      throw std::runtime_error("scene lacks the object, hand_target, gcp site, the hand's free "
                               "joint or two user values per actuator");
    mocap_ = m->body_mocapid[target];
    root_ = m->jnt_bodyid[0];
    if (p.time_step_s > 0.0) m->opt.timestep = p.time_step_s;
    if (p.implicit) m->opt.integrator = mjINT_IMPLICIT;  // the servos' damping
    dt_ = m->opt.timestep;
    if (p.contact_time_constant_s > 0.0)
      for (int g = 0; g < m->ngeom; ++g) m->geom_solref[mjNREF * g] = p.contact_time_constant_s;
    m->opt.noslip_iterations = p.noslip_iterations;
    // Contacts within contact_distance_m are reported (as Bullet's manifold points within
    // two margins) but push only once the geoms touch: margin = gap, half on each geom.
    for (int g = 0; g < m->ngeom; ++g)
      m->geom_margin[g] = m->geom_gap[g] = 0.5 * p.contact_distance_m;
    if (p.mu > 0.0)
      for (int g = 0; g < m->ngeom; ++g) m->geom_friction[3 * g] = p.mu;

    mj_resetDataKeyframe(m, d, key);
    mj_forward(m, d);
    // W as Bullet's approach-down world: x_W = x_G, y_W = −y_G, z_W = −z_G (gravity −z_W).
    Eigen::Matrix3d R_OG;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) R_OG(r, c) = d->site_xmat[9 * site + 3 * r + c];
    R_OW_ = R_OG * Eigen::Vector3d(1, -1, -1).asDiagonal();
    Eigen::Isometry3d X_OS = Eigen::Isometry3d::Identity();
    X_OS.linear() = R_OG;
    X_OS.translation() << d->site_xpos[3 * site], d->site_xpos[3 * site + 1],
        d->site_xpos[3 * site + 2];
    p_RG_ = (body_pose(d, root_).inverse() * X_OS).translation();
    com_O_ << m->body_ipos[3 * object_], m->body_ipos[3 * object_ + 1],
        m->body_ipos[3 * object_ + 2];
    X_BO_plan_ = X_BO();

    // Hand joints at the reach start; servo targets, limits and gains of the bounded close.
    const std::string k = "grasp_" + std::to_string(key);
    std::vector<int> hand_joints;
    for (int j = 1; j < m->njnt; ++j)
      if (m->jnt_bodyid[j] != object_ && m->jnt_type[j] != mjJNT_FREE) hand_joints.push_back(j);
    const mjtNum* start = numeric(m, k + "_start", static_cast<int>(hand_joints.size()));
    for (size_t i = 0; i < hand_joints.size(); ++i)
      d->qpos[m->jnt_qposadr[hand_joints[i]]] = start[i];
    const int nu = m->nu;
    const mjtNum* squeeze = numeric(m, k + "_squeeze", nu);
    const mjtNum* effort = numeric(m, k + "_effort", nu);
    const mjtNum* hold = numeric(m, k + "_hold_effort", nu);
    reach_s_ = numeric(m, k + "_reach_s", 1)[0];
    plan_.assign(m->key_ctrl + key * nu, m->key_ctrl + (key + 1) * nu);
    squeeze_.assign(squeeze, squeeze + nu);
    effort_.assign(effort, effort + nu);
    hold_.assign(hold, hold + nu);
    target_ = std::vector<double>(nu, 0.0);
    feedforward_ = target_;
    for (int a = 0; a < nu; ++a) {
      const int j = m->actuator_trnid[2 * a];
      if (!(effort_[a] > 0.0)) {
        // Locked at the plan, as Bullet builds joints no actor drives (lock_passive_joints).
        m->jnt_limited[j] = 1;
        m->jnt_range[2 * j] = m->jnt_range[2 * j + 1] = plan_[a];
        d->qpos[m->jnt_qposadr[j]] = plan_[a];
      }
      // A position servo that pushes with the capped effort at the plan, as Bullet's motor
      // does until the joint gets to its squeeze target (less on the way there); joints that
      // hold the plan reach their limit hold_error_rad off it. Critically damped (the damping,
      // outside the force cap, is given back along the reach by feedforward: ctrl()).
      const double travel = std::abs(squeeze_[a] - plan_[a]);
      const double kp =
          effort_[a] / (travel > 0.0 ? p.push_error_fraction * travel : p.hold_error_rad);
      const int dof = m->jnt_dofadr[j];
      const double inertia = std::max(m->dof_M0[dof], m->dof_armature[dof]);
      kp_.push_back(kp);
      kd_.push_back(p.servo_damping_ratio * 2.0 * std::sqrt(kp * inertia));
      m->actuator_gainprm[mjNGAIN * a] = kp;
      m->actuator_biasprm[mjNBIAS * a + 1] = -kp;
      m->actuator_biasprm[mjNBIAS * a + 2] = 0.0;
      m->actuator_forcelimited[a] = 1;
      m->dof_damping[dof] = kd_.back();
      target_[a] = d->qpos[m->jnt_qposadr[j]];
    }
    set_limits();
    for (int i = 0; i < 3; ++i) m->opt.gravity[i] = 0.0;
    mj_forward(m, d);
  }

  StandardCheckResult run() {
    StandardCheckResult r;
    result_ = &r;
    if (p_.trace_interval_s > 0.0)
      trace_every_ = std::max(1, static_cast<int>(std::lround(p_.trace_interval_s / dt_)));
    // Settle, then close: reach (minimum jerk to the plan, effort capped), bounded squeeze.
    run_for(p_.settle_time_s, current_target());
    phase_ = "close";
    close(r);
    r.close_shift_m = pose_change(X_BO_plan_, &r.close_turn_rad);
    if (!verdict(r, "close", X_BO_plan_, true)) return r;
    X_BO_ref_ = X_BO();
    closed_ = true;

    // Lift: gravity along −z_W with the hand compensated, rise lift_height_m, hold.
    phase_ = "lift";
    set_gravity(-p_.gravity_mps2 * R_OW_.col(2));
    const Pose bottom = current_target();
    const auto rise = [&](double t) {
      Pose X = bottom;
      X.p += p_.lift_height_m * min_jerk(t / p_.lift_time_s) * R_OW_.col(2);
      return X;
    };
    if (run_for(p_.lift_time_s, rise)) run_for(p_.lift_hold_s, rise(p_.lift_time_s), true);
    if (!verdict(r, "lift", X_BO_ref_, true)) return r;

    // Shake along x_W, y_W, z_W at once, then rock about them through the GCP.
    phase_ = "shake";
    const Pose top = current_target();
    const double f = std::max(p_.shake_frequency_hz, 1.0 / p_.shake_time_s);
    const bool shook = run_for(p_.shake_time_s, [&](double t) {
      Pose X = top;
      X.p += p_.shake_amplitude_m * (R_OW_ * faded_lissajous(t, f, p_.shake_time_s));
      return X;
    });
    if (!verdict(r, "shake", X_BO_ref_, shook)) return r;
    phase_ = "rock";
    const Pose still = current_target();
    const Eigen::Vector3d pivot = still.p + still.q * p_RG_;
    const double f_rock = std::max(p_.rock_frequency_hz, 1.0 / p_.rock_time_s);
    const bool rocked = run_for(p_.rock_time_s, [&](double t) {
      const Eigen::Vector3d theta =
          R_OW_ * (p_.rock_angle_rad * faded_lissajous(t, f_rock, p_.rock_time_s));
      if (theta.norm() == 0.0) return still;
      const Eigen::Quaterniond R(Eigen::AngleAxisd(theta.norm(), theta.normalized()));
      return Pose{pivot + R * (still.p - pivot), R * still.q};
    });
    verdict(r, "rock", X_BO_ref_, rocked);
    return r;
  }

 private:
  using Trajectory = std::function<Pose(double)>;

  Pose current_target() const {
    const mjtNum* p = d_->mocap_pos + 3 * mocap_;
    const mjtNum* q = d_->mocap_quat + 4 * mocap_;
    return {Eigen::Vector3d(p[0], p[1], p[2]), Eigen::Quaterniond(q[0], q[1], q[2], q[3])};
  }

  double joint_q(int a) const { return d_->qpos[m_->jnt_qposadr[m_->actuator_trnid[2 * a]]]; }
  double joint_qd(int a) const { return d_->qvel[m_->jnt_dofadr[m_->actuator_trnid[2 * a]]]; }

  /// Effort limits: the capped effort, squeeze_hold_factor × it once a pushing joint is
  /// behind the plan (in the squeeze and later).
  void set_limits() {
    for (int a = 0; a < m_->nu; ++a) {
      const double push = squeezing_ ? squeeze_[a] - plan_[a] : 0.0;
      const bool behind = push * (plan_[a] - joint_q(a)) > 0.0;
      const double limit = behind ? hold_[a] : effort_[a];
      m_->actuator_forcerange[2 * a] = -limit;
      m_->actuator_forcerange[2 * a + 1] = limit;
    }
  }

  void set_gravity(const Eigen::Vector3d& g) {
    for (int i = 0; i < 3; ++i) m_->opt.gravity[i] = g[i];
    // Gravity on the hand is cancelled, as an arm's controller would (docs/physics.md §2).
    for (int b = 1; b < m_->nbody; ++b)
      for (int i = 0; i < 3; ++i)
        d_->xfrc_applied[6 * b + i] = b == object_ ? 0.0 : -m_->body_mass[b] * g[i];
  }

  void step(const Pose& X) {
    for (int i = 0; i < 3; ++i) d_->mocap_pos[3 * mocap_ + i] = X.p[i];
    d_->mocap_quat[4 * mocap_] = X.q.w();
    d_->mocap_quat[4 * mocap_ + 1] = X.q.x();
    d_->mocap_quat[4 * mocap_ + 2] = X.q.y();
    d_->mocap_quat[4 * mocap_ + 3] = X.q.z();
    set_limits();
    if (squeezing_)  // the target approaches the squeeze target at Bullet's servo speed
      for (int a = 0; a < m_->nu; ++a) {
        feedforward_[a] = p_.servo_gain_per_s * (squeeze_[a] - target_[a]);
        target_[a] += dt_ * feedforward_[a];
      }
    for (int a = 0; a < m_->nu; ++a)
      d_->ctrl[a] = target_[a] + (kp_[a] > 0.0 ? kd_[a] * feedforward_[a] / kp_[a] : 0.0);
    mj_step(m_, d_);
    if (unstable()) blew_up_ = true;
    if (trace_every_ > 0 && ++steps_ % trace_every_ == 0) {
      TraceSample t;
      t.phase = phase_;
      t.sim_time_s = d_->time;
      t.object_shift_m = pose_change(closed_ ? X_BO_ref_ : X_BO_plan_, &t.object_turn_rad);
      t.contacts = contact_count();
      result_->trace.push_back(t);
    }
  }

  bool unstable() const {
    if (d_->warning[mjWARN_BADQACC].number > 0) return true;
    for (int i = 0; i < m_->nq; ++i)
      if (!std::isfinite(d_->qpos[i])) return true;
    const int od = m_->jnt_dofadr[m_->body_jntadr[object_]];
    const Eigen::Vector3d v_object(d_->qvel[od], d_->qvel[od + 1], d_->qvel[od + 2]);
    const Eigen::Vector3d v_base(d_->qvel[0], d_->qvel[1], d_->qvel[2]);
    return v_object.norm() > p_.unstable_speed_mps || v_base.norm() > p_.unstable_speed_mps;
  }

  Eigen::Isometry3d X_BO() const {
    return body_pose(d_, root_).inverse() * body_pose(d_, object_);
  }

  /// Object shift at its centre of mass in the hand against `X_BO_reference` [m]; turn [rad].
  double pose_change(const Eigen::Isometry3d& X_BO_reference, double* turn) const {
    const Eigen::Isometry3d X = X_BO();
    if (turn) *turn = Eigen::AngleAxisd(X_BO_reference.linear().transpose() * X.linear()).angle();
    return (X * com_O_ - X_BO_reference * com_O_).norm();
  }

  int contact_count() const {
    int n = 0;
    for (int c = 0; c < d_->ncon; ++c) {
      const mjContact& con = d_->contact[c];
      const int b1 = m_->geom_bodyid[con.geom1];
      const int b2 = m_->geom_bodyid[con.geom2];
      if ((b1 == object_) != (b2 == object_) && con.dist < p_.contact_distance_m) ++n;
    }
    return n;
  }

  /// Outcome against `X_BO_reference` (docs/physics.md §4); records a failure in `r`.
  bool verdict(StandardCheckResult& r, const char* phase, const Eigen::Isometry3d& X_BO_reference,
               bool ran) {
    r.shift_m = pose_change(X_BO_reference, &r.turn_rad);
    if (blew_up_) r.outcome = "unstable";
    else if (contact_count() == 0) r.outcome = "dropped";
    else if (ran && r.shift_m < p_.held_translation_m && r.turn_rad < p_.held_rotation_rad)
      r.outcome = "held";
    else r.outcome = "slipped";
    r.held = r.outcome == "held";
    if (!r.held) r.failed_phase = phase;
    return r.held;
  }

  bool run_for(double duration, const Pose& X, bool rest_exit = false) {
    return run_for(duration, [X](double) { return X; }, rest_exit);
  }

  /// Bullet's run(): false when blown up or failed (after close: moved or turned past the held
  /// limits, or no contact for no_contact_exit_time_s); with `rest_exit`, true once the object
  /// has rested in the hand for rest_exit_time_s.
  bool run_for(double duration, const Trajectory& trajectory, bool rest_exit = false) {
    const int steps = static_cast<int>(std::lround(duration / dt_));
    const int rest_steps =
        rest_exit ? std::max(1, static_cast<int>(std::lround(p_.rest_exit_time_s / dt_))) : 0;
    const int no_contact_steps =
        std::max(1, static_cast<int>(std::lround(p_.no_contact_exit_time_s / dt_)));
    int at_rest = 0, without_contact = 0;
    Eigen::Isometry3d X_BO_rest = X_BO();
    for (int s = 1; s <= steps; ++s) {
      step(trajectory(s * dt_));
      if (blew_up_) return false;
      if (closed_) {
        double turned = 0.0;
        const double moved = pose_change(X_BO_ref_, &turned);
        if (moved >= p_.held_translation_m || turned >= p_.held_rotation_rad) return false;
        without_contact = contact_count() > 0 ? 0 : without_contact + 1;
        if (without_contact >= no_contact_steps) return false;
      }
      if (rest_steps > 0) {
        double turned = 0.0;
        if (pose_change(X_BO_rest, &turned) < p_.rest_drift_m && turned < p_.rest_drift_rad) {
          if (++at_rest >= rest_steps) return true;
        } else {
          at_rest = 0;
          X_BO_rest = X_BO();
        }
      }
    }
    return true;
  }

  void close(StandardCheckResult& r) {
    const int nu = m_->nu;
    const Pose X = current_target();
    std::vector<double> q0(nu);
    for (int a = 0; a < nu; ++a) q0[a] = joint_q(a);
    const int reach_steps = std::max(1, static_cast<int>(std::ceil(reach_s_ / dt_)));
    for (int k = 1; k <= reach_steps && !blew_up_; ++k) {
      const double tau = static_cast<double>(k) / reach_steps;
      for (int a = 0; a < nu; ++a) {
        target_[a] = q0[a] + (plan_[a] - q0[a]) * min_jerk(tau);
        feedforward_[a] = (plan_[a] - q0[a]) * min_jerk_rate(tau) / (reach_steps * dt_);
      }
      step(X);
      if (moved_off_plan()) return;
    }
    target_ = plan_;
    squeezing_ = true;
    // Ends when the actor joints have stalled and the object has rested in the hand.
    const int max_steps = static_cast<int>(std::lround(p_.squeeze_max_time_s / dt_));
    const int min_steps = static_cast<int>(std::lround(p_.squeeze_min_time_s / dt_));
    const int stall_steps = std::max(1, static_cast<int>(std::lround(p_.stall_time_s / dt_)));
    int stalled = 0, k = 1;
    Eigen::Isometry3d X_BO_still = X_BO();
    for (; k <= max_steps && !blew_up_; ++k) {
      step(X);
      bool still = true;
      for (int a = 0; a < nu; ++a) {
        const double sign = m_->actuator_user[a * m_->nuser_actuator];
        const double speed = m_->actuator_user[a * m_->nuser_actuator + 1];
        if (sign != 0.0 && std::abs(joint_qd(a)) > p_.stall_speed * speed) still = false;
      }
      if (still) {
        double turned = 0.0;
        const double drift = pose_change(X_BO_still, &turned);
        still = drift < p_.rest_drift_m && turned < p_.rest_drift_rad;
      }
      stalled = still ? stalled + 1 : 0;
      if (!still) X_BO_still = X_BO();
      if (k >= min_steps && stalled >= stall_steps) break;
      if (moved_off_plan()) break;
    }
    r.squeeze_s = std::min(k, max_steps) * dt_;
  }

  /// Bullet's bounded close: the object moved or turned past the held limits from its planned
  /// pose in the hand ends the close (slipped).
  bool moved_off_plan() const {
    double turned = 0.0;
    const double moved = pose_change(X_BO_plan_, &turned);
    return moved >= p_.held_translation_m || turned >= p_.held_rotation_rad;
  }

  mjModel* m_;
  mjData* d_;
  const StandardCheckParams& p_;
  int object_ = -1, root_ = -1, mocap_ = -1;
  double dt_ = 0.002;
  double reach_s_ = 0.0;
  Eigen::Matrix3d R_OW_;
  Eigen::Vector3d p_RG_;  ///< GCP in the hand root frame
  Eigen::Vector3d com_O_;
  Eigen::Isometry3d X_BO_plan_, X_BO_ref_;
  std::vector<double> kp_, kd_;  ///< servo gains [N·m/rad, N·m·s/rad or N/m, N·s/m]
  std::vector<double> plan_, squeeze_, effort_, hold_, target_, feedforward_;
  StandardCheckResult* result_ = nullptr;
  std::string phase_ = "settle";
  int trace_every_ = 0, steps_ = 0;
  bool squeezing_ = false, closed_ = false, blew_up_ = false;
};

}  // namespace

StandardCheckParams read_scene_protocol(const mjModel* m, StandardCheckParams p) {
  for (const SceneField& f : kSceneFields)
    p.*f.value = numeric(m, std::string("sim_") + f.name, 1)[0];  // MjcfNames::sim_numeric
  return p;
}

StandardCheckResult run_standard_check(mjModel* m, mjData* d, int key,
                                       const StandardCheckParams& p) {
  StandardRun run(m, d, key, p);
  return run.run();
}

}  // namespace cordgrasp::mujoco_check
