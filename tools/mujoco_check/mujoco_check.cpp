// cordgrasp-mujoco-check: lift test in MuJoCo on a scene from `cordgrasp export --format mjcf`.
// MuJoCo and CLI11 only: with libqhullcpp linked, as the cordgrasp libraries do, MuJoCo's own
// qhull calls abort on their first message.
// Per keyframe (grasp): gravity off, the position servos squeeze past the planned joint values
// (the actor joints by squeeze_rad in their closing direction: a weaker Bullet squeeze spring,
// docs/physics.md §3); then gravity along the approach (the GCP's +z) and the hand (mocap)
// rises against it; held when the object stays within 2 cm and 15° of its pose in the hand.
#include <mujoco/mujoco.h>

#include <CLI/CLI.hpp>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>


namespace {

/// Settings of the MuJoCo lift test (durations as Bullet's quick protocol, docs/physics.md §3).
struct LiftCheckParams {
  double close_s = 0.3;         ///< squeeze with gravity off [s]
  double lift_m = 0.10;         ///< hand rise against gravity [m]
  double lift_s = 0.5;          ///< duration of the rise (minimum jerk) [s]
  double hold_s = 0.3;          ///< hold still afterwards [s]
  double gravity_mps2 = 9.81;
  /// Servo target past the plan [rad]: the scene's kp = effort / 0.5 rad, so 0.1 pushes with
  /// 20 % of the effort (full effort squeezes most objects out in MuJoCo; docs/export.md).
  double squeeze_rad = 0.1;
  double squeeze_m = 0.002;     ///< prismatic joints (the scene's kp = effort / 0.01 m)
  double max_shift_m = 0.02;    ///< held: object shift in the hand below this
  double max_turn_rad = 15.0 * M_PI / 180.0;  ///< and turn below this
};

struct LiftCheckResult {
  bool held = false;
  double shift_m = 0.0;  ///< object's largest shift in the hand frame after closing
  double turn_rad = 0.0;
};

Eigen::Isometry3d body_pose(const mjData* d, int body) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() << d->xpos[3 * body], d->xpos[3 * body + 1], d->xpos[3 * body + 2];
  X.linear() = Eigen::Quaterniond(d->xquat[4 * body], d->xquat[4 * body + 1],
                                  d->xquat[4 * body + 2], d->xquat[4 * body + 3])
                   .toRotationMatrix();
  return X;
}

