#include "cordgrasp/core/xor_area.h"

#include <clipper.hpp>

#include <cmath>

#include "plane_geometry_2d.h"

namespace cordgrasp {
namespace {

using detail::cross2;

void to_path(const std::vector<Eigen::Vector2d>& poly, double scale, ClipperLib::Path& path) {
  path.clear();
  for (const Eigen::Vector2d& v : poly)
    path.emplace_back(std::llround(v.x() * scale), std::llround(v.y() * scale));
}

double clip_area(const std::vector<Eigen::Vector2d>& p, const std::vector<Eigen::Vector2d>& q,
                 ClipperLib::ClipType type, double scale) {
  // One Clipper and path buffers per thread, cleared between calls (avoids reallocation).
  thread_local ClipperLib::Clipper clipper;
  thread_local ClipperLib::Path path_p, path_q;
  thread_local ClipperLib::Paths solution;
  clipper.Clear();
  to_path(p, scale, path_p);
  to_path(q, scale, path_q);
  clipper.AddPath(path_p, ClipperLib::ptSubject, true);
  clipper.AddPath(path_q, ClipperLib::ptClip, true);
  solution.clear();
  clipper.Execute(type, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double area = 0.0;
  for (const ClipperLib::Path& path : solution) area += ClipperLib::Area(path);
  return std::abs(area) / (scale * scale);
}

bool degenerate(const std::vector<Eigen::Vector2d>& p) {
  return p.size() < 3 || detail::signed_polygon_area(p) == 0.0;
}

}  // namespace

double polygon_area(const std::vector<Eigen::Vector2d>& polygon) {
  return std::abs(detail::signed_polygon_area(polygon));
}

double xor_area(const std::vector<Eigen::Vector2d>& p, const std::vector<Eigen::Vector2d>& q,
                double scale) {
  if (degenerate(p)) return degenerate(q) ? 0.0 : polygon_area(q);
  if (degenerate(q)) return polygon_area(p);
  return clip_area(p, q, ClipperLib::ctXor, scale);
}

double intersection_area(const std::vector<Eigen::Vector2d>& p,
                         const std::vector<Eigen::Vector2d>& q, double scale) {
  if (degenerate(p) || degenerate(q)) return 0.0;
  return clip_area(p, q, ClipperLib::ctIntersection, scale);
}

double convex_xor_area(const std::vector<Eigen::Vector2d>& p,
                       const std::vector<Eigen::Vector2d>& q) {
  const double ap = polygon_area(p), aq = polygon_area(q);
  if (degenerate(p) || degenerate(q)) return ap + aq;
  // Sutherland–Hodgman: clip P by each edge of Q (made counter-clockwise).
  thread_local std::vector<Eigen::Vector2d> cur, next;
  cur.assign(p.begin(), p.end());
  const bool ccw = detail::signed_polygon_area(q) > 0.0;
  const size_t m = q.size();
  for (size_t k = 0; k < m && !cur.empty(); ++k) {
    const Eigen::Vector2d& a = ccw ? q[k] : q[m - 1 - k];
    const Eigen::Vector2d& b = ccw ? q[(k + 1) % m] : q[(2 * m - 2 - k) % m];
    const Eigen::Vector2d e = b - a;
    next.clear();
    const size_t n = cur.size();
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d& s = cur[i];
      const Eigen::Vector2d& t = cur[(i + 1) % n];
      const double ds = cross2(e, s - a), dt = cross2(e, t - a);
      if (ds >= 0.0) next.push_back(s);
      if ((ds >= 0.0) != (dt >= 0.0)) next.push_back(s + (t - s) * (ds / (ds - dt)));
    }
    cur.swap(next);
  }
  const double ai = cur.size() < 3 ? 0.0 : polygon_area(cur);
  return std::max(0.0, ap + aq - 2.0 * ai);
}

}  // namespace cordgrasp
