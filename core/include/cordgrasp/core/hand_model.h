#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// One collision or visual element of a link (URDF <collision>/<visual>).
struct Geometry {
  enum class Kind { kBox, kCylinder, kSphere, kMesh };
  Kind kind = Kind::kBox;
  Eigen::Isometry3d X_LG = Eigen::Isometry3d::Identity();  ///< geometry frame in link frame
  Eigen::Vector3d box_size_m = Eigen::Vector3d::Zero();     ///< full box extents [m]
  double radius_m = 0.0;                                    ///< sphere / cylinder radius [m]
  double length_m = 0.0;                                    ///< cylinder length along z [m]
  std::shared_ptr<const Mesh> mesh;  ///< kMesh: vertices in the geometry frame, scale applied [m]
  std::string mesh_path;             ///< kMesh: resolved file path
  Eigen::Vector4d rgba = Eigen::Vector4d(0.7, 0.7, 0.7, 1.0);  ///< visual colour (URDF material)
};

/// Mass properties of a link, in the link frame.
struct Inertial {
  double mass_kg = 0.0;
  Eigen::Vector3d com_m = Eigen::Vector3d::Zero();          ///< centre of mass in link frame
  Eigen::Matrix3d inertia_kgm2 = Eigen::Matrix3d::Zero();   ///< about the COM, link axes
  bool substituted = false;  ///< missing/placeholder in the URDF, replaced by a sane default
};

struct Link {
  std::string name;
  Inertial inertial;
  std::vector<Geometry> collisions;
  std::vector<Geometry> visuals;
  int parent_joint = -1;  ///< index into HandModel::joints; -1 for the root
};

enum class JointType { kFixed, kRevolute, kContinuous, kPrismatic };

/// q[joint] = multiplier · q[master] + offset (URDF <mimic> or a description coupling).
struct Mimic {
  int master_joint = -1;
  double multiplier = 1.0;
  double offset = 0.0;  ///< [rad] or [m]
};

struct Joint {
  std::string name;
  JointType type = JointType::kFixed;
  int parent_link = -1;
  int child_link = -1;
  Eigen::Isometry3d X_PJ = Eigen::Isometry3d::Identity();  ///< joint frame in parent link frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();         ///< unit axis in joint frame
  double lower = 0.0;           ///< [rad] or [m]; -inf for continuous
  double upper = 0.0;           ///< [rad] or [m]; +inf for continuous
  double effort_limit = 0.0;    ///< [N·m] or [N]; 0 when the URDF gives none
  double velocity_limit = 0.0;  ///< [rad/s] or [m/s]; 0 when the URDF gives none
  std::optional<Mimic> mimic;
  bool is_moving() const { return type != JointType::kFixed; }
};

/// A finger that closes as a unit (Simox EndEffectorActor): joints with direction and speed.
struct Actor {
  struct Entry {
    int joint = -1;
    double direction_speed = 1.0;  ///< signed relative closing speed (docs/algorithm.md §7.4)
  };
  std::string name;
  std::vector<Entry> joints;
};

/// Grasp centre point (docs/algorithm.md §1): its +z is the approach direction, into the object.
struct GraspCenterPoint {
  int link = -1;
  Eigen::Isometry3d X_LG = Eigen::Isometry3d::Identity();  ///< GCP frame in that link's frame
};

/// Palm axis (docs/hand-description.md): a unit vector fixed in a link, pointing from the palm
/// towards the fingers' closing region; the "axis that points from the palm" of paper Eq. (2).
struct PalmNormal {
  int link = -1;                                     ///< HandModel link index
  Eigen::Vector3d n_L = Eigen::Vector3d::UnitZ();    ///< unit vector in that link's frame
};

/// A hand: URDF kinematics and geometry plus the grasping description (GCP, preshape, actors).
/// Joint vectors (`q`) have one entry per element of `joints`; fixed joints' entries are ignored.
struct HandModel {
  std::string name;
  std::string urdf_path;         ///< resolved path of the URDF
  std::string description_path;  ///< resolved path of the hand description file
  std::vector<Link> links;
  std::vector<Joint> joints;     ///< topological order: a joint's parent link precedes it
  int root_link = 0;

  GraspCenterPoint gcp;
  Eigen::VectorXd preshape;      ///< open configuration, one entry per joint
  std::vector<Actor> actors;     ///< closing fingers
  std::vector<int> thumb_links;  ///< links of the thumb (roll calibration, docs/algorithm.md §7.1)
  std::optional<PalmNormal> palm_normal;  ///< palm axis for α (Eq. (2)); none: GCP z
  std::optional<double> palm_width_m;  ///< W_palm override (docs/algorithm.md §4), else measured
  /// Default contact patch radius of this hand's pads [m] (ContactModel::soft_finger_radius_m;
  /// planner and physics, unless --soft-finger-radius is given). 0: point contacts. Two-finger
  /// grippers need > 0: two point contacts are never force closure.
  double soft_finger_radius_m = 0.0;
};

/// Index of the link called `name`, or -1.
int find_link(const HandModel& hand, const std::string& name);

/// Index of the joint called `name`, or -1.
int find_joint(const HandModel& hand, const std::string& name);

/// Number of independently moving joints (not fixed, not mimic).
int degrees_of_freedom(const HandModel& hand);

/// Total mass of all links [kg].
double total_mass(const HandModel& hand);

}  // namespace cordgrasp
