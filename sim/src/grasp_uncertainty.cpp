#include "cordgrasp/sim/grasp_uncertainty.h"

#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/enum_names.h"

namespace cordgrasp {
namespace {

constexpr EnumName<UncertaintyFactor> kFactorNames[] = {
    {UncertaintyFactor::kHandOffset, "hand_offset"}, {UncertaintyFactor::kHandTurn, "hand_turn"},
    {UncertaintyFactor::kFriction, "friction"},      {UncertaintyFactor::kMass, "mass"},
    {UncertaintyFactor::kComOffset, "com_offset"},   {UncertaintyFactor::kSqueeze, "squeeze"},
};

/// splitmix64 step: mixes a 64-bit state into a well-spread value.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// Range check of one field (check_uncertainty_params' archive).
struct RangeCheck {
  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    const std::string name = nvp.name;
    const double value = *nvp.value;
    double hi = 0.9;  // relative spreads
    if (name == "hand_offset_sigma_m" || name == "com_offset_sigma_m") hi = 0.05;
    if (name == "hand_turn_sigma_rad") hi = M_PI / 4.0;
    if (std::isfinite(value) && value >= 0.0 && value <= hi) return;
    std::ostringstream why;
    why << name << ": " << value << " is not in [0, " << hi << "]";
    throw std::invalid_argument(why.str());
  }
};

/// Sets every field to 0.
struct ZeroFields {
  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    *nvp.value = 0.0;
  }
};

/// Is any field non-zero?
struct AnyNonZero {
  bool any = false;
  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    any = any || *nvp.value != 0.0;
  }
};

}  // namespace

const char* to_string(UncertaintyFactor factor) { return enum_to_string(factor, kFactorNames); }

UncertaintyParams uncertainty_none() {
  UncertaintyParams params;
  ZeroFields zero;
  params.Serialize(&zero);
  return params;
}

bool is_none(const UncertaintyParams& params) {
  UncertaintyParams copy = params;
  AnyNonZero check;
  copy.Serialize(&check);
  return !check.any;
}

void check_uncertainty_params(const UncertaintyParams& params) {
  UncertaintyParams copy = params;
  RangeCheck check;
  copy.Serialize(&check);
}

UncertaintyDraw draw_uncertainty(const UncertaintyParams& params, std::uint64_t seed,
                                 int grasp_index, int trial) {
  // One stream per (seed, grasp, trial), drawn in a fixed order.
  std::mt19937_64 rng(mix(mix(mix(seed) ^ static_cast<std::uint64_t>(grasp_index)) ^
                          static_cast<std::uint64_t>(trial)));
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto normal3 = [&] {
    const double x = normal(rng), y = normal(rng), z = normal(rng);
    return Eigen::Vector3d(x, y, z);
  };
  const Eigen::Vector3d offset = normal3();
  const Eigen::Vector3d turn = normal3();
  const double mu = uniform(rng);
  const double mass = uniform(rng);
  const Eigen::Vector3d com = normal3();
  const double squeeze = uniform(rng);

  UncertaintyDraw d;
  d.hand_offset_G_m = params.hand_offset_sigma_m * offset;
  d.hand_turn_G_rad = params.hand_turn_sigma_rad * turn;
  d.mu_factor = 1.0 + params.mu_relative_spread * mu;
  d.mass_factor = 1.0 + params.mass_relative_spread * mass;
  d.com_offset_O_m = params.com_offset_sigma_m * com;
  d.squeeze_factor = 1.0 + params.squeeze_relative_spread * squeeze;
  d.scores = {offset.norm(), turn.norm(), mu, mass, com.norm(), squeeze};
  return d;
}

