#include "cordgrasp/sim/sim_result.h"

#include <algorithm>
#include <stdexcept>

#include "cordgrasp/core/enum_names.h"

namespace cordgrasp {

namespace {
constexpr EnumName<Outcome> kOutcomeNames[] = {{Outcome::kHeld, "held"},
                                               {Outcome::kSlipped, "slipped"},
                                               {Outcome::kDropped, "dropped"},
                                               {Outcome::kUnstable, "unstable"},
                                               {Outcome::kNotRun, "not_run"}};
}  // namespace

const char* to_string(Outcome outcome) { return enum_to_string(outcome, kOutcomeNames); }

Outcome parse_outcome(const std::string& text) {
  return parse_enum(text, kOutcomeNames, "outcome");
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

namespace {

/// Lost in a test after the close (lift, shake or gravity6).
bool lost_after_close(const SimResult& r) {
  const PhaseResult* failed = r.held() ? nullptr : r.failed_phase();
  return failed &&
         (failed->name == "lift" || failed->name == "shake" || failed->name == "gravity6");
}

}  // namespace

bool SimResult::lost_without_pressing() const {
  if (!lost_after_close(*this)) return false;
  const PhaseResult* close = phase("close");
  return close && close->squeeze_effort_ratio < kPressingEffortRatio;
}

bool SimResult::lost_below_weight_margin() const {
  return lost_after_close(*this) && weight_margin && *weight_margin < 1.0;
}

int count_held(const std::vector<Outcome>& outcomes) {
  return static_cast<int>(std::count(outcomes.begin(), outcomes.end(), Outcome::kHeld));
}

}  // namespace cordgrasp
