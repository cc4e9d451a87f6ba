#pragma once
// Internal to hand loading (hand_description.cpp, urdf_import.cpp, substitute_inertial.cpp):
// the one-line error format and the geometry bounds both the URDF and the description checks use.
#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/geometry_points.h"
#include "cordgrasp/core/hand_model.h"

namespace cordgrasp::hand_load {

inline std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

/// Throws InputError "load_hand: '<file>': <problem>" (docs/hand-description.md, Errors).
[[noreturn]] inline void fail(const std::string& file, const std::string& problem) {
  throw InputError("load_hand: " + in_quotes(file) + ": " + problem);
}

/// Axis-aligned box of points [m]; empty until a point is added.
struct Box3 {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return !(min.array() <= max.array()).all(); }
  void add(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
};

/// Appends geometry_points(g) (extent points, link frame [m]) to `out`.
inline void append_geometry_corners(const Geometry& g, std::vector<Eigen::Vector3d>& out) {
  const auto pts = geometry_points(g);
  out.insert(out.end(), pts.begin(), pts.end());
}

}  // namespace cordgrasp::hand_load
