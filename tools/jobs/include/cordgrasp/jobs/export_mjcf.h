#pragma once
// A plan as a MuJoCo scene (MJCF, read by MuJoCo 2.2.2 and later); layout in docs/export.md.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"

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
};

/// Writes the MJCF scene of `grasps` (world = object frame) to `path` and the hand's meshes
/// as binary STL into "<stem>_meshes/" beside it; the object's convex parts (hull vertices,
/// object frame) are inline. Returns the files written, `path` first.
/// @throws InputError when a file cannot be written.
std::vector<std::string> write_mjcf_scene(const std::string& path, const HandModel& hand,
                                          const std::vector<Grasp>& grasps,
                                          const ContactModel& contact,
                                          const std::vector<std::vector<Eigen::Vector3d>>& parts,
                                          const MjcfParams& params = {});

}  // namespace cordgrasp