UncertainTrial apply_uncertainty(const Grasp& grasp, const SimParams& params,
                                 const UncertaintyDraw& draw) {
  UncertainTrial out{grasp, params};
  // The hand moves rigidly in its GCP frame: X_OG' = X_OG · Δ, and the root with it.
  Eigen::Isometry3d delta = Eigen::Isometry3d::Identity();
  delta.translate(draw.hand_offset_G_m);
  const double angle = draw.hand_turn_G_rad.norm();
  if (angle > 0.0) delta.rotate(Eigen::AngleAxisd(angle, draw.hand_turn_G_rad / angle));
  const Eigen::Isometry3d motion_O = grasp.X_OG * delta * grasp.X_OG.inverse();
  out.grasp.X_OB = motion_O * grasp.X_OB;
  out.grasp.X_OG = motion_O * grasp.X_OG;

  SimParams& p = out.params;
  p.contact.mu *= draw.mu_factor;
  if (p.mass_kg)
    *p.mass_kg *= draw.mass_factor;
  else
    p.density_kgm3 *= draw.mass_factor;  // mass = density × volume
  p.com_offset_x_m += draw.com_offset_O_m.x();
  p.com_offset_y_m += draw.com_offset_O_m.y();
  p.com_offset_z_m += draw.com_offset_O_m.z();
  // The effort is sized ∝ k·m·g/μ with the true m and μ; the controller knows only the
  // nominal ones, so k carries μ / m back out.
  p.squeeze_weight_factor *= draw.squeeze_factor * draw.mu_factor / draw.mass_factor;
  return out;
}

Grasp close_at_drawn_pose(const Grasp& drawn, const HandModel& hand, const HandSetup& setup,
                          HandObjectCollider& collider) {
  FingerResult closed;
  const Eigen::VectorXd& q_start =
      drawn.q_preshape.size() == drawn.q.size() ? drawn.q_preshape : setup.q_preshape;
  close_fingers(hand, setup, collider, drawn.X_OB, q_start, FingerParams{}, closed);
  Grasp out = drawn;
  std::vector<char> reclosed(static_cast<size_t>(setup.num_links), 0);
  for (size_t a = 0; a < hand.actors.size() && a < setup.actor_joints.size(); ++a) {
    // A finger that meets the object no later than planned keeps the plan: it presses the
    // object there, as the planned grasp's fingers do (a gripper's first pad pushes the free
    // object to the other). One the drawn pose leaves short of the object closes on.
    double further = 0.0;
    for (const Actor::Entry& e : hand.actors[a].joints)
      further += e.direction_speed * (closed.q[e.joint] - drawn.q[e.joint]);
    if (!(further > 0.0)) continue;
    for (const int j : setup.actor_joints[a]) out.q[j] = closed.q[j];
    for (const int l : setup.actor_links[a]) reclosed[static_cast<size_t>(l)] = 1;
  }
  const auto on_reclosed = [&](const Contact& c) {
    return c.link >= 0 && c.link < setup.num_links && reclosed[static_cast<size_t>(c.link)];
  };
  out.contacts.clear();
  for (const Contact& c : drawn.contacts)
    if (!on_reclosed(c)) out.contacts.push_back(c);
  for (const Contact& c : closed.contacts)
    if (on_reclosed(c)) out.contacts.push_back(c);
  return out;
}

bool moves_hand(const UncertaintyParams& uncertainty) {
  return uncertainty.hand_offset_sigma_m > 0.0 || uncertainty.hand_turn_sigma_rad > 0.0;
}

DrawnPoseCloser::DrawnPoseCloser(const HandModel& hand, const Mesh& mesh)
    : hand_(hand),
      owned_(make_bullet_hand_collider(hand, mesh)),
      collider_(*owned_),
      setup_(prepare_hand(hand, collider_)) {}

DrawnPoseCloser::DrawnPoseCloser(const HandModel& hand, HandObjectCollider& collider,
                                 const HandSetup& setup)
    : hand_(hand), collider_(collider), setup_(setup) {}

Grasp DrawnPoseCloser::close(const Grasp& drawn) {
  const std::lock_guard<std::mutex> lock(mutex_);
  return close_at_drawn_pose(drawn, hand_, setup_, collider_);
}

}  // namespace cordgrasp
