#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

int find_link(const HandModel& hand, const std::string& name) {
  for (size_t i = 0; i < hand.links.size(); ++i)
    if (hand.links[i].name == name) return static_cast<int>(i);
  return -1;
}

int find_joint(const HandModel& hand, const std::string& name) {
  for (size_t i = 0; i < hand.joints.size(); ++i)
    if (hand.joints[i].name == name) return static_cast<int>(i);
  return -1;
}

int degrees_of_freedom(const HandModel& hand) {
  int dof = 0;
  for (const auto& j : hand.joints) dof += (j.is_moving() && !j.mimic) ? 1 : 0;
  return dof;
}

double total_mass(const HandModel& hand) {
  double m = 0.0;
  for (const auto& l : hand.links) m += l.inertial.mass_kg;
  return m;
}

}  // namespace cordgrasp
