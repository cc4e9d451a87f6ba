#pragma once
#include <Eigen/Core>

#include "cordgrasp/core/grasp.h"

namespace cordgrasp {

/// A contact of link 0 at p_O with the unit of n_O as its outward normal.
inline Contact contact(const Eigen::Vector3d& p_O, const Eigen::Vector3d& n_O) {
  Contact c;
  c.link = 0;
  c.p_O = p_O;
  c.n_O = n_O.normalized();
  return c;
}

}  // namespace cordgrasp
