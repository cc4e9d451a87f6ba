#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <string>

namespace cordgrasp {

/// [x, y, z] as a JSON array.
inline nlohmann::json to_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// Eigen vector from a JSON array of three numbers.
inline Eigen::Vector3d vec3_from_json(const nlohmann::json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

/// "(x, y, z)" for human output.
std::string vec_text(const nlohmann::json& j);

}  // namespace cordgrasp
