#include "cordgrasp/jobs/export_moveit.h"

#include <cmath>
#include <sstream>

#include "cordgrasp/core/kinematics.h"

namespace cordgrasp {
namespace {

std::string num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << (std::abs(v) < 1e-15 ? 0.0 : v);
  return s.str();
}

/// A YAML double-quoted scalar.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// trajectory_msgs/JointTrajectory with one point (ROS 2 Duration: sec, nanosec).
void write_posture(std::ostream& y, const char* key, const HandModel& hand,
                   const std::vector<int>& joints, const Eigen::VectorXd& q, double time_s) {
  y << "  " << key << ":\n";
  y << "    header: {frame_id: \"\"}\n";
  y << "    joint_names: [";
  for (size_t i = 0; i < joints.size(); ++i)
    y << (i ? ", " : "") << quoted(hand.joints[joints[i]].name);
  y << "]\n    points:\n      - positions: [";
  for (size_t i = 0; i < joints.size(); ++i) y << (i ? ", " : "") << num(q[joints[i]]);
  const double sec = std::floor(time_s);
  y << "]\n        time_from_start: {sec: " << static_cast<long>(sec)
    << ", nanosec: " << static_cast<long>(std::llround((time_s - sec) * 1e9)) << "}\n";
}

/// moveit_msgs/GripperTranslation.
void write_translation(std::ostream& y, const char* key, const std::string& frame,
                       const Eigen::Vector3d& d, double desired_m, double min_m) {
  y << "  " << key << ":\n";
  y << "    direction:\n      header: {frame_id: " << quoted(frame) << "}\n";
  y << "      vector: {x: " << num(d.x()) << ", y: " << num(d.y()) << ", z: " << num(d.z())
    << "}\n";
  y << "    desired_distance: " << num(desired_m) << "\n    min_distance: " << num(min_m) << "\n";
}

}  // namespace

std::string moveit_grasps_yaml(const HandModel& hand, const std::vector<Grasp>& grasps,
                               const MoveitGraspParams& p) {
  std::vector<int> moving;
  for (size_t j = 0; j < hand.joints.size(); ++j)
    if (hand.joints[j].is_moving()) moving.push_back(static_cast<int>(j));
  const std::string root = hand.links[hand.root_link].name;
  std::ostringstream y;
  y << "# moveit_msgs/Grasp list written by cordgrasp export (hand " << hand.name
    << "); lengths in m, angles in rad; docs/export.md\n";
  if (grasps.empty()) y << "[]\n";
  for (size_t k = 0; k < grasps.size(); ++k) {
    const Grasp& g = grasps[k];
    const Eigen::VectorXd& q = g.q;  // as planned
    const Eigen::VectorXd& q_pre = g.q_preshape;
    // Approach: the GCP's +z (into the object) in the root link frame, at the grasp.
    const Eigen::Isometry3d X_BG = g.X_OB.inverse() * g.X_OG;
    const Eigen::Vector3d approach_B = X_BG.linear().col(2).normalized();
    const Eigen::Quaterniond r(g.X_OB.linear());
    const Eigen::Vector3d t = g.X_OB.translation();
    y << "- id: " << quoted(p.id_prefix + std::to_string(k)) << "\n";
    write_posture(y, "pre_grasp_posture", hand, moving, q_pre, p.posture_time_s);
    write_posture(y, "grasp_posture", hand, moving, q, p.posture_time_s);
    y << "  grasp_pose:\n    header: {frame_id: " << quoted(p.object_frame) << "}\n";
    y << "    pose:\n      position: {x: " << num(t.x()) << ", y: " << num(t.y())
      << ", z: " << num(t.z()) << "}\n";
    y << "      orientation: {x: " << num(r.x()) << ", y: " << num(r.y()) << ", z: " << num(r.z())
      << ", w: " << num(r.w()) << "}\n";
    y << "  grasp_quality: " << num(g.epsilon) << "\n";
    write_translation(y, "pre_grasp_approach", root, approach_B, p.approach_desired_m,
                      p.approach_min_m);
    write_translation(y, "post_grasp_retreat", root, -approach_B, p.retreat_desired_m,
                      p.retreat_min_m);
    write_translation(y, "post_place_retreat", root, -approach_B, p.retreat_desired_m,
                      p.retreat_min_m);
    y << "  max_contact_force: 0\n";
    y << "  allowed_touch_objects: [" << quoted(p.object_frame) << "]\n";
  }
  return y.str();
}

}  // namespace cordgrasp
