#include "substitute_inertial.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>

#include "hand_load_common.h"

namespace cordgrasp::hand_load {
namespace {

/// Substituted inertials: solid box of the link's geometry bounds at this density [kg/m³].
constexpr double kSubstituteDensity_kgm3 = 700.0;
/// Substituted inertials never go below this mass [kg].
constexpr double kMinSubstituteMass_kg = 0.001;
/// Side of the cube used for links without any geometry [m].
constexpr double kFrameCubeSide_m = 0.01;
/// Declared mass / bounding-box volume outside this range is a placeholder [kg/m³]: the box
/// over-estimates the volume, so a real link can only look lighter, never denser than steel.
constexpr double kMinPlausibleDensity_kgm3 = 20.0;
constexpr double kMaxPlausibleDensity_kgm3 = 10000.0;

/// Bounds of the link's collision geometry (of its visuals when it has no collision geometry).
Box3 link_geometry_box(const Link& link) {
  std::vector<Eigen::Vector3d> pts;
  for (const auto& g : link.collisions) append_geometry_corners(g, pts);
  if (pts.empty())
    for (const auto& g : link.visuals) append_geometry_corners(g, pts);
  Box3 box;
  for (const auto& p : pts) box.add(p);
  return box;
}

Eigen::Matrix3d solid_box_inertia(double mass, const Eigen::Vector3d& size) {
  const Eigen::Vector3d s2 = size.cwiseProduct(size);
  return Eigen::Vector3d(mass / 12.0 * (s2.y() + s2.z()), mass / 12.0 * (s2.x() + s2.z()),
                         mass / 12.0 * (s2.x() + s2.y()))
      .asDiagonal();
}

/// True when the inertia tensor is physically possible for a body of this mass (and, when the
/// geometry is known, one that fits inside a box of diagonal `diag_m`).
bool plausible_inertia(const Inertial& in, double diag_m) {
  const Eigen::Matrix3d& I = in.inertia_kgm2;
  if (!I.allFinite() || (I - I.transpose()).cwiseAbs().maxCoeff() > 1e-12 * I.norm() + 1e-15)
    return false;
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  if (ev.minCoeff() <= 0.0) return false;
  const double tri_tol = 1e-9 * ev.sum();
  if (ev(0) + ev(1) < ev(2) - tri_tol) return false;  // triangle inequality
  // trace/2 = ∫|r|² dm <= m · (largest distance from the COM)² <= m · diag².
  if (diag_m > 0.0 && 0.5 * ev.sum() > in.mass_kg * diag_m * diag_m) return false;
  return true;
}

}  // namespace

bool substitute_inertial_if_needed(Link& link, bool declared) {
  const Box3 box = link_geometry_box(link);
  const bool has_geometry = !box.empty();
  const Eigen::Vector3d size = has_geometry ? (box.max - box.min).eval() : Eigen::Vector3d::Zero();
  const double volume = size.prod();
  Inertial& in = link.inertial;
  bool mass_ok = declared && std::isfinite(in.mass_kg) && in.mass_kg > 0.0;
  if (mass_ok && has_geometry && volume > 0.0) {
    const double density = in.mass_kg / volume;
    mass_ok = density >= kMinPlausibleDensity_kgm3 && density <= kMaxPlausibleDensity_kgm3;
  }
  const bool inertia_ok = mass_ok && plausible_inertia(in, has_geometry ? size.norm() : 0.0);
  if (mass_ok && inertia_ok && in.com_m.allFinite()) return false;

  const Eigen::Vector3d box_size = has_geometry
                                       ? size.cwiseMax(Eigen::Vector3d::Constant(1e-3)).eval()
                                       : Eigen::Vector3d::Constant(kFrameCubeSide_m);
  const Eigen::Vector3d center =
      has_geometry ? (0.5 * (box.min + box.max)).eval() : Eigen::Vector3d::Zero();
  if (!mass_ok) {
    in.mass_kg = std::max(kMinSubstituteMass_kg, kSubstituteDensity_kgm3 * box_size.prod());
    in.com_m = center;
  } else if (has_geometry) {
    // Keep the declared mass; keep its COM when it lies inside the geometry bounds.
    const Eigen::Vector3d margin = 0.05 * box_size;
    const bool inside = in.com_m.allFinite() &&
                        (in.com_m.array() >= (box.min - margin).array()).all() &&
                        (in.com_m.array() <= (box.max + margin).array()).all();
    if (!inside) in.com_m = center;
  } else if (!in.com_m.allFinite()) {
    in.com_m = center;
  }
  in.inertia_kgm2 = solid_box_inertia(in.mass_kg, box_size);
  in.substituted = true;
  return true;
}

void warn_substituted_once(const std::string& urdf_path, const std::vector<std::string>& names) {
  static std::mutex mutex;
  static std::set<std::string> warned;
  std::lock_guard<std::mutex> lock(mutex);
  if (!warned.insert(urdf_path).second) return;
  std::ostringstream msg;
  msg << "cordgrasp: warning: " << in_quotes(urdf_path)
      << ": missing, placeholder or impossible inertials on " << names.size()
      << " link(s), replaced by solid boxes of their geometry bounds (" << kSubstituteDensity_kgm3
      << " kg/m^3 unless the declared mass is plausible): ";
  for (size_t i = 0; i < names.size(); ++i) msg << (i ? ", " : "") << in_quotes(names[i]);
  std::cerr << msg.str() << '\n';
}

}  // namespace cordgrasp::hand_load
