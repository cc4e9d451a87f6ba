#include "fingertip_meeting_point.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "cordgrasp/core/kinematics.h"

namespace cordgrasp::hand_draft {
namespace {

/// The meeting point must bring the fingertips this much nearer each other than open, relative
/// to their open spread (below it the digits do not close towards each other).
constexpr double kMinRelativeApproach = 1e-3;

double mean_pairwise_distance(const std::vector<Eigen::Vector3d>& p) {
  double sum = 0.0;
  int n = 0;
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t k = i + 1; k < p.size(); ++k) {
      sum += (p[i] - p[k]).norm();
      ++n;
    }
  return n ? sum / n : 0.0;
}

}  // namespace

MeetingPoint fingertip_meeting_point(const HandModel& hand, const Eigen::VectorXd& q_open,
                                     const std::vector<ClosingDigit>& digits,
                                     const MeetingPointParams& params) {
  MeetingPoint out;
  bool any_joint = false;
  for (const ClosingDigit& d : digits) any_joint = any_joint || !d.closed_q.empty();
  if (digits.size() < 2 || !any_joint || params.samples < 2) return out;
  auto tips_at = [&](double s) {
    Eigen::VectorXd q = q_open;
    for (const ClosingDigit& d : digits)
      for (const auto& [j, closed] : d.closed_q) q[j] = q_open[j] + s * (closed - q_open[j]);
    q = clamp_to_limits(hand, apply_couplings(hand, clamp_to_limits(hand, q)));
    const auto X = link_poses(hand, q);
    std::vector<Eigen::Vector3d> tips;
    for (const ClosingDigit& d : digits) tips.push_back(X[d.tip_link] * d.p_tip_L);
    return tips;
  };
  std::vector<Eigen::Vector3d> best_tips = tips_at(0.0);
  out.spread_open_m = mean_pairwise_distance(best_tips);
  const double first = 1.0 / (params.samples - 1);
  const std::vector<Eigen::Vector3d> first_tips = tips_at(first);
  for (size_t i = 0; i < digits.size(); ++i)
    out.start_motion_W.push_back((first_tips[i] - best_tips[i]) / first);
  double best = out.spread_open_m;
  for (int k = 1; k < params.samples; ++k) {
    const double s = double(k) / (params.samples - 1);
    std::vector<Eigen::Vector3d> tips = tips_at(s);
    const double spread = mean_pairwise_distance(tips);
    if (spread < best) {
      best = spread;
      best_tips = std::move(tips);
      out.closure = s;
    }
  }
  if (!(best < out.spread_open_m * (1.0 - kMinRelativeApproach))) return out;
  out.found = true;
  out.spread_m = best;
  out.tips_W = best_tips;
  for (const auto& t : best_tips) out.p_W += t / double(best_tips.size());
  return out;
}

Eigen::Vector3d main_closing_axis(const std::vector<Eigen::Vector3d>& closing_motion_W) {
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& m : closing_motion_W)
    if (m.norm() > 1e-12) scatter += m.normalized() * m.normalized().transpose();
  if (scatter.isZero()) return Eigen::Vector3d::Zero();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  return eig.eigenvectors().col(2);  // eigenvalues ascending
}

RootsPlane roots_plane(const std::vector<Eigen::Vector3d>& roots_W, double min_second_ratio,
                       double max_flat_ratio) {
  RootsPlane out;
  if (roots_W.size() < 3) return out;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& r : roots_W) c += r / double(roots_W.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& r : roots_W) scatter += (r - c) * (r - c).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  const Eigen::Vector3d sd = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();  // ascending
  if (sd[2] <= 0.0 || sd[1] < min_second_ratio * sd[2] || sd[0] > max_flat_ratio * sd[1])
    return out;
  out.found = true;
  out.normal_W = eig.eigenvectors().col(0);
  return out;
}

OddDirection odd_direction_out_of_row(const std::vector<Eigen::Vector3d>& directions,
                                      double parallel_cosine, double margin) {
  OddDirection out;
  int found = 0;
  const size_t n = directions.size();
  for (size_t i = 0; i < n && n > 2; ++i) {
    bool row = true;
    double most_alike = -1.0;
    for (size_t a = 0; a < n; ++a) {
      if (a == i) continue;
      most_alike = std::max(most_alike, directions[i].dot(directions[a]));
      for (size_t b = a + 1; b < n; ++b)
        if (b != i && directions[a].dot(directions[b]) < parallel_cosine) row = false;
    }
    if (row && most_alike <= parallel_cosine - margin) {
      out.index = int(i);
      out.cosine = most_alike;
      ++found;
    }
  }
  if (found != 1) out = OddDirection{};
  return out;
}

Opposition opposition_across(const Eigen::Vector3d& axis_W,
                             const std::vector<Eigen::Vector3d>& roots_W,
                             const std::vector<Eigen::Vector3d>& closing_motion_W,
                             const Eigen::Vector3d& palm_W, double min_cosine) {
  Opposition out;
  Eigen::Vector3d along = Eigen::Vector3d::Zero(), against = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < roots_W.size() && i < closing_motion_W.size(); ++i) {
    const Eigen::Vector3d& m = closing_motion_W[i];
    if (m.norm() < 1e-12) continue;
    const double c = m.normalized().dot(axis_W);
    if (c >= min_cosine) {
      out.along.push_back(int(i));
      along += roots_W[i];
    } else if (c <= -min_cosine) {
      out.against.push_back(int(i));
      against += roots_W[i];
    }
  }
  if (out.along.empty() || out.against.empty()) return out;
  along /= double(out.along.size());
  against /= double(out.against.size());
  const Eigen::Vector3d apart = against - along;
  const double gap = apart.dot(axis_W);
  if (apart.norm() < 1e-12 || std::abs(gap) < 1e-12) return out;
  out.roots_apart_cosine = gap / apart.norm();
  out.palm_between = (palm_W - along).dot(axis_W) / gap;
  return out;
}

}  // namespace cordgrasp::hand_draft
