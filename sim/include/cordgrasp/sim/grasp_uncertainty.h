#pragma once
// What a real robot does not know exactly (docs/physics.md §3b): where its hand is, the
// friction, the object's mass and centre of mass, and the grip force it gets. One trial's
// conditions are drawn from a seed, the grasp index and the trial index alone.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <memory>
#include <mutex>

#include "cordgrasp/core/finger_stage.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/serialize.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// Distributions of the uncertain conditions of a physics trial. The defaults are the
/// `realistic` model (docs/physics.md §3b); uncertainty_none() sets every field to 0.
struct UncertaintyParams {
  /// Hand position error: Gaussian σ per axis of the GCP frame [m] (hand–eye calibration).
  double hand_offset_sigma_m = 2e-3;
  /// Hand orientation error: Gaussian σ per axis of a rotation vector about the GCP [rad].
  double hand_turn_sigma_rad = 2.0 * M_PI / 180.0;
  /// Friction: μ × (1 + u · this), u uniform in [−1, 1] [-] (tabulated μ are good to ±20 %).
  double mu_relative_spread = 0.2;
  /// Object mass: mass × (1 + u · this), u uniform in [−1, 1] [-] (a guessed density).
  double mass_relative_spread = 0.3;
  /// Centre of mass error: Gaussian σ per axis of the object frame [m] (unknown filling).
  double com_offset_sigma_m = 3e-3;
  /// Grip force: the weight-sized squeeze × (1 + u · this), u uniform in [−1, 1], still
  /// capped by the joints' effort limits [-] (motor current and transmission losses).
  double squeeze_relative_spread = 0.2;

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(hand_offset_sigma_m), CORDGRASP_NVP(hand_turn_sigma_rad),
                 CORDGRASP_NVP(mu_relative_spread), CORDGRASP_NVP(mass_relative_spread),
                 CORDGRASP_NVP(com_offset_sigma_m), CORDGRASP_NVP(squeeze_relative_spread));
  }
};

/// Every spread and σ 0: a trial is the grasp as planned.
UncertaintyParams uncertainty_none();

/// True when every spread and σ of `params` is 0.
bool is_none(const UncertaintyParams& params);

/// Checks that σ are finite, ≥ 0 and ≤ 5 cm / 45°, and relative spreads in [0, 0.9].
/// @throws std::invalid_argument naming the first field out of range and its range.
void check_uncertainty_params(const UncertaintyParams& params);

/// The uncertain factors, in the order of UncertaintyDraw::scores.
enum class UncertaintyFactor { kHandOffset, kHandTurn, kFriction, kMass, kComOffset, kSqueeze };
constexpr int kUncertaintyFactors = 6;

/// "hand_offset", "hand_turn", "friction", "mass", "com_offset", "squeeze".
const char* to_string(UncertaintyFactor factor);

/// One trial's conditions.
struct UncertaintyDraw {
  Eigen::Vector3d hand_offset_G_m = Eigen::Vector3d::Zero();  ///< hand shift, GCP frame
  Eigen::Vector3d hand_turn_G_rad = Eigen::Vector3d::Zero();  ///< rotation vector about the GCP
  double mu_factor = 1.0;                                     ///< μ multiplier [-]
  double mass_factor = 1.0;                                   ///< mass multiplier [-]
  Eigen::Vector3d com_offset_O_m = Eigen::Vector3d::Zero();   ///< COM shift, object frame
  double squeeze_factor = 1.0;                                ///< grip force multiplier [-]
  /// Standardized draw of each factor (UncertaintyFactor order), whatever its spread: the
  /// norm of the 3 standard normals of a vector factor, u in [−1, 1] of a scalar one.
  std::array<double, kUncertaintyFactors> scores{};
};

/// Draws the conditions of trial `trial` of the grasp with index `grasp_index` in its plan,
/// from those three numbers alone (so results depend neither on threads nor on order).
/// Every factor is drawn whatever its spread: zeroing one leaves the others' draws unchanged.
UncertaintyDraw draw_uncertainty(const UncertaintyParams& params, std::uint64_t seed,
                                 int grasp_index, int trial);

/// A grasp and the physics settings of one uncertain trial.
struct UncertainTrial {
  Grasp grasp;
  SimParams params;
};

/// `grasp` with its hand moved and turned about the GCP by the draw, and `params` with μ, the
/// mass (mass_kg when set, else density_kgm3) and the COM offset changed. The grip force is
/// sized as the controller would, from the nominal μ and mass, times squeeze_factor:
/// squeeze_weight_factor × squeeze_factor × mu_factor / mass_factor (the effort limits still
/// cap it).
UncertainTrial apply_uncertainty(const Grasp& grasp, const SimParams& params,
                                 const UncertaintyDraw& draw);

/// `drawn` (a grasp whose hand apply_uncertainty moved) with the fingers that the drawn pose
/// leaves short of the object closed on until they touch it, from the plan's preshape
/// (close_fingers, the planner's finger stage): a robot's fingers close until contact where
/// the hand arrives, while the planned joint values there leave such a finger short (the
/// bounded squeeze goes only SimParams::squeeze_travel_m past them). A finger that meets the
/// object no later than planned keeps the plan and its contacts; a re-closed one gets the
/// contacts it closed on (none if it touched nothing). `setup` is prepare_hand(hand, collider).
Grasp close_at_drawn_pose(const Grasp& drawn, const HandModel& hand, const HandSetup& setup,
                          HandObjectCollider& collider);

/// Whether `uncertainty` moves the hand (a hand offset or turn with σ > 0): then each draw's
/// fingers close again at the drawn pose.
bool moves_hand(const UncertaintyParams& uncertainty);

/// close_at_drawn_pose for the tests of one hand and object, one draw at a time from any
/// thread: a collider with its hand setup, built once per plan (or borrowed from the planner,
/// which already has one) rather than once per grasp. `hand` outlives it.
class DrawnPoseCloser {
 public:
  /// Builds a collider for `hand` and `mesh` and prepares the hand on it.
  DrawnPoseCloser(const HandModel& hand, const Mesh& mesh);
  /// Borrows `collider` (built for `hand` and the object; it outlives this) with its hand
  /// `setup` (prepare_hand on it, copied).
  DrawnPoseCloser(const HandModel& hand, HandObjectCollider& collider, const HandSetup& setup);
  /// close_at_drawn_pose(drawn, hand, setup, collider), serialized.
  Grasp close(const Grasp& drawn);

 private:
  const HandModel& hand_;
  std::unique_ptr<HandObjectCollider> owned_;
  HandObjectCollider& collider_;
  HandSetup setup_;
  std::mutex mutex_;
};

}  // namespace cordgrasp
