#include "cordgrasp/core/guide_frame.h"

#include <Eigen/Geometry>

namespace cordgrasp {

PlaneFrame guide_frame(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                       const Eigen::Vector3d& p3) {
  PlaneFrame f;
  f.origin = p1;
  f.normal = (p2 - p1).cross(p3 - p1).normalized();
  f.e1 = (p2 - p1).normalized();
  f.e2 = f.normal.cross(f.e1);
  return f;
}

bool is_acute_triangle(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                       const Eigen::Vector3d& p3, double min_area_m2) {
  if ((p2 - p1).dot(p3 - p1) <= 0.0) return false;
  if ((p1 - p2).dot(p3 - p2) <= 0.0) return false;
  if ((p1 - p3).dot(p2 - p3) <= 0.0) return false;
  return 0.5 * (p2 - p1).cross(p3 - p1).norm() > min_area_m2;
}

}  // namespace cordgrasp
