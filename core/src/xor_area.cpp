#include "cordgrasp/core/xor_area.h"

#include <clipper.hpp>
#include <cmath>

#include "convex_xor_area.h"
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
  return detail::convex_xor_area(p.data(), p.size(), q.data(), q.size());
}

}  // namespace cordgrasp
