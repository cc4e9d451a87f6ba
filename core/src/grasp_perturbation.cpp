#include "cordgrasp/core/grasp_perturbation.h"

#include <random>

namespace cordgrasp {

namespace {

Eigen::Vector3d random_unit_vector(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  for (;;) {
    const Eigen::Vector3d v(normal(rng), normal(rng), normal(rng));
    if (v.norm() > 1e-9) return v.normalized();
  }
}

}  // namespace

Grasp perturbed_grasp(const Grasp& grasp, const PerturbationParams& params, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Eigen::Vector3d offset = params.offset_m * random_unit_vector(rng);
  const Eigen::AngleAxisd turn(params.turn_rad, random_unit_vector(rng));
  // Rigid motion of the hand in the object frame: turn about the GCP, then shift.
  const Eigen::Vector3d p_G = grasp.X_OG.translation();
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.translate(p_G + offset);
  motion.rotate(turn);
  motion.translate(-p_G);
  Grasp out = grasp;
  out.X_OB = motion * grasp.X_OB;
  out.X_OG = motion * grasp.X_OG;
  return out;
}

}  // namespace cordgrasp
