#pragma once
// A plan as a MuJoCo scene (MJCF, read by MuJoCo 2.2.2 and later); layout in docs/export.md.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/sim/validate_grasp.h"

namespace cordgrasp {

/// Settings of the MuJoCo scene; physics defaults follow docs/physics.md where MuJoCo has a
/// counterpart.
struct MjcfParams {
  double time_step_s = 0.002;        ///< <option timestep>
  double density_kgm3 = 500.0;       ///< density of the object's convex parts [kg/m³]
  double squeeze_rad = 0.5;          ///< position gain = effort / squeeze (rotary joints)
  double squeeze_m = 0.01;           ///< position gain = effort / squeeze (prismatic joints)
  double default_effort_Nm = 2.0;    ///< rotary joints whose URDF gives no effort
  double default_effort_N = 50.0;    ///< prismatic joints whose URDF gives no effort
  double armature_kgm2 = 1e-3;       ///< reflected actuator inertia, rotary joints
  double armature_kg = 0.5;          ///< reflected actuator inertia, prismatic joints
  double gcp_site_size_m = 0.005;    ///< radius of the GCP site
  double weld_time_s = 0.01;         ///< solref time constant of the hand-to-target weld [s]
};

/// Names the scene gives to what tests and tools look up (mj_name2id).
struct MjcfNames {
  static constexpr const char* kObjectBody = "object";        ///< free body of the object
  static constexpr const char* kObjectJoint = "object_free";  ///< its free joint
  static constexpr const char* kGcpSite = "gcp";              ///< the hand's GCP frame
  static constexpr const char* kHandJoint = "hand_free";      ///< free joint of the hand root
  /// Mocap body the hand root is welded to: move it to move the hand (an arm's target).
  static constexpr const char* kHandTarget = "hand_target";
  /// Keyframe of grasp k: "grasp_<k>".
  static std::string keyframe(int k) { return "grasp_" + std::to_string(k); }
  /// Custom numeric `<what>` of grasp k's bounded close: "grasp_<k>_<what>" (docs/export.md).
  static std::string close_numeric(int k, const std::string& what) {
    return keyframe(k) + "_" + what;
  }
  static constexpr const char* kStart = "start";        ///< hand joints at the reach start
  static constexpr const char* kSqueeze = "squeeze";    ///< servo targets of the squeeze
  static constexpr const char* kEffort = "effort";      ///< servo effort limits
  static constexpr const char* kHoldEffort = "hold_effort";  ///< limits behind the plan
  static constexpr const char* kReachTime = "reach_s";  ///< duration of the reach [s]
  /// Custom numeric of the physics setting `field` (a SimParams number) the closes were
  /// made with: "sim_<field>", one value (booleans 0 / 1).
  static std::string sim_numeric(const std::string& field) { return "sim_" + field; }
};

/// Writes the MJCF scene of `grasps` (world = object frame) to `path` and the hand's meshes
/// as binary STL into "<stem>_meshes/" beside it; the object's convex parts (hull vertices,
/// object frame) are inline. `closes` (one per grasp, or empty) adds each grasp's bounded close
/// as `<custom><numeric>` elements, and with them every number of `sim`, the physics settings
/// the closes were made with (the protocol's phases for cordgrasp-mujoco-check). Returns the
/// files written, `path` first.
/// @throws InputError when a file cannot be written; std::invalid_argument when `closes` is
/// neither empty nor one per grasp.
std::vector<std::string> write_mjcf_scene(const std::string& path, const HandModel& hand,
                                          const std::vector<Grasp>& grasps,
                                          const ContactModel& contact,
                                          const std::vector<std::vector<Eigen::Vector3d>>& parts,
                                          const MjcfParams& params = {},
                                          const std::vector<BoundedClose>& closes = {},
                                          const SimParams& sim = {});

}  // namespace cordgrasp
