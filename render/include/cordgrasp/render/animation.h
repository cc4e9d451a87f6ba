#pragma once
// Animated WebP files (libwebp's animation encoder and decoder): lossy frames, any browser.
#include <memory>
#include <string>
#include <vector>

#include "cordgrasp/render/image.h"

namespace cordgrasp {

/// Settings of an animation file.
struct AnimationParams {
  double frame_rate_hz = 25.0;  ///< frames per second of add_frame() without a duration
  int quality = 90;             ///< lossy quality, 0 (smallest) … 100 (best); below ~85 the
                                ///< sub-frame blending leaves ghosts of moved parts
  int effort = 2;               ///< encoder effort (libwebp "method"), 0 (fast) … 6 (small)
  int loop_count = 0;           ///< times the animation plays; 0: forever
};

/// Builds an animated WebP frame by frame, keeping only the encoder's state (not the frames).
/// Not thread-safe. Every frame must have the size of the first.
class AnimationEncoder {
 public:
  /// @throws std::invalid_argument for sizes outside [1, 16383] px or bad params.
  AnimationEncoder(int width_px, int height_px, const AnimationParams& params = {});
  ~AnimationEncoder();
  AnimationEncoder(const AnimationEncoder&) = delete;
  AnimationEncoder& operator=(const AnimationEncoder&) = delete;

  /// Appends `image`, shown for `duration_s` (≤ 0: one frame at params.frame_rate_hz).
  /// @throws std::invalid_argument for another size; std::runtime_error when libwebp fails.
  void add_frame(const Image& image, double duration_s = 0.0);

  /// Frames added so far.
  int frame_count() const;

  /// The WebP file's bytes; the encoder takes no frames afterwards.
  /// @throws std::runtime_error with no frames or when libwebp fails.
  std::string finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One decoded frame of an animation.
struct AnimationFrame {
  Image image;            ///< the whole canvas, RGBA
  double timestamp_s = 0.0;  ///< end of this frame's display time since the start [s]
};

/// Frames of an animated (or still) WebP. @throws InputError naming `what` when the bytes are
/// not a WebP libwebp decodes.
std::vector<AnimationFrame> decode_animation(const std::string& bytes,
                                             const std::string& what = "animation");

/// decode_animation of the file at `path`. @throws InputError naming the path.
std::vector<AnimationFrame> read_animation(const std::string& path);

}  // namespace cordgrasp
