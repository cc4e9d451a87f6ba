#include "cordgrasp/core/explore_cords.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <numeric>
#include <random>
#include <stdexcept>

#include "cord_random.h"
#include "cordgrasp/core/cord_object.h"
#include "cordgrasp/core/guide_frame.h"
#include "cordgrasp/core/parallel_for.h"
#include "cordgrasp/core/scan_cord_set.h"
#include "cordgrasp/core/sphere_points.h"

namespace cordgrasp {
namespace {

using Clock = std::chrono::steady_clock;

/// Unit sphere points, computed once per (count, kind) and process (they are deterministic).
const std::vector<Eigen::Vector3d>& cached_sphere_points(int count, SphereSequence kind) {
  static std::mutex mutex;
  static std::map<std::pair<int, int>, std::vector<Eigen::Vector3d>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  std::vector<Eigen::Vector3d>& points = cache[{count, int(kind)}];
  if (int(points.size()) != count) points = sphere_points(count, kind);
  return points;
}

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

std::vector<GraspRegion> explore_cords(const Mesh& mesh, double palm_width_m,
                                       const CordParams& params, ExplorationStats* stats_out,
                                       std::shared_ptr<const MeshBvh> object_bvh, int threads) {
  const Clock::time_point start = Clock::now();
  if (!(palm_width_m > 0.0)) throw std::invalid_argument("explore_cords: palm width must be > 0 m");
  const CordObject object = make_cord_object(mesh, std::move(object_bvh));
  ExplorationStats st;
  const bool timed = params.time_limit_s > 0.0;
  const Clock::time_point deadline =
      timed ? start + std::chrono::duration_cast<Clock::duration>(
                          std::chrono::duration<double>(params.time_limit_s))
            : Clock::time_point::max();
  auto out_of_time = [&]() {
    if (timed && Clock::now() >= deadline) st.hit_time_limit = true;
    return st.hit_time_limit;
  };

  const double r2 = object.radius_m + params.r2_margin_m;
  const double r1 = r2 + params.delta_r_m;
  const int count = std::max(0, params.sphere_points);
  const std::vector<Eigen::Vector3d>& unit = cached_sphere_points(count, params.sphere_sequence);
  std::mt19937_64 rng(params.seed);
  std::vector<int> perm1(count), perm2(count), perm3(count);
  std::iota(perm1.begin(), perm1.end(), 0);
  perm2 = perm3 = perm1;

  // Algorithm 1 (docs/algorithm.md §5).
  std::vector<GraspRegion> found;
  const size_t wanted = size_t(std::max(0, params.sets));
  // kFallback (docs/algorithm.md §4): sampling ends at `wanted` sets whose cords all touch the
  // object, or at 2 × `wanted` sets in all when the object is too small for full sets.
  const bool fallback = params.side_cord_policy == SideCordPolicy::kFallback;
  size_t full = 0;
  auto enough = [&]() {
    return fallback ? (full >= wanted || found.size() >= 2 * wanted) : found.size() >= wanted;
  };
  const Clock::time_point sampling_start = Clock::now();
  // Guide triangles are drawn in the serial order; up to `batch` acute ones at a time are scanned
  // on `threads` threads, then taken in draw order until enough sets are found (scans past that
  // point are dropped): the regions and counters are those of a one-at-a-time loop.
  struct Sampled {
    int j = 0;
    Eigen::Vector3d p1, p2, p3;
    bool acute = false;
    ScanFailure why = ScanFailure::kNone;
    std::optional<GraspRegion> region;
  };
  const int batch = threads > 1 ? 2 * threads : 1;
  std::vector<Sampled> pending;
  bool stop = false;
  for (int it = 0; it < params.max_iterations && !enough() && count > 0 && !stop; ++it) {
    if (out_of_time()) break;
    ++st.iterations;
    detail::shuffle(perm1, rng);
    detail::shuffle(perm2, rng);
    detail::shuffle(perm3, rng);
    int j = 0;
    while (j < count && !enough() && !stop) {
      pending.clear();
      for (int k = j, acute = 0; k < count && acute < batch; ++k) {
        Sampled& c = pending.emplace_back();
        c.j = k;
        c.p1 = object.center + r1 * unit[perm1[k]];
        c.p2 = object.center + r2 * unit[perm2[k]];
        c.p3 = object.center + r2 * unit[perm3[k]];
        c.acute = is_acute_triangle(c.p1, c.p2, c.p3, params.min_triangle_area_m2);
        acute += c.acute ? 1 : 0;
      }
      parallel_for(int(pending.size()), threads, [&](int i) {
        Sampled& c = pending[size_t(i)];
        if (c.acute)
          c.region = scan_cord_set(object, c.p1, c.p2, c.p3, palm_width_m, params, &c.why);
      });
      for (Sampled& c : pending) {
        if (enough()) break;
        if ((c.j & 63) == 0 && out_of_time()) {
          stop = true;
          break;
        }
        j = c.j + 1;
        ++st.triangles_sampled;
        if (!c.acute) continue;
        ++st.triangles_acute;
        if (c.why != ScanFailure::kSeedCord) ++st.seed_cords;
        if (c.why == ScanFailure::kNone || c.why == ScanFailure::kSideCord) ++st.sets_tried;
        if (c.region) {
          ++st.sets_valid;
          if (side_cords_missed(*c.region) == 0) ++full;
          found.push_back(std::move(*c.region));
        }
      }
    }
  }
  st.sampling_time_s = seconds_since(sampling_start);

  // Local improvement (docs/algorithm.md §5): L rigid perturbations of each set's T0.
  const Clock::time_point improvement_start = Clock::now();
  if (params.local_improvement && !st.hit_time_limit) {
    // The perturbations are drawn first, in the serial order, and scanned independently (on
    // `threads` threads); the valid ones are appended in draw order.
    struct Perturbed {
      Eigen::Vector3d p[3];
      bool tried = false;
      std::optional<GraspRegion> region;
    };
    const size_t base = found.size();
    std::vector<Perturbed> drawn;
    drawn.reserve(base * size_t(std::max(0, params.perturbations_per_set)));
    for (size_t s = 0; s < base; ++s) {
      const Eigen::Vector3d t0[3] = {found[s].p1, found[s].p2, found[s].p3};
      const Eigen::Vector3d g = (t0[0] + t0[1] + t0[2]) / 3.0;
      for (int l = 0; l < params.perturbations_per_set; ++l) {
        const Eigen::Vector3d axis = detail::uniform_unit_vector(rng);
        const double angle = detail::uniform01(rng) * params.perturb_max_angle_rad;
        const Eigen::Vector3d shift =
            detail::uniform_in_ball(rng, params.perturb_max_translation_m);
        const Eigen::AngleAxisd rot(angle, axis);
        Perturbed& d = drawn.emplace_back();
        for (int k = 0; k < 3; ++k) d.p[k] = g + rot * (t0[k] - g) + shift;
      }
    }
    std::atomic<bool> late{false};
    parallel_for(int(drawn.size()), threads, [&](int i) {
      if (late || (timed && Clock::now() >= deadline)) {
        late = true;  // the rest is skipped (the result is marked not reproducible)
        return;
      }
      Perturbed& d = drawn[size_t(i)];
      d.tried = true;
      if (!is_acute_triangle(d.p[0], d.p[1], d.p[2], params.min_triangle_area_m2)) return;
      d.region = scan_cord_set(object, d.p[0], d.p[1], d.p[2], palm_width_m, params);
    });
    if (late) st.hit_time_limit = true;
    for (Perturbed& d : drawn) {
      st.improvement_tried += d.tried ? 1 : 0;
      if (!d.region) continue;
      d.region->from_local_improvement = true;
      ++st.improvement_valid;
      found.push_back(std::move(*d.region));
    }
  }
  st.improvement_time_s = seconds_since(improvement_start);

  std::stable_sort(found.begin(), found.end(),
                   [](const GraspRegion& a, const GraspRegion& b) { return a.chi_m2 < b.chi_m2; });
  st.time_s = seconds_since(start);
  if (stats_out) *stats_out = st;
  return found;
}

}  // namespace cordgrasp
