#include "cordgrasp/core/candidate_measures.h"

#include <algorithm>

namespace cordgrasp {

CandidateMeasures candidate_measures(const std::vector<Contact>& contacts,
                                     const HandSetup& setup, const Eigen::Vector3d& com_O,
                                     double radius_m) {
  CandidateMeasures m;
  if (contacts.empty()) return m;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Contact& c : contacts) mean += c.p_O;
  mean /= static_cast<double>(contacts.size());
  m.com_offset = radius_m > 0.0 ? (mean - com_O).norm() / radius_m : 0.0;

  Eigen::Vector3d net = Eigen::Vector3d::Zero();
  for (const std::vector<int>& links : setup.actor_links) {
    Eigen::Vector3d push = Eigen::Vector3d::Zero();
    for (const Contact& c : contacts)
      if (std::find(links.begin(), links.end(), c.link) != links.end()) push -= c.n_O;
    if (push.norm() <= 1e-12) continue;
    ++m.fingers_in_contact;
    net += push.normalized();
  }
  // A static link (the palm) pushes back on whatever presses the object onto it.
  for (const Contact& c : contacts) {
    if (std::find(setup.static_links.begin(), setup.static_links.end(), c.link) ==
        setup.static_links.end())
      continue;
    m.palm_contact = true;
    const double onto = net.dot(c.n_O);  // n_O points from the object toward the link
    if (onto > 0.0) net -= onto * c.n_O;
  }
  if (m.fingers_in_contact > 0) m.push_imbalance = net.norm() / m.fingers_in_contact;
  return m;
}

}  // namespace cordgrasp
