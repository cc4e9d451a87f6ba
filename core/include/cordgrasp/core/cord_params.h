#pragma once
#include <cstdint>
#include <string>

#include "cordgrasp/core/serialize.h"

namespace cordgrasp {

/// Point set used for Φ1, Φ2, Φ3 on the sampling spheres (docs/algorithm.md §5).
enum class SphereSequence {
  kYershovaLaValle,  ///< Lindemann–LaValle lattice on the 6 cube faces, spherical bilinear map
  kFibonacci,        ///< golden-angle spiral; any near-uniform set works (reshuffled anyway)
};

/// How front_cord() builds cords once the guide triangle is known to be free
/// (docs/algorithm.md §3).
enum class CordConstruction {
  kHullChain,  ///< exact equivalent of TIGHTEN for the convex, free guides of §3: P_l, P_r by
               ///< TIGHTEN's first-event rule, front cord = convex-hull chain P_r→P_l
               ///< (O(k log k); collinear cord points dropped). Falls back to kTighten when
               ///< P_l or P_r is not a strict hull vertex.
  kTighten,    ///< TIGHTEN (docs/algorithm.md §2.3) on all candidates (O(k·h)), both Case I steps
};

/// How χ (docs/algorithm.md §6) intersects the projected front-cord polygons.
enum class XorBackend {
  kClipper,  ///< Clipper 6.4.2 integer XOR, coordinates × `clipper_scale`
  kConvex,   ///< exact convex clipping: A(P)+A(Q)−2A(P∩Q), valid as every Q_i is convex
};

/// What scanning does when a rotated cord T^{±i} fails (docs/algorithm.md §4).
enum class SideCordPolicy {
  kDiscardSet,  ///< any failing or case-changing ±i cord discards the set
  kShrink,      ///< shrink n symmetrically to the last i whose ±i cords succeed
  kEmptyWhenMissed,  ///< a ±i guide triangle that holds no part of the
                     ///< object (Case I "no contact": the scan swept past an object narrower
                     ///< than the palm) gives an empty polygon Q_i, which χ's degenerate rule
                     ///< scores A(Q_i ⊕ Q_0) = A(Q_0); any other failure or a case change still
                     ///< discards the set. n stays palm-width based, so such sets keep
                     ///< their size and rank behind sets whose cords all touch the object.
  kFallback,  ///< (default) the paper's discard where the object allows it: sets whose cords
              ///< all touch the object rank first (by χ); sets valid only with empty Q_i
              ///< (as kEmptyWhenMissed) rank after them, and exploration keeps sampling until
              ///< `sets` full sets or 2 × `sets` sets in all (docs/algorithm.md §4)
};

/// "yershova_lavalle", "fibonacci".
const char* to_string(SphereSequence sequence);
/// Parses the names of to_string(SphereSequence). @throws std::invalid_argument otherwise.
SphereSequence parse_sphere_sequence(const std::string& text);

/// "hull_chain", "tighten".
const char* to_string(CordConstruction construction);
/// Parses the names of to_string(CordConstruction). @throws std::invalid_argument otherwise.
CordConstruction parse_cord_construction(const std::string& text);

/// "clipper", "convex".
const char* to_string(XorBackend backend);
/// Parses the names of to_string(XorBackend). @throws std::invalid_argument otherwise.
XorBackend parse_xor_backend(const std::string& text);

/// "discard", "shrink", "empty", "fallback" (the CLI's --side-cords names).
const char* to_string(SideCordPolicy policy);
/// Parses the names of to_string(SideCordPolicy). @throws std::invalid_argument otherwise.
SideCordPolicy parse_side_cord_policy(const std::string& text);

/// Every number of the exploration stage (docs/algorithm.md §1–§6) with its default and unit.
struct CordParams {
  // Spheres (docs/algorithm.md §1)
  double r2_margin_m = 0.005;  ///< r2 = r + this (docs/algorithm.md §1) [m]
  double delta_r_m = 0.10;     ///< r1 = r2 + Δr [m]

