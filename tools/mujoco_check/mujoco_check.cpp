// cordgrasp-mujoco-check: protocol `standard` in MuJoCo on a scene from `cordgrasp export
// --format mjcf` (docs/export.md): per keyframe (grasp) the bounded close the scene carries,
// then lift, shake and rock; held as Bullet's (docs/physics.md §3, §3a, §4).
// MuJoCo, Eigen and CLI11 only: with libqhullcpp linked, as the cordgrasp libraries do,
// MuJoCo's own qhull calls abort on their first message.
#include <mujoco/mujoco.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>

#include "standard_check.h"

using cordgrasp::mujoco_check::StandardCheckParams;
using cordgrasp::mujoco_check::StandardCheckResult;

int main(int argc, char** argv) {
  CLI::App app{"cordgrasp-mujoco-check: protocol standard (bounded close, lift, shake) in "
               "MuJoCo on a scene written by `cordgrasp export --format mjcf` (a second "
               "opinion, not the validation)"};
  std::string scene, csv, trace_csv;
  StandardCheckParams p;
  app.add_option("--scene", scene, "MJCF scene from `cordgrasp export`")->required();
  app.add_option("--out", csv,
                 "CSV: grasp,held,outcome,failed_phase,shift_m,turn_rad,close_shift_m,"
                 "close_turn_rad,squeeze_s");
  app.add_option("--trace", trace_csv,
                 "CSV: grasp,phase,sim_time_s,object_shift_m,object_turn_rad,contacts");
  app.add_option("--trace-interval", p.trace_interval_s, "Trace row interval [s]; 0: 0.01 s")
      ->capture_default_str();
  app.add_option("--time-step", p.time_step_s, "MuJoCo time step [s]; 0: the scene's")
      ->capture_default_str();
  app.add_option("--mu", p.mu, "Friction of every geom; 0: the scene's (the plan's)")
      ->capture_default_str();
  app.add_option("--contact-time-constant", p.contact_time_constant_s,
                 "Contact time constant (solref[0]) of every geom [s]; 0: the scene's")
      ->capture_default_str();
  app.add_option("--implicit", p.implicit, "MuJoCo's implicit integrator")
      ->capture_default_str();
  app.add_option("--hold-error", p.hold_error_rad,
                 "Error at which a servo holding the plan reaches its effort limit [rad or m]")
      ->capture_default_str();
  app.add_option("--push-error-fraction", p.push_error_fraction,
                 "A pushing servo reaches its effort limit this fraction of its travel short "
                 "of its target")
      ->capture_default_str();
  app.add_option("--noslip-iterations", p.noslip_iterations, "MuJoCo noslip iterations")
      ->capture_default_str();
  app.add_option("--damping-ratio", p.servo_damping_ratio, "Damping ratio of the servos")
      ->capture_default_str();
  std::optional<double> lift_s, lift_m, gravity;
  app.add_option("--lift-s", lift_s, "Duration of the rise [s]; default: the scene's");
  app.add_option("--lift-m", lift_m, "Height of the rise [m]; default: the scene's");
  app.add_option("--gravity", gravity, "Gravity in lift and shake [m/s^2]; default: the scene's");
  CLI11_PARSE(app, argc, argv);
  try {
    char error[1000] = "";
    std::unique_ptr<mjModel, void (*)(mjModel*)> m(
        mj_loadXML(scene.c_str(), nullptr, error, sizeof(error)), mj_deleteModel);
    if (!m) throw std::runtime_error("'" + scene + "': " + error);
    try {
      p = cordgrasp::mujoco_check::read_scene_protocol(m.get(), p);
    } catch (const std::exception& e) {
      throw std::runtime_error("'" + scene + "': " + e.what());
    }
    if (lift_s) p.lift_time_s = *lift_s;
    if (lift_m) p.lift_height_m = *lift_m;
    if (gravity) p.gravity_mps2 = *gravity;
    std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(m.get()), mj_deleteData);
    // Each grasp's run changes gains, limits and options: it gets a fresh copy of the scene.
    std::unique_ptr<mjModel, void (*)(mjModel*)> run_model(mj_copyModel(nullptr, m.get()),
                                                           mj_deleteModel);
    std::ofstream out;
    if (!csv.empty()) {
      out.open(csv);
      if (!out) throw std::runtime_error("cannot write '" + csv + "'");
      out << "grasp,held,outcome,failed_phase,shift_m,turn_rad,close_shift_m,close_turn_rad,"
             "squeeze_s\n";
    }
    std::ofstream trace;
    if (!trace_csv.empty()) {
      trace.open(trace_csv);
      if (!trace) throw std::runtime_error("cannot write '" + trace_csv + "'");
      trace << "grasp,phase,sim_time_s,object_shift_m,object_turn_rad,contacts\n";
      if (!(p.trace_interval_s > 0.0)) p.trace_interval_s = 0.01;
    }
    int held = 0;
    for (int k = 0; k < m->nkey; ++k) {
      mj_copyModel(run_model.get(), m.get());
      const StandardCheckResult r =
          cordgrasp::mujoco_check::run_standard_check(run_model.get(), d.get(), k, p);
      held += r.held;
      std::printf("grasp %d: %s%s%s (closing: shift %.1f mm, turn %.1f deg; then shift %.1f mm, "
                  "turn %.1f deg)\n",
                  k, r.outcome.c_str(), r.held ? "" : " in ", r.failed_phase.c_str(),
                  r.close_shift_m * 1e3, r.close_turn_rad * 180 / M_PI, r.shift_m * 1e3,
                  r.turn_rad * 180 / M_PI);
      if (out)
        out << k << ',' << (r.held ? 1 : 0) << ',' << r.outcome << ',' << r.failed_phase << ','
            << r.shift_m << ',' << r.turn_rad << ',' << r.close_shift_m << ','
            << r.close_turn_rad << ',' << r.squeeze_s << '\n';
      for (const auto& t : r.trace)
        if (trace)
          trace << k << ',' << t.phase << ',' << t.sim_time_s << ',' << t.object_shift_m << ','
                << t.object_turn_rad << ',' << t.contacts << '\n';
    }
    std::printf("mujoco-check: %d/%d held\n", held, static_cast<int>(m->nkey));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cordgrasp-mujoco-check: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
