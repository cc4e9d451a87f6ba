#include "cordgrasp/sim/sim_result.h"

#include <algorithm>
#include <stdexcept>

namespace cordgrasp {

const char* to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::kHeld: return "held";
    case Outcome::kSlipped: return "slipped";
    case Outcome::kDropped: return "dropped";
    case Outcome::kUnstable: return "unstable";
    case Outcome::kNotRun: return "not_run";
  }
  return "?";
}

Outcome parse_outcome(const std::string& text) {
  for (Outcome o : {Outcome::kHeld, Outcome::kSlipped, Outcome::kDropped, Outcome::kUnstable,
                    Outcome::kNotRun})
    if (text == to_string(o)) return o;
  throw std::invalid_argument("unknown outcome '" + text +
                              "' (allowed: held, slipped, dropped, unstable, not_run)");
}

const PhaseResult* SimResult::phase(const std::string& name) const {
  for (const PhaseResult& p : phases)
    if (p.name == name) return &p;
  return nullptr;
}

const PhaseResult* SimResult::failed_phase() const {
  for (const PhaseResult& p : phases)
    if (p.outcome != Outcome::kHeld && p.outcome != Outcome::kNotRun) return &p;
  return nullptr;
}

int count_held(const std::vector<Outcome>& outcomes) {
  return static_cast<int>(std::count(outcomes.begin(), outcomes.end(), Outcome::kHeld));
}

}  // namespace cordgrasp
