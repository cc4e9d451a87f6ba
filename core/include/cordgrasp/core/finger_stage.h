#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/grasp_region.h"
#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/serialize.h"

namespace cordgrasp {

/// Parameters of the finger stage (docs/algorithm.md §7).
struct FingerParams {
  double approach_step_m = 1e-3;  ///< approach step along GCP +z
  double retreat_step_m = 1e-3;   ///< retreat step along GCP −z
  int max_retreat_steps = 1000;   ///< give up (hand cannot get free) after this many
  /// Closing step per iteration: each actor joint moves by close_step × its signed
  /// speed (Simox directionAndSpeed), in the joint's units (rad, or m for prismatic joints,
  /// whose descriptions scale the speed accordingly, e.g. −0.1 → 2 mm).
  double close_step = 0.02;
  double contact_tolerance_m = 0.5e-3;  ///< bisection near contact stops this close to the
                                        ///< surface; links this close are contacts
  int max_close_iterations = 2000;      ///< safety cap on closing iterations
  int min_contacts = 2;                 ///< fewer contacts → rejected
  /// Static links (palm, finger bases) within contact_tolerance_m of the object at the end are
  /// contacts too (Simox only records actor contacts); a palm the object rests on pushes it.
  bool static_link_contacts = true;
  /// Hands with one actor (parallel grippers): when closing ends with one finger on the object
  /// and the other short of it, shift the hand by half the gap along that finger's way to the
  /// object and close again — the object centres the gripper, as a compliant wrist (and our
  /// physics, where the first pad pushes the free object) does. Simox has no such step.
  bool centre_single_actor = true;
  /// Largest gap that centring closes [m] (a finger farther from the object is not opposite).
  double centre_max_gap_m = 0.05;

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(approach_step_m), CORDGRASP_NVP(retreat_step_m),
                 CORDGRASP_NVP(max_retreat_steps), CORDGRASP_NVP(close_step),
                 CORDGRASP_NVP(contact_tolerance_m), CORDGRASP_NVP(max_close_iterations),
                 CORDGRASP_NVP(min_contacts), CORDGRASP_NVP(static_link_contacts),
                 CORDGRASP_NVP(centre_single_actor), CORDGRASP_NVP(centre_max_gap_m));
  }
};

/// How one finger-stage attempt ended.
enum class FingerStatus {
  kOk,             ///< at least min_contacts contacts
  kNoContact,      ///< fingers closed without touching the object
  kOneContact,     ///< fewer than min_contacts (typically one) contacts
  kCannotRetreat,  ///< still colliding after max_retreat_steps (hand starts inside the object)
};

/// "ok", "no_contact", "one_contact", "cannot_retreat".
const char* to_string(FingerStatus status);

/// Per-hand data of the finger stage, computed once per hand in preshape.
struct HandSetup {
  Eigen::VectorXd q_preshape;  ///< preshape with couplings applied, clamped to limits
  /// Joints each actor moves: its own plus mimic joints following them.
  std::vector<std::vector<int>> actor_joints;
  std::vector<std::vector<int>> actor_links;  ///< links with geometry an actor moves
  std::vector<int> static_links;  ///< links with geometry moved by no actor (palm, bases)
  int num_links = 0;
  /// ignore_pair[a * num_links + b]: self-collision between links a and b is not checked
  /// (kinematic neighbours, i.e. joined through at most one moving joint, or touching in
  /// preshape).
  std::vector<char> ignore_pair;
  /// Thumb calibration R_GH = [o_h l_h z_h] in GCP coordinates (docs/algorithm.md §7.1).
  Eigen::Matrix3d R_GH = Eigen::Matrix3d::Identity();
  Eigen::Isometry3d X_GB = Eigen::Isometry3d::Identity();  ///< root in GCP frame, preshape
};

/// Thumb calibration of docs/algorithm.md §7.1 in preshape, in GCP coordinates: columns o_h (thumb
/// tip → centroid of the other finger tips, z removed), l_h = z_h × o_h, z_h. Finger tips are the
/// geometry centres of the thumb's outermost link and of each other actor's outermost link.
/// Identity when the hand names no thumb or no other finger.
Eigen::Matrix3d thumb_calibration(const HandModel& hand, const Eigen::VectorXd& q_preshape);

/// Computes the HandSetup (actor link sets, ignored self-collision pairs measured with
/// `collider` in preshape, thumb calibration). @throws std::invalid_argument when the hand has
/// no actor or the collider's link count differs.
HandSetup prepare_hand(const HandModel& hand, HandObjectCollider& collider);

/// GCP pose for a grasp region (docs/algorithm.md §7.1): at P1, z = unit(P_m − P1), roll from
/// o_w = unit(P_r − P_l ⊥ z) with R = [o_w l_w z]·R_GHᵀ; `flip_roll` adds 180° about z.
Eigen::Isometry3d gcp_pose_for_region(const GraspRegion& region, const Eigen::Matrix3d& R_GH,
                                      bool flip_roll = false);

/// Result of one finger-stage attempt; poses in the object frame.
struct FingerResult {
  FingerStatus status = FingerStatus::kNoContact;
  Eigen::Isometry3d X_OG = Eigen::Isometry3d::Identity();  ///< GCP after approach/retreat
  Eigen::Isometry3d X_OB = Eigen::Isometry3d::Identity();  ///< hand root after approach/retreat
  Eigen::VectorXd q_preshape;                              ///< joints before closing
  Eigen::VectorXd q;                                       ///< joints after closing
  std::vector<Contact> contacts;  ///< one per actor link within contact_tolerance_m
  int approach_steps = 0;
  int retreat_steps = 0;
  int close_iterations = 0;
};

/// Approach, retreat and close (docs/algorithm.md §7.2–§7.4): the hand in preshape with its GCP at
/// `X_OG_start` moves along GCP +z in approach steps until it has travelled `approach_travel_m`
/// or collides with the object; retreats along −z until collision-free; then closes every actor
/// (0.02 rad × speed per iteration, bisection near contact; stops on the object, other actors
/// or static links; mimic joints follow). Bad cases come back as a status, never as an exception.
FingerResult run_finger_stage(const HandModel& hand, const HandSetup& setup,
                              HandObjectCollider& collider, const Eigen::Isometry3d& X_OG_start,
                              double approach_travel_m, const FingerParams& params = {});

/// Closing only (docs/algorithm.md §7.4) from joint vector `q_start` with the root at X_OB; fills
/// q, contacts, close_iterations and status of `result`.
void close_fingers(const HandModel& hand, const HandSetup& setup, HandObjectCollider& collider,
                   const Eigen::Isometry3d& X_OB, const Eigen::VectorXd& q_start,
                   const FingerParams& params, FingerResult& result);

}  // namespace cordgrasp
