#pragma once
// P(held) of a grasp under uncertainty (grasp_uncertainty.h): trials drawn one at a time until
// the Wilson interval lies on one side of the acceptance threshold (docs/physics.md §3b).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/serialize.h"
#include "cordgrasp/core/wilson_interval.h"
#include "cordgrasp/sim/grasp_uncertainty.h"
#include "cordgrasp/sim/sim_result.h"
#include "cordgrasp/sim/validate_grasp.h"

namespace cordgrasp {

/// The sequential test of P(held).
struct HoldProbabilityParams {
  double min_hold_probability = 0.8;  ///< acceptance threshold on P(held) [-]
  int max_draws = 20;                 ///< draws per grasp at most (CLI --trials)
  int min_draws = 5;                  ///< the test's first look (sooner where its verdict is sure)
  std::uint64_t seed = 1;             ///< seed of the draws (draw_uncertainty)

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(min_hold_probability), CORDGRASP_NVP(max_draws),
                 CORDGRASP_NVP(min_draws), CORDGRASP_NVP(seed));
  }
};

/// Checks threshold in (0, 1), 1 ≤ min_draws ≤ max_draws ≤ 1000.
/// @throws std::invalid_argument naming the field.
void check_hold_probability_params(const HoldProbabilityParams& params);

/// Checks a P(held) test whole: its uncertainty model (check_uncertainty_params) and its
/// sequential test (check_hold_probability_params).
/// @throws std::invalid_argument naming the field.
void check_hold_test(const UncertaintyParams& uncertainty, const HoldProbabilityParams& params);

/// The sequential test at `min_hold_probability`, with at most `max_draws` draws from `seed`
/// (min_draws lowered to max_draws when fewer draws are allowed than its default).
HoldProbabilityParams hold_test_params(double min_hold_probability, int max_draws,
                                       std::uint64_t seed);

/// The test that confirms an accepted grasp: `test` with a seed of its own (other draws).
HoldProbabilityParams confirmation_test(const HoldProbabilityParams& test);

/// Where the 95 % interval lies against the threshold.
enum class HoldVerdict {
  kUndecided,  ///< the interval contains the threshold
  kAbove,      ///< low > threshold: the grasp holds often enough
  kBelow,      ///< high < threshold: it does not
};

/// "undecided", "above", "below".
const char* to_string(HoldVerdict verdict);

/// The verdict of `interval` against `threshold`.
HoldVerdict hold_verdict(const ProportionInterval& interval, double threshold);

/// Whether the sequential test stops after `held` of `draws`: at max_draws, or from min_draws
/// on once the Wilson 95 % interval is decided; before min_draws, once it is decided and the
/// draws left to min_draws cannot change that verdict (the test then ends as it would at
/// min_draws, with fewer draws: e.g. 1 held of 4 at threshold 0.8, where a fifth draw leaves
/// at most 2 of 5, below).
bool stop_drawing(int held, int draws, const HoldProbabilityParams& params);

/// One uncertain trial and how it ended.
struct UncertainDrawResult {
  int trial = 0;         ///< draw index (draw_uncertainty's `trial`)
  UncertaintyDraw draw;  ///< its conditions
  Outcome outcome = Outcome::kNotRun;
  std::string failed_phase;  ///< first phase not held ("" when held)
  double wall_time_s = 0.0;
  double cpu_s = 0.0;  ///< CPU time of its simulation (the thread that ran it) [s]
};

/// For one factor: its mean standardized draw in failed and in held trials, and their
/// difference over its standard deviation in all draws (an effect size; sign: failed − held).
struct FactorSensitivity {
  UncertaintyFactor factor = UncertaintyFactor::kHandOffset;
  double mean_failed = 0.0;
  double mean_held = 0.0;
  double effect = 0.0;
};

/// Which factors the failed draws share. Factors whose spread is 0 are left out.
struct FailureSensitivity {
  std::vector<FactorSensitivity> factors;
  /// The factor with the largest |effect|; unset unless some draws held and some failed.
  std::optional<UncertaintyFactor> most_associated;
};

/// The sensitivity of `draws` (FailureSensitivity); empty factors unless some held and some
/// failed.
FailureSensitivity failure_sensitivity(const std::vector<UncertainDrawResult>& draws,
                                       const UncertaintyParams& uncertainty);

/// P(held) of one grasp with its interval and the draws behind it.
struct HoldProbability {
  std::vector<UncertainDrawResult> draws;
  int held = 0;
  ProportionInterval interval;  ///< Wilson 95 % of held / draws
  double threshold = 0.8;
  HoldVerdict verdict = HoldVerdict::kUndecided;
  FailureSensitivity sensitivity;
  double cpu_s = 0.0;  ///< CPU time of every draw simulated, discarded ones included [s]
  bool complete = true;  ///< false when `cancel` stopped it before the test did
  int simulations = 0;   ///< draws simulated (a batch may run past the stop: jobs > 1)
  double wall_time_s = 0.0;
};

/// Simulates `grasp` (index `grasp_index` in its plan) under draws 0, 1, ... of `uncertainty`
/// (apply_uncertainty on `sim`, then validate_grasp with `tests`) until stop_drawing says so.
/// Deterministic: the draws depend on (params.seed, grasp_index, draw) alone; `jobs` draws
/// are simulated at once and those past the stop discarded, so the result does not depend on
/// it. `cancel` is checked before each batch. Where the model moves the hand (moves_hand),
/// each draw's fingers close again at the drawn pose with `closer`, or with one built for
/// this call when it is null.
/// @throws std::invalid_argument for bad params (check_*).
HoldProbability estimate_hold_probability(const Mesh& mesh, const HandModel& hand,
                                          const Grasp& grasp, int grasp_index, const SimParams& sim,
                                          const SimTests& tests,
                                          const UncertaintyParams& uncertainty,
                                          const HoldProbabilityParams& params,
                                          const CancelToken& cancel = {}, int jobs = 1,
                                          DrawnPoseCloser* closer = nullptr);

/// "0.85 [0.64, 0.95]": P(held) and its Wilson 95 % interval.
std::string hold_probability_text(const HoldProbability& h);

/// "P(held) 0.85 [0.64, 0.95] in 20 draws, above 0.80; failures go with low friction"
std::string hold_probability_line(const HoldProbability& h);

}  // namespace cordgrasp