LiftCheckResult check_grasp(const mjModel* m, mjData* d, int key, const LiftCheckParams& p) {
  mjModel* mm = const_cast<mjModel*>(m);
  mj_resetDataKeyframe(m, d, key);
  // Squeeze targets: actor joints past the plan in their closing direction (the actuator's
  // user value: +1, −1, or 0 for joints no actor drives).
  for (int a = 0; a < m->nu; ++a) {
    const int j = m->actuator_trnid[2 * a];
    const double sign = m->nuser_actuator > 0 ? m->actuator_user[a * m->nuser_actuator] : 0.0;
    const double squeeze = m->jnt_type[j] == mjJNT_SLIDE ? p.squeeze_m : p.squeeze_rad;
    d->ctrl[a] = m->key_ctrl[key * m->nu + a] + sign * squeeze;
  }
  const int object = mj_name2id(m, mjOBJ_BODY, "object");
  const int target = mj_name2id(m, mjOBJ_BODY, "hand_target");
  if (target < 0 || m->body_mocapid[target] < 0 || m->njnt < 1 || m->jnt_type[0] != mjJNT_FREE)
    throw std::runtime_error("scene lacks the mocap body hand_target or the hand's free joint");
  const int root = m->jnt_bodyid[0];  // the hand root's free joint is the scene's first joint
  const int mocap = m->body_mocapid[target];
  const int site = mj_name2id(m, mjOBJ_SITE, "gcp");
  if (object < 0 || root < 0 || site < 0)
    throw std::runtime_error("scene lacks the object body, the mocap hand or the gcp site");
  mj_forward(m, d);
  const Eigen::Vector3d z_G(d->site_xmat[9 * site + 2], d->site_xmat[9 * site + 5],
                            d->site_xmat[9 * site + 8]);
  const Eigen::Vector3d start(d->mocap_pos[3 * mocap], d->mocap_pos[3 * mocap + 1],
                              d->mocap_pos[3 * mocap + 2]);

  const Eigen::Vector3d gravity0(m->opt.gravity[0], m->opt.gravity[1], m->opt.gravity[2]);
  for (int i = 0; i < 3; ++i) mm->opt.gravity[i] = 0.0;
  const double dt = m->opt.timestep;
  for (double t = 0; t < p.close_s; t += dt) mj_step(m, d);
  const Eigen::Isometry3d X_HO_ref = body_pose(d, root).inverse() * body_pose(d, object);

  for (int i = 0; i < 3; ++i) mm->opt.gravity[i] = p.gravity_mps2 * z_G[i];
  // Gravity on the hand is cancelled, as an arm's controller would (docs/physics.md §2):
  // a force −m·g at the centre of mass of every body but the object.
  for (int b = 1; b < m->nbody; ++b)
    for (int i = 0; i < 3; ++i)
      d->xfrc_applied[6 * b + i] = b == object ? 0.0 : -m->body_mass[b] * m->opt.gravity[i];
  LiftCheckResult r;
  for (double t = 0; t < p.lift_s + p.hold_s; t += dt) {
    const double s = std::min(1.0, t / p.lift_s);
    const double blend = s * s * s * (10 - 15 * s + 6 * s * s);  // minimum jerk
    const Eigen::Vector3d pos = start - blend * p.lift_m * z_G;
    for (int i = 0; i < 3; ++i) d->mocap_pos[3 * mocap + i] = pos[i];
    mj_step(m, d);
    const Eigen::Isometry3d X_HO = body_pose(d, root).inverse() * body_pose(d, object);
    r.shift_m = std::max(r.shift_m, (X_HO.translation() - X_HO_ref.translation()).norm());
    r.turn_rad = std::max(
        r.turn_rad, Eigen::AngleAxisd(X_HO_ref.linear().transpose() * X_HO.linear()).angle());
    if (r.shift_m > p.max_shift_m || r.turn_rad > p.max_turn_rad) break;
  }
  for (int i = 0; i < 3; ++i) mm->opt.gravity[i] = gravity0[i];
  r.held = r.shift_m <= p.max_shift_m && r.turn_rad <= p.max_turn_rad;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cordgrasp-mujoco-check: lift test in MuJoCo on a scene written by `cordgrasp "
               "export --format mjcf` (a second opinion, not the validation)"};
  std::string scene, csv;
  LiftCheckParams p;
  app.add_option("--scene", scene, "MJCF scene from `cordgrasp export`")->required();
  app.add_option("--out", csv, "CSV: grasp,held,shift_m,turn_rad");
  app.add_option("--lift-s", p.lift_s, "Duration of the rise [s]")->capture_default_str();
  app.add_option("--lift-m", p.lift_m, "Height of the rise [m]")->capture_default_str();
  app.add_option("--gravity", p.gravity_mps2, "Gravity while lifting [m/s^2]")
      ->capture_default_str();
  app.add_option("--hold-s", p.hold_s, "Hold after the rise [s]")->capture_default_str();
  app.add_option("--close-s", p.close_s, "Squeeze before lifting [s]")->capture_default_str();
  app.add_option("--squeeze-rad", p.squeeze_rad,
                 "Servo target past the plan [rad]; 0.5 (the scene's kp = effort / 0.5 rad) "
                 "pushes with the full effort")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    char error[1000] = "";
    std::unique_ptr<mjModel, void (*)(mjModel*)> m(
        mj_loadXML(scene.c_str(), nullptr, error, sizeof(error)), mj_deleteModel);
    if (!m) throw std::runtime_error("'" + scene + "': " + error);
    std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(m.get()), mj_deleteData);
    std::ofstream out;
    if (!csv.empty()) {
      out.open(csv);
      if (!out) throw std::runtime_error("cannot write '" + csv + "'");
      out << "grasp,held,shift_m,turn_rad\n";
    }
    int held = 0;
    for (int k = 0; k < m->nkey; ++k) {
      const LiftCheckResult r = check_grasp(m.get(), d.get(), k, p);
      held += r.held;
      std::printf("grasp %d: %s (shift %.1f mm, turn %.1f deg)\n", k,
                  r.held ? "held" : "dropped", r.shift_m * 1e3, r.turn_rad * 180 / M_PI);
      if (out)
        out << k << ',' << (r.held ? 1 : 0) << ',' << r.shift_m << ',' << r.turn_rad << '\n';
    }
    std::printf("mujoco-check: %d/%d held\n", held, static_cast<int>(m->nkey));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cordgrasp-mujoco-check: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
