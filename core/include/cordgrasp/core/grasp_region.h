#pragma once
#include <Eigen/Core>
#include <vector>

namespace cordgrasp {

/// 3D polyline [m].
using Polyline3 = std::vector<Eigen::Vector3d>;

/// Which front-cord construction produced a region (Case I or II, docs/algorithm.md §3).
enum class CordCase { kI = 1, kII = 2 };

/// A scanned set of front cords: one candidate grasp region of the exploration stage
/// (docs/algorithm.md §3–§6). All points in the object frame [m].
struct GraspRegion {
  Eigen::Vector3d p1 = Eigen::Vector3d::Zero();   ///< seed guide triangle T0 = (P1, P2, P3)
  Eigen::Vector3d p2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d p3 = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< ν of T0 (unit)
  Eigen::Vector3d p_l = Eigen::Vector3d::Zero();  ///< virtual grasping point, thumb (P2) side
  Eigen::Vector3d p_r = Eigen::Vector3d::Zero();  ///< virtual grasping point, index (P3) side
  Eigen::Vector3d p_m = Eigen::Vector3d::Zero();  ///< (P_l + P_r) / 2
  CordCase cord_case = CordCase::kI;
  int n = 0;                    ///< cords per side; front_cords has 2n + 1 entries
  std::vector<Polyline3> front_cords;  ///< i = −n..n in order; front_cords[n] is the seed's
  double xi_m = 0.0;            ///< ξ of the seed front cord [m] (docs/algorithm.md §1)
  double chi_m2 = 0.0;          ///< XOR measure χ, Eq. (1) [m²] (docs/algorithm.md §6)
  bool from_local_improvement = false;  ///< found by local improvement (docs/algorithm.md §5)
};

/// Number of rotated cords T^{±i} that missed the object (empty front cords, scored as empty
/// polygons Q_i; docs/algorithm.md §4). 0: every cord of the set touches the object.
int side_cords_missed(const GraspRegion& region);

}  // namespace cordgrasp
