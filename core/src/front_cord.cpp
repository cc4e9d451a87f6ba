#include "cordgrasp/core/front_cord.h"

#include <algorithm>
#include <cmath>

#include "convex_hull_2d.h"
#include "cordgrasp/core/plane_cross_section.h"
#include "cordgrasp/core/tighten_cord.h"
#include "plane_geometry_2d.h"
#include "segment_pierces.h"

namespace cordgrasp {
namespace {

using detail::cross2;

/// Segments whose endpoints are farther than this (barycentric units) on one side of a guide
/// edge line skip the exact intersection test: far above rounding, so nothing is missed.
constexpr double kSideMargin = 1e-9;

/// Reused buffers (one set per thread) so the hot path does not allocate.
struct Workspace {
  std::vector<Segment2> local_segments;
  std::vector<Eigen::Vector2d> candidates;
  std::vector<double> hits;
  std::vector<Eigen::Vector2d> hull_input;
  std::vector<Eigen::Vector2d> hull;
  std::vector<Eigen::Vector2d> hull_scratch;
};

/// Front cord as the counter-clockwise hull chain from P_r to P_l (CordConstruction::kHullChain):
/// only candidates strictly on P1's side of line P_r P_l can be on it. Empty when P_r or P_l is
/// not a vertex of that strict hull (near-degenerate input: the caller falls back to TIGHTEN).
void hull_chain(Workspace& ws, const Eigen::Vector2d& q1, const Eigen::Vector2d& p_r,
                const Eigen::Vector2d& p_l, std::vector<Eigen::Vector2d>& chain) {
  chain.clear();
  const Eigen::Vector2d dir = p_l - p_r;
  const double side = cross2(dir, q1 - p_r);
  ws.hull_input.clear();
  for (const Eigen::Vector2d& v : ws.candidates)
    if (cross2(dir, v - p_r) * side > 0.0) ws.hull_input.push_back(v);
  ws.hull_input.push_back(p_r);
  ws.hull_input.push_back(p_l);
  detail::convex_hull_ccw(ws.hull_input, ws.hull, ws.hull_scratch);
  const auto& h = ws.hull;
  const size_t m = h.size();
  const size_t ir = size_t(std::find(h.begin(), h.end(), p_r) - h.begin());
  const size_t il = size_t(std::find(h.begin(), h.end(), p_l) - h.begin());
  if (ir == m || il == m) return;
  for (size_t k = ir;; k = (k + 1) % m) {
    chain.push_back(h[k]);
    if (k == il) break;
  }
}

/// P_l and P_r of Case I: the first points swept from P1 as the target moves P2→P3 and P3→P2
/// (ties: nearer), exactly TIGHTEN's first event (first_swept_point) for candidates already in
/// the closed triangle; one pass for both.
std::pair<int, int> tangent_points(const Eigen::Vector2d& q1,
                                   const std::vector<Eigen::Vector2d>& pts, double eps_len) {
  int il = -1, ir = -1;
  Eigen::Vector2d dl(0.0, 0.0), dr(0.0, 0.0);
  double dl2 = 0.0, dr2 = 0.0;
  const double eps2 = eps_len * eps_len;
  for (int k = 0; k < int(pts.size()); ++k) {
    const Eigen::Vector2d d = pts[k] - q1;
    const double d2 = d.squaredNorm();
    if (d2 <= eps2) continue;
    if (il < 0) {
      il = ir = k;
      dl = dr = d;
      dl2 = dr2 = d2;
      continue;
    }
    const double cl = cross2(d, dl);  // > 0: swept before the current P_l (sense +1)
    if (cl > 0.0 || (cl == 0.0 && d2 < dl2)) {
      il = k;
      dl = d;
      dl2 = d2;
    }
    const double cr = -cross2(d, dr);  // sense −1
    if (cr > 0.0 || (cr == 0.0 && d2 < dr2)) {
      ir = k;
      dr = d;
      dr2 = d2;
    }
  }
  return {il, ir};
}

/// Does closed segment [a, b] meet segment s at parameter t ∈ [0, 1] along a→b?
/// Appends every such t (both overlap ends for a collinear overlap) to `ts`.
void segment_hits(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Segment2& s,
                  std::vector<double>& ts) {
  const Eigen::Vector2d r = b - a, sv = s.b - s.a, qa = s.a - a;
  const double denom = cross2(r, sv);
  if (denom != 0.0) {
    const double t = cross2(qa, sv) / denom, u = cross2(qa, r) / denom;
    if (u >= 0.0 && u <= 1.0 && t >= 0.0 && t <= 1.0) ts.push_back(t);
    return;
  }
  if (cross2(qa, r) != 0.0) return;
  const double len2 = r.squaredNorm();
  const double ta = qa.dot(r) / len2, tb = (s.b - a).dot(r) / len2;
  const double lo = std::max(std::min(ta, tb), 0.0), hi = std::min(std::max(ta, tb), 1.0);
  if (lo <= hi) {
    ts.push_back(lo);
    ts.push_back(hi);
  }
}

std::optional<FrontCord> fail(FrontCordFailure why, FrontCordFailure* out) {
  if (out) *out = why;
  return std::nullopt;
}

}  // namespace

Polyline3 FrontCord::cord_3d() const {
  Polyline3 out;
  out.reserve(cord.size());
  for (const Eigen::Vector2d& q : cord) out.push_back(frame.to_3d(q));
  return out;
}

std::optional<FrontCord> front_cord(const CordObject& object, const Eigen::Vector3d& p1,
                                    const Eigen::Vector3d& p2, const Eigen::Vector3d& p3,
                                    const CordParams& params, FrontCordFailure* failure) {
  thread_local std::vector<Segment2> segments;
  const PlaneFrame frame = guide_frame(p1, p2, p3);
  const Eigen::Vector2d region[3] = {Eigen::Vector2d::Zero(), frame.to_2d(p2), frame.to_2d(p3)};
  segments.clear();
  append_plane_cross_section_segments(*object.bvh, frame, segments, region);
  return front_cord_from_segments(frame, p2, p3, segments, object.radius_m, params, failure);
}

std::optional<FrontCord> front_cord_from_segments(const PlaneFrame& frame,
                                                  const Eigen::Vector3d& p2,
                                                  const Eigen::Vector3d& p3,
                                                  const std::vector<Segment2>& segments,
                                                  double radius_m, const CordParams& params,
                                                  FrontCordFailure* failure) {
  thread_local Workspace ws;
  if (failure) *failure = FrontCordFailure::kNone;
  FrontCord fc;
  fc.frame = frame;
  const Eigen::Vector2d q1(0.0, 0.0), q2 = fc.frame.to_2d(p2), q3 = fc.frame.to_2d(p3);
  const double eps = params.eps_len_m;
  const double len12 = (q2 - q1).norm(), len13 = (q3 - q1).norm();
  const Eigen::Vector2d dir12 = (q2 - q1) / len12, dir13 = (q3 - q1) / len13;

  // One pass over S: guide-edge freedom, P2P3 hits, candidates inside the closed triangle.
  // Barycentric weights (l1, l2, l3) of each endpoint: l3 = 0 on line P1P2, l2 = 0 on P1P3,
  // l1 = 0 on P2P3; the exact edge tests run only for segments not strictly on one side.
  const double inv_area = 1.0 / cross2(q2 - q1, q3 - q1);
  const double tol = params.barycentric_tol;
  const Eigen::Vector2d box_lo = q1.cwiseMin(q2).cwiseMin(q3);
  const Eigen::Vector2d box_hi = q1.cwiseMax(q2).cwiseMax(q3);
  auto one_side = [](double u, double v) {
    return (u > kSideMargin && v > kSideMargin) || (u < -kSideMargin && v < -kSideMargin);
  };
  ws.local_segments.clear();
  ws.candidates.clear();
  ws.hits.clear();
  for (const Segment2& s : segments) {
    if (std::max(s.a.x(), s.b.x()) < box_lo.x() || std::min(s.a.x(), s.b.x()) > box_hi.x() ||
        std::max(s.a.y(), s.b.y()) < box_lo.y() || std::min(s.a.y(), s.b.y()) > box_hi.y())
      continue;
    const double a1 = cross2(q2 - s.a, q3 - s.a) * inv_area;
    const double a2 = cross2(q3 - s.a, q1 - s.a) * inv_area;
    const double a3 = cross2(q1 - s.a, q2 - s.a) * inv_area;
    const double b1 = cross2(q2 - s.b, q3 - s.b) * inv_area;
    const double b2 = cross2(q3 - s.b, q1 - s.b) * inv_area;
    const double b3 = cross2(q1 - s.b, q2 - s.b) * inv_area;
    if ((!one_side(a3, b3) && detail::segment_pierces(q1, dir12, len12, s, eps)) ||
        (!one_side(a2, b2) && detail::segment_pierces(q1, dir13, len13, s, eps)))
      return fail(FrontCordFailure::kGuideBlocked, failure);
    const size_t nhits = ws.hits.size();
    if (!one_side(a1, b1)) segment_hits(q2, q3, s, ws.hits);
    const bool in_a = a1 >= -tol && a2 >= -tol && a3 >= -tol;
    const bool in_b = b1 >= -tol && b2 >= -tol && b3 >= -tol;
    // Shared mesh edges give bit-identical endpoints; skipping a repeat of one of the last two
    // candidates (adjacent triangles are usually sliced one after the other) is exact.
    auto add = [&](const Eigen::Vector2d& v) {
      const size_t m = ws.candidates.size();
      if ((m > 0 && ws.candidates[m - 1] == v) || (m > 1 && ws.candidates[m - 2] == v)) return;
      ws.candidates.push_back(v);
    };
    if (in_a) add(s.a);
    if (in_b) add(s.b);
    if (in_a || in_b || ws.hits.size() > nhits) ws.local_segments.push_back(s);
  }

  TightenOptions topt;
  topt.eps_len_m = eps;
  topt.eps_area_m2 = params.eps_area_rel * radius_m * radius_m;
  topt.barycentric_tol = params.barycentric_tol;
  topt.dedup_m = params.dedup_m;

  const bool use_hull = params.cord_construction == CordConstruction::kHullChain;
  Eigen::Vector2d p_l, p_r;
  if (ws.hits.empty()) {
    fc.cord_case = CordCase::kI;
    if (ws.candidates.empty()) return fail(FrontCordFailure::kNoContact, failure);
    if (use_hull) {
      // TIGHTEN on P1→P2→P3→P1: its first event is P_l, its last contact P_r (the first event
      // of the mirrored sweep from P1, P3 towards P2).
      const auto [il, ir] = tangent_points(q1, ws.candidates, eps);
      p_l = ws.candidates[il];
      p_r = ws.candidates[ir];
    } else {
      const auto back = tighten_cord({q1, q2, q3, q1}, ws.candidates, ws.local_segments, topt);
      if (!back) return fail(FrontCordFailure::kTightenFailed, failure);
      if (back->size() < 3) return fail(FrontCordFailure::kNoContact, failure);
      p_l = (*back)[1];
      p_r = (*back)[back->size() - 2];
    }
  } else {
    fc.cord_case = CordCase::kII;
    const auto [tmin, tmax] = std::minmax_element(ws.hits.begin(), ws.hits.end());
    p_l = q2 + *tmin * (q3 - q2);
    p_r = q2 + *tmax * (q3 - q2);
  }
  if ((p_l - p_r).norm() < params.min_grasp_gap_m)
    return fail(FrontCordFailure::kGraspPointsTooClose, failure);

  if (use_hull) hull_chain(ws, q1, p_r, p_l, fc.cord);
  if (fc.cord.empty()) {
    auto front = tighten_cord({p_r, q3, q1, q2, p_l}, ws.candidates, ws.local_segments, topt);
    if (!front) return fail(FrontCordFailure::kTightenFailed, failure);
    fc.cord = std::move(*front);
  }
  if (fc.cord_case == CordCase::kII && fc.cord.size() < 3)
    return fail(FrontCordFailure::kTooFewSegments, failure);
  return fc;
}

}  // namespace cordgrasp
