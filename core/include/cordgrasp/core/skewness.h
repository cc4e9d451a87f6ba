#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cordgrasp {

/// Skewness α (docs/algorithm.md §9, paper Eq. (2)) [rad] in [0, π/4]: with δ ∈ [0, π] the angle
/// between the palm axis (GCP +z) and the object's largest principal axis, α = |δ −
/// (π/2)·round(δ/(π/2))|. α = 0 when the palm axis is perpendicular or parallel to the principal
/// axis. Axes need not be unit; a zero axis gives α = 0.
double skewness_alpha_rad(const Eigen::Vector3d& palm_axis, const Eigen::Vector3d& principal_axis);

}  // namespace cordgrasp
