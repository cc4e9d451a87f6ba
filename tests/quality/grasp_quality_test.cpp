// Grasp wrench space (docs/algorithm.md §8): force closure and ε.
#include "cordgrasp/core/grasp_quality.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "cordgrasp/core/shapes.h"
#include "test_contacts.h"

namespace cordgrasp {
namespace {

constexpr double kAnalyticTol = 1e-6;
constexpr double kExactTol = 1e-9;

WrenchSpaceObject unit_object(double torque_scale = 1.0) {
  WrenchSpaceObject o;
  o.center_O = Eigen::Vector3d::Zero();
  o.torque_scale_per_m = torque_scale;
  return o;
}

QualityParams textbook(double mu) {
  QualityParams p;
  p.contact.mu = mu;
  return p;
}

// Two pads pressing on opposite faces of a 10 cm box, each touching along two points (the pad's
// edges): the 4 contacts are not collinear, so friction also resists torsion about x.
std::vector<Contact> opposite_pad_contacts() {
  return {contact({0.05, 0.0, 0.01}, Eigen::Vector3d::UnitX()),
          contact({0.05, 0.0, -0.01}, Eigen::Vector3d::UnitX()),
          contact({-0.05, 0.0, 0.01}, -Eigen::Vector3d::UnitX()),
          contact({-0.05, 0.0, -0.01}, -Eigen::Vector3d::UnitX())};
}

TEST(GraspQuality, OppositeContactsOnBoxAreForceClosureWithFriction) {
  const WrenchSpaceObject box = prepare_wrench_space(make_box_mesh({0.1, 0.1, 0.1}), {});
  const GraspQuality q = evaluate_grasp_quality(opposite_pad_contacts(), box, textbook(0.5));
  EXPECT_TRUE(q.force_closure);
  EXPECT_GT(q.epsilon, 0.0);
}

TEST(GraspQuality, OppositeContactsOnBoxAreNotForceClosureWithoutFriction) {
  const WrenchSpaceObject box = prepare_wrench_space(make_box_mesh({0.1, 0.1, 0.1}), {});
  const GraspQuality q = evaluate_grasp_quality(opposite_pad_contacts(), box, textbook(0.0));
  EXPECT_FALSE(q.force_closure);
  EXPECT_EQ(q.epsilon, 0.0);
}

// The linear program that screens wrench sets before the hull (docs/finger-stage-and-quality.md)
// changes no verdict and no ε: random contact sets on a sphere, from clearly not FC to clearly
// FC, judged by evaluate_grasp_quality and by the hull of the same cone edges alone.
TEST(GraspQuality, TextbookVerdictsAndEpsilonAreThoseOfTheHullAlone) {
  constexpr int kSets = 200;
  constexpr double kRadius_m = 0.05;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_direction = [&] {
    Eigen::Vector3d d;
    do d = Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    while (d.norm() < 0.1 || d.norm() > 1.0);
    return d.normalized();
  };
  const WrenchSpaceObject object = unit_object(1.0 / kRadius_m);
  int fc = 0, not_fc = 0;
  testing::internal::CaptureStdout();  // the linear program's solver must print nothing
  for (int k = 0; k < kSets; ++k) {
    QualityParams params = textbook(std::uniform_real_distribution<double>(0.05, 1.0)(rng));
    if (k % 2 == 1) params.contact.soft_finger_radius_m = 0.005;
    const int n = std::uniform_int_distribution<int>(2, 5)(rng);
    // Contacts on one cap of the sphere (spread < 1: often not FC) or all around it.
    const double spread = std::uniform_real_distribution<double>(0.2, 2.0)(rng);
    const Eigen::Vector3d pole = random_direction();
    std::vector<Contact> contacts;
    for (int c = 0; c < n; ++c) {
      const Eigen::Vector3d d = (pole + spread * random_direction()).normalized();
      contacts.push_back(contact(kRadius_m * d, d));
    }
    const GraspQuality q = evaluate_grasp_quality(contacts, object, params);
    std::vector<Wrench> w;
    for (const Contact& c : contacts) {
      const auto cw = contact_wrenches(c.p_O, c.n_O, params.contact.mu, params.contact.cone_edges,
                                       object.center_O, object.torque_scale_per_m,
                                       params.contact.soft_finger_radius_m);
      w.insert(w.end(), cw.begin(), cw.end());
    }
    const WrenchHull hull = wrench_hull(w);
    const bool hull_fc = hull.valid && hull.min_origin_distance > params.min_epsilon;
    EXPECT_EQ(q.force_closure, hull_fc) << "set " << k;
    EXPECT_EQ(q.epsilon, hull_fc ? hull.min_origin_distance : 0.0) << "set " << k;
    (hull_fc ? fc : not_fc) += 1;
  }
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  // Both kinds occur often enough for the comparison to mean something.
  EXPECT_GT(fc, kSets / 10);
  EXPECT_GT(not_fc, kSets / 10);
}

// With point contacts, two contacts are never force closure in 6D, whatever μ: no contact force
// has a moment about the line through both points, so every wrench has zero component along it.
TEST(GraspQuality, TwoPointContactsAreNeverForceClosure) {
  const WrenchSpaceObject box = prepare_wrench_space(make_box_mesh({0.1, 0.1, 0.1}), {});
  const std::vector<Contact> two = {contact({0.05, 0.0, 0.0}, Eigen::Vector3d::UnitX()),
                                    contact({-0.05, 0.0, 0.0}, -Eigen::Vector3d::UnitX())};
  for (double mu : {0.0, 0.5, 2.0}) {
    const GraspQuality q = evaluate_grasp_quality(two, box, textbook(mu));
    EXPECT_FALSE(q.force_closure) << "mu " << mu;
    EXPECT_FALSE(q.hull.valid) << "mu " << mu;
  }
}

// Two soft fingers pinching opposite faces: torsional friction resists the moment about the
// line through the contacts, so the pinch is force closure with friction and not without.
TEST(GraspQuality, TwoOppositeSoftFingerContactsAreForceClosureOnlyWithFriction) {
  const WrenchSpaceObject box = prepare_wrench_space(make_box_mesh({0.1, 0.1, 0.1}), {});
  const std::vector<Contact> two = {contact({0.05, 0.0, 0.0}, Eigen::Vector3d::UnitX()),
                                    contact({-0.05, 0.0, 0.0}, -Eigen::Vector3d::UnitX())};
  QualityParams soft = textbook(0.5);
  soft.contact.soft_finger_radius_m = 0.005;
  const GraspQuality with_friction = evaluate_grasp_quality(two, box, soft);
  EXPECT_TRUE(with_friction.force_closure);
  EXPECT_GT(with_friction.epsilon, 0.0);
  soft.contact.mu = 0.0;
  EXPECT_FALSE(evaluate_grasp_quality(two, box, soft).force_closure);
}

TEST(GraspQuality, FewerThanTwoContactsAreNotForceClosure) {
  const std::vector<Contact> one = {contact({1, 0, 0}, Eigen::Vector3d::UnitX())};
  EXPECT_FALSE(evaluate_grasp_quality(one, unit_object(), textbook(0.5)).force_closure);
  EXPECT_FALSE(evaluate_grasp_quality({}, unit_object(), textbook(0.5)).force_closure);
}

TEST(GraspQuality, PrepareUsesVertexMeanAndLongestBoxSide) {
  Mesh box = make_box_mesh({0.1, 0.3, 0.2});
  for (auto& v : box.vertices) v += Eigen::Vector3d(1.0, 2.0, 3.0);
  const WrenchSpaceObject o = prepare_wrench_space(box, {});
  EXPECT_NEAR(o.torque_scale_per_m, 2.0 / 0.3, kExactTol);
  EXPECT_TRUE(o.center_O.isApprox(Eigen::Vector3d(1.0, 2.0, 3.0), kExactTol));
}

TEST(ContactWrenches, EdgesAreUnitForcesInsideTheConeWithScaledTorque) {
  const Eigen::Vector3d p(0.1, 0.2, 0.3), n = Eigen::Vector3d(1, 2, 2).normalized();
  const double mu = 0.5, lambda = 4.0;
  const auto w = contact_wrenches(p, n, mu, 8, Eigen::Vector3d::Zero(), lambda);
  ASSERT_EQ(w.size(), 8u);
  for (const Wrench& x : w) {
    const Eigen::Vector3d f = x.head<3>();
    EXPECT_NEAR(f.norm(), 1.0, kExactTol);
    EXPECT_NEAR(-f.dot(n), 1.0 / std::sqrt(1.0 + mu * mu), kExactTol);  // half-angle atan μ
    EXPECT_TRUE(x.tail<3>().isApprox(lambda * p.cross(f), kExactTol));
  }
}

// Three contacts 120° apart on the equator of a sphere, pushing towards its centre.
//
// Derivation of ε. Take λR = 1 (R = 1 m, λ = 1/m) and normals n_k = (cos θ_k, sin θ_k, 0).
// The implementation's tangent t1 is the coordinate axis least aligned with n: z for every
// contact here (θ_k = 10° + 120° k avoids the tie of θ = 0; rotating the whole grasp about z is
// an isometry of wrench space, so ε is that of θ_k = 120° k). With t2 = n × z, s = 1/√(1+μ²) and
// a = μ s, the edge forces are f_kj = −s n_k + a (cos φ_j z + sin φ_j t2_k), φ_j = 45° j, and
// torques n_k × f_kj, so
//     w_kj = s N_k + a√2 (cos φ_j U_k + sin φ_j V_k),
//     N_k = (−n_k; 0),  U_k = (z; t2_k)/√2,  V_k = (t2_k; −z)/√2,
// with N_k, U_k, V_k orthonormal. The nearest facet {w : u·w = ε} (|u| = 1) holds the whole
// cone of contact B (θ = 120°), edges j = 0, 1 of contact A (θ = 0°) and edge j = 4 of contact C
// (θ = 240°); these eleven wrenches give six independent linear conditions on (u, ε):
//     u·U_B = 0,  u·V_B = 0,  s u·N_B = ε,
//     u·V_A = (√2 − 1) u·U_A   (edges 0 and 1 equally far),  s u·N_A + a√2 u·U_A = ε,
//     s u·N_C − a√2 u·U_C = ε.
// Solving for u/ε and normalising (done symbolically) gives, for μ = 1/2,
//     ε = 94√3 / √(1114725 + 14560√3 − 85120√2 − 238560√6) = 0.24679496192653...
// The brute-force facet enumeration below confirms that no other facet is nearer.
double analytic_sphere_epsilon_mu_half() {
  const double r2 = std::sqrt(2.0), r3 = std::sqrt(3.0), r6 = std::sqrt(6.0);
  return 94.0 * r3 / std::sqrt(1114725.0 + 14560.0 * r3 - 85120.0 * r2 - 238560.0 * r6);
}

std::vector<Contact> sphere_equator_contacts(double radius) {
  std::vector<Contact> out;
  for (int k = 0; k < 3; ++k) {
    const double th = M_PI / 18.0 + 2.0 * M_PI * k / 3.0;
    const Eigen::Vector3d n(std::cos(th), std::sin(th), 0.0);
    out.push_back(contact(radius * n, n));
  }
  return out;
}

// Independent oracle: every 6-subset of the wrenches spanning a hyperplane with all wrenches on
// one side is a facet; ε is the smallest origin distance among them.
double brute_force_epsilon(const std::vector<Wrench>& w) {
  const int n = static_cast<int>(w.size());
  double best = std::numeric_limits<double>::infinity();
  int idx[6];
  std::function<void(int, int)> rec = [&](int start, int depth) {
    if (depth == 6) {
      Eigen::Matrix<double, 5, 6> D;  // rows w_i − w_0 span the hyperplane; normal in kernel
      for (int i = 1; i < 6; ++i) D.row(i - 1) = (w[idx[i]] - w[idx[0]]).transpose();
      Eigen::FullPivLU<Eigen::Matrix<double, 5, 6>> lu(D);
      if (lu.rank() < 5) return;
      Eigen::Matrix<double, 6, 1> u = lu.kernel().col(0).normalized();
      double b = u.dot(w[idx[0]]);
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const Wrench& x : w) {
        lo = std::min(lo, u.dot(x) - b);
        hi = std::max(hi, u.dot(x) - b);
      }
      constexpr double kSide = 1e-10;
      if (lo < -kSide && hi > kSide) return;  // not supporting
      if (hi > kSide) b = -b;                 // orient: all points on the origin's side
      best = std::min(best, std::abs(b));
      return;
    }
    for (int i = start; i < n; ++i) {
      idx[depth] = i;
      rec(i + 1, depth + 1);
    }
  };
  rec(0, 0);
  return best;
}

TEST(GraspQuality, ThreeSymmetricSphereContactsMatchAnalyticEpsilon) {
  const double radius = 1.0;
  const auto contacts = sphere_equator_contacts(radius);
  const WrenchSpaceObject sphere = unit_object(1.0 / radius);
  const GraspQuality q = evaluate_grasp_quality(contacts, sphere, textbook(0.5));
  ASSERT_TRUE(q.force_closure);
  EXPECT_NEAR(q.epsilon, analytic_sphere_epsilon_mu_half(), kAnalyticTol);

  std::vector<Wrench> w;
  for (const Contact& c : contacts) {
    const auto cw = contact_wrenches(c.p_O, c.n_O, 0.5, 8, sphere.center_O, 1.0 / radius);
    w.insert(w.end(), cw.begin(), cw.end());
  }
  EXPECT_NEAR(brute_force_epsilon(w), analytic_sphere_epsilon_mu_half(), 1e-9);
}

TEST(GraspQuality, EpsilonIsScaleInvariantWithCharacteristicLength) {
  // Same grasp on a sphere 10× smaller: λ = 1/R keeps the wrench set identical.
  const double radius = 0.1;
  const GraspQuality q = evaluate_grasp_quality(sphere_equator_contacts(radius),
                                                unit_object(1.0 / radius), textbook(0.5));
  EXPECT_NEAR(q.epsilon, analytic_sphere_epsilon_mu_half(), kAnalyticTol);
}

TEST(GraspQuality, SimoxModeIgnoresMuAndUsesFortyFiveDegreeCones) {
  const WrenchSpaceObject box = prepare_wrench_space(make_box_mesh({0.1, 0.1, 0.1}), [] {
    QualityParams p;
    p.mode = QualityMode::kSimox;
    return p;
  }());
  ASSERT_GT(box.ows_min_offset, 0.0);
  QualityParams simox;
  simox.mode = QualityMode::kSimox;
  simox.contact.mu = 0.0;
  const GraspQuality a = evaluate_grasp_quality(opposite_pad_contacts(), box, simox);
  simox.contact.mu = 0.9;
  const GraspQuality b = evaluate_grasp_quality(opposite_pad_contacts(), box, simox);
  EXPECT_TRUE(a.force_closure);  // μ = 0 is FC in simox mode: μ_eff = 1
  EXPECT_EQ(a.epsilon, b.epsilon);
  // Textbook mode with μ = 1 has the same cones, hence the same hull.
  const GraspQuality t = evaluate_grasp_quality(opposite_pad_contacts(), box, textbook(1.0));
  EXPECT_NEAR(a.hull.min_centroid_distance, t.hull.min_centroid_distance, kExactTol);
  EXPECT_NEAR(a.epsilon, a.hull.min_centroid_distance / box.ows_min_offset, kExactTol);
}

TEST(GraspQuality, SimoxOwsIsDeterministicForASeed) {
  QualityParams p;
  p.mode = QualityMode::kSimox;
  p.simox_ows_faces = 30;  // fewer than the faces: the seeded sampling matters
  const Mesh sphere = make_sphere_mesh(0.05, 6, 8);
  ASSERT_GT(sphere.triangles.size(), 30u);
  const double a = prepare_wrench_space(sphere, p).ows_min_offset;
  const double b = prepare_wrench_space(sphere, p).ows_min_offset;
  EXPECT_EQ(a, b);
  EXPECT_GT(a, 0.0);
  p.seed = 2;
  EXPECT_NE(prepare_wrench_space(sphere, p).ows_min_offset, a);
}

// The verdict and ε of evaluate_grasp_quality are those of the raw wrench hull (origin deeper
// than min_epsilon), on random grasps of both outcomes.
TEST(GraspQuality, VerdictAndEpsilonAreThoseOfTheWrenchHullOnRandomGrasps) {
  std::mt19937_64 rng(17);
  std::normal_distribution<double> gauss;
  const WrenchSpaceObject object = unit_object(2.0 / 0.1);
  int fc = 0, total = 0;
  for (int trial = 0; trial < 160; ++trial) {
    std::vector<Contact> contacts;
    const int k = 2 + trial % 4;
    for (int i = 0; i < k; ++i) {
      const Eigen::Vector3d dir = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
      const Eigen::Vector3d noise(gauss(rng), gauss(rng), gauss(rng));
      contacts.push_back(contact(0.05 * dir, dir + 0.4 * noise));
    }
    std::vector<Wrench> w;
    for (const Contact& c : contacts) {
      const auto cw =
          contact_wrenches(c.p_O, c.n_O, 0.5, 8, object.center_O, object.torque_scale_per_m);
      w.insert(w.end(), cw.begin(), cw.end());
    }
    const WrenchHull hull = wrench_hull(w);
    const bool hull_fc = hull.valid && hull.min_origin_distance > QualityParams{}.min_epsilon;
    const GraspQuality q = evaluate_grasp_quality(contacts, object, textbook(0.5));
    EXPECT_EQ(q.force_closure, hull_fc) << "trial " << trial;
    if (hull_fc) {
      EXPECT_NEAR(q.epsilon, hull.min_origin_distance, kExactTol);
    }
    fc += hull_fc;
    ++total;
  }
  EXPECT_GT(fc, 10);  // both outcomes are exercised
  EXPECT_LT(fc, total - 10);
}

TEST(QualityMode, ParsesBothNamesAndRejectsOthers) {
  EXPECT_EQ(parse_quality_mode("textbook"), QualityMode::kTextbook);
  EXPECT_EQ(parse_quality_mode("simox"), QualityMode::kSimox);
  EXPECT_STREQ(to_string(QualityMode::kSimox), "simox");
  EXPECT_THROW(parse_quality_mode("ferrari"), std::invalid_argument);
}

}  // namespace
}  // namespace cordgrasp