  // Cord generation (docs/algorithm.md §2); tolerances of TIGHTEN (§2.3)
  double eps_len_m = 1e-9;         ///< TIGHTEN length tolerance eps_len [m]
  double eps_area_rel = 1e-14;     ///< TIGHTEN eps_a = eps_area_rel · r² [1]
  double barycentric_tol = 1e-12;  ///< closed-triangle test: barycentric ≥ −tol [1]
  double dedup_m = 1e-7;           ///< cord points closer than this are merged [m]
  double min_grasp_gap_m = 1e-3;   ///< FAIL when ‖P_l − P_r‖ is below this (§2.5) [m]
  CordConstruction cord_construction = CordConstruction::kHullChain;  ///< see CordConstruction

  // Eligibility of the seed cord (docs/algorithm.md §3)
  double xi_min_m = 0.015;                             ///< ξ_min [m]
  double xi_max_m = 0.075;                             ///< ξ_max [m]
  double max_squeeze_angle_rad = 0.78539816339744831;  ///< Case II angle test bound, π/4 [rad]

  // Scanning (docs/algorithm.md §4)
  double scan_angle_rad = 0.034906585039886591;  ///< θ = 2° between neighbouring cords [rad]
  int max_cords_per_side = 200;    ///< safety cap on n (not in the paper; n ≈ 5–30 in practice)
  SideCordPolicy side_cord_policy = SideCordPolicy::kFallback;  ///< see SideCordPolicy

  // Algorithm 1 (docs/algorithm.md §5)
  SphereSequence sphere_sequence = SphereSequence::kYershovaLaValle;
  int sphere_points = 10000;            ///< N points on each sphere [1]
  int max_iterations = 1000;            ///< M outer iterations (reshuffles) [1]
  int sets = 20;                        ///< K valid sets to collect before local improvement [1]
  double min_triangle_area_m2 = 1e-12;  ///< acute test: area must exceed this [m²]

  // Local improvement (docs/algorithm.md §5)
  bool local_improvement = true;   ///< run the local-improvement pass
  int perturbations_per_set = 10;  ///< L rigid perturbations of each set's T0 [1]
  double perturb_max_angle_rad = 0.087266462599716474;  ///< rotation ∈ [0, 5°] [rad]
  double perturb_max_translation_m = 0.01;              ///< translation uniform in this ball [m]

  // XOR measure χ (docs/algorithm.md §6)
  XorBackend xor_backend = XorBackend::kConvex;  ///< kConvex by default: same χ, ~20× cheaper
  double clipper_scale = 1e7;                    ///< S: Clipper integer units per meter (0.1 µm)

  // run control
  std::uint64_t seed = 1;      ///< seeds the single std::mt19937_64 (shuffles, perturbations)
  double time_limit_s = 30.0;  ///< wall-clock cap of explore_cords; ≤ 0 means none [s].
                               ///< Hitting it makes the result time-dependent.

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(r2_margin_m), CORDGRASP_NVP(delta_r_m), CORDGRASP_NVP(eps_len_m),
                 CORDGRASP_NVP(eps_area_rel), CORDGRASP_NVP(barycentric_tol),
                 CORDGRASP_NVP(dedup_m), CORDGRASP_NVP(min_grasp_gap_m),
                 CORDGRASP_NVP(cord_construction), CORDGRASP_NVP(xi_min_m),
                 CORDGRASP_NVP(xi_max_m), CORDGRASP_NVP(max_squeeze_angle_rad),
                 CORDGRASP_NVP(scan_angle_rad), CORDGRASP_NVP(max_cords_per_side),
                 CORDGRASP_NVP(side_cord_policy), CORDGRASP_NVP(sphere_sequence),
                 CORDGRASP_NVP(sphere_points), CORDGRASP_NVP(max_iterations), CORDGRASP_NVP(sets),
                 CORDGRASP_NVP(min_triangle_area_m2), CORDGRASP_NVP(local_improvement),
                 CORDGRASP_NVP(perturbations_per_set), CORDGRASP_NVP(perturb_max_angle_rad),
                 CORDGRASP_NVP(perturb_max_translation_m), CORDGRASP_NVP(xor_backend),
                 CORDGRASP_NVP(clipper_scale), CORDGRASP_NVP(seed), CORDGRASP_NVP(time_limit_s));
  }
};

}  // namespace cordgrasp
