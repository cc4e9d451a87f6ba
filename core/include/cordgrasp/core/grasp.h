#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/grasp_region.h"
#include "cordgrasp/core/serialize.h"

namespace cordgrasp {

/// A finger–object contact (docs/algorithm.md §7.4), in the object frame.
struct Contact {
  int link = -1;                                    ///< HandModel link index
  Eigen::Vector3d p_O = Eigen::Vector3d::Zero();    ///< contact point on the object [m]
  Eigen::Vector3d n_O = Eigen::Vector3d::UnitZ();   ///< unit normal, out of the object (toward
                                                    ///< the finger); the finger pushes along −n_O
};

/// Measures of a closed grasp that the wrench space does not see, computed from its contacts
/// (docs/finger-stage-and-quality.md, "Candidate filters").
struct CandidateMeasures {
  int fingers_in_contact = 0;  ///< actors with at least one contact
  bool palm_contact = false;   ///< a static link (palm, finger base) touches the object
  /// ‖mean of the contact points − centre of mass‖ / bounding radius r (0 = centred).
  double com_offset = 0.0;
  /// Net push of the fingers when each presses with the same force along its mean contact
  /// normal, ‖Σ_a unit(Σ_k −n_k)‖ / fingers, in [0, 1] (0 = balanced); a component pushing
  /// the object onto a static-link contact is taken by that contact and not counted.
  double push_imbalance = 0.0;

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(fingers_in_contact), CORDGRASP_NVP(palm_contact),
                 CORDGRASP_NVP(com_offset), CORDGRASP_NVP(push_imbalance));
  }
};

/// Wall-clock time spent per planner stage [s].
struct StageTimes {
  double exploration_s = 0.0;  ///< cord exploration (shared by all grasps of one plan)
  double finger_s = 0.0;       ///< pose, approach, retreat, close for this grasp
  double quality_s = 0.0;      ///< wrench space and ε
};

/// A planned grasp: hand configuration relative to the object, its contacts and quality.
struct Grasp {
  Eigen::Isometry3d X_OB = Eigen::Isometry3d::Identity();  ///< hand root link in object frame
  Eigen::Isometry3d X_OG = Eigen::Isometry3d::Identity();  ///< GCP in object frame
  Eigen::VectorXd q;               ///< joint vector after closing (one entry per hand joint)
  Eigen::VectorXd q_preshape;      ///< joint vector before closing
  std::vector<Contact> contacts;
  bool force_closure = false;
  double epsilon = 0.0;            ///< ε quality (docs/algorithm.md §8), in the chosen mode
  /// Skewness α (docs/algorithm.md §9) [rad], in [0, π/4], of the hand's palm normal
  /// (HandModel::palm_normal; the GCP z axis for a hand without one).
  double alpha_rad = 0.0;
  double alpha_approach_rad = 0.0;  ///< skewness α of the GCP z axis (approach) [rad]
  std::optional<int> region_rank;  ///< cord planner: rank of the region (0 = lowest χ)
  std::optional<double> chi_m2;    ///< cord planner: χ of that region [m²]
  std::optional<GraspRegion> region;  ///< cord planner: the region itself (cords, P1, P_l, P_r)
  CandidateMeasures measures;      ///< contact-based measures (candidate_measures())
  StageTimes times;
};

}  // namespace cordgrasp
