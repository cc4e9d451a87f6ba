#pragma once
// Internal to drafting a hand description: where the fingertips come closest together when the
// digits close from open (the grasp centre witness of docs/hand-description.md, "Drafting a
// description").
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "cordgrasp/core/hand_model.h"

namespace cordgrasp::hand_draft {

/// One digit: its fingertip and the joints that close it, each with its closed value.
struct ClosingDigit {
  int tip_link = -1;                                  ///< link holding the fingertip
  Eigen::Vector3d p_tip_L = Eigen::Vector3d::Zero();  ///< fingertip in that link [m]
  std::vector<std::pair<int, double>> closed_q;       ///< joint index, closed value [rad, m]
};

/// Sampling of the closing sweep.
struct MeetingPointParams {
  int samples = 40;  ///< closure fractions sampled from open (0) to closed (1), both included
};

/// The fingertips where they come closest together during the sweep.
struct MeetingPoint {
  bool found = false;                             ///< >= 2 digits, >= 1 closing joint
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();  ///< centroid of the fingertips there [m]
  double closure = 0.0;                           ///< fraction of the sweep, 0 open .. 1 closed
  double spread_open_m = 0.0;                     ///< mean pairwise fingertip distance, open [m]
  double spread_m = 0.0;                          ///< the same where they come closest [m]
  std::vector<Eigen::Vector3d> tips_W;            ///< each digit's fingertip there [m]
  /// Each digit's fingertip motion over the sweep's first step, per unit of the closure
  /// fraction: the way it starts closing [m].
  std::vector<Eigen::Vector3d> start_motion_W;
};

/// Moves every closing joint linearly from `q_open` to its closed value (couplings applied,
/// limits enforced) and returns where the mean pairwise distance between the digits' fingertips
/// is smallest (the earliest such fraction on ties).
MeetingPoint fingertip_meeting_point(const HandModel& hand, const Eigen::VectorXd& q_open,
                                     const std::vector<ClosingDigit>& digits,
                                     const MeetingPointParams& params = {});

/// How the digits close relative to an axis: those whose closing motion runs along it against
/// those running against it.
struct Opposition {
  std::vector<int> along;    ///< digits whose closing motion has cosine >= min_cosine with the axis
  std::vector<int> against;  ///< digits whose closing motion has cosine <= -min_cosine
  /// Cosine between the axis and the vector from the along digits' roots' centroid to the
  /// against digits' (0 when either group is empty): 1 when they face each other along it.
  double roots_apart_cosine = 0.0;
  /// Where the palm's centroid lies along the axis between the two roots' centroids: 0 at the
  /// along digits', 1 at the against digits' (0 when either group is empty).
  double palm_between = 0.0;
};

/// The direction most of the closing motions run along (either sign; unit): the principal axis
/// of their directions. Zero when no digit moves.
Eigen::Vector3d main_closing_axis(const std::vector<Eigen::Vector3d>& closing_motion_W);

/// Opposition of the digits (roots_W[i], closing_motion_W[i]: fingertip displacement while
/// closing) along `axis_W` (unit), relative to the palm centroid `palm_W`.
Opposition opposition_across(const Eigen::Vector3d& axis_W,
                             const std::vector<Eigen::Vector3d>& roots_W,
                             const std::vector<Eigen::Vector3d>& closing_motion_W,
                             const Eigen::Vector3d& palm_W, double min_cosine);

/// The plane through three or more points that spread over two directions (a palm's face
/// holding the digits' roots).
struct RootsPlane {
  bool found = false;  ///< >= 3 points, spread along a second direction, flat across it
  Eigen::Vector3d normal_W = Eigen::Vector3d::Zero();  ///< unit, sign arbitrary
};

/// The plane of `roots_W` when their spread along the second principal direction is at least
/// `min_second_ratio` of the first's, and across the plane at most `max_flat_ratio` of the
/// second's (standard deviations).
RootsPlane roots_plane(const std::vector<Eigen::Vector3d>& roots_W, double min_second_ratio = 0.25,
                       double max_flat_ratio = 0.2);

/// The one direction out of a row: every other pair of `directions` (unit) has a cosine of at
/// least `parallel_cosine`, and this one's cosine with each of them is at most
/// `parallel_cosine - margin`. index -1 when no direction, or more than one, is so.
struct OddDirection {
  int index = -1;
  double cosine = 1.0;  ///< its largest cosine with another direction
};
OddDirection odd_direction_out_of_row(const std::vector<Eigen::Vector3d>& directions,
                                      double parallel_cosine, double margin);

}  // namespace cordgrasp::hand_draft
