#pragma once
// An animation of one grasp's physics (close, lift, shake, gravity6) as an animated WebP.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/render/renderer.h"
#include "cordgrasp/sim/sim_params.h"
#include "cordgrasp/sim/sim_result.h"
#include "cordgrasp/sim/validate_grasp.h"

namespace cordgrasp {

/// Size, rate and quality of the physics animations.
struct VideoParams {
  int width_px = 640;            ///< frame width [px]
  int height_px = 480;           ///< frame height [px], caption band included
  double frame_rate_hz = 25.0;   ///< frames per simulated second (played in real time)
  int quality = 90;              ///< lossy WebP quality, 0 … 100
  double final_hold_s = 1.0;     ///< the last frame, with the verdict, stays this long [s]
};

/// When and where a grasp's physics first failed, from its samples.
struct FailureMoment {
  std::string phase;         ///< the phase (or segment, "shake y") of the first failing sample
  double sim_time_s = 0.0;   ///< [s]
  size_t sample = 0;         ///< index into the samples
};

/// The first sample of the phase that decided `result` (its first phase that did not hold) at
/// which the object is off by more than `limits`' held_translation_m or held_rotation_rad, or
/// out of contact; that phase's last sample when no single sample shows it; nothing for a held
/// grasp or without samples of that phase.
std::optional<FailureMoment> failure_moment(const std::vector<PhaseSnapshot>& samples,
                                            const SimResult& result, const SimParams& limits);

/// Frames of a grasp's physics from its phase-hook samples (SimParams::trace_interval_s =
/// 1 / frame_rate_hz, phase ends included), played in simulated time. The camera follows the
/// hand's base link, framed on hand and object at the end of closing; each frame says the
/// phase, time, object shift and contacts; from the failure moment on, a red border and the
/// failure; the last frame holds the verdict. Returns the WebP file's bytes.
/// @throws std::invalid_argument without samples; as Renderer::render.
std::string physics_animation(Renderer& renderer, const HandModel& hand,
                              std::shared_ptr<const Mesh> object,
                              const std::vector<PhaseSnapshot>& samples, const SimResult& result,
                              const SimParams& limits, const std::string& title,
                              const VideoParams& video = {});

}  // namespace cordgrasp
