#include "cordgrasp/render/animation.h"

#include <webp/decode.h>
#include <webp/demux.h>
#include <webp/encode.h>
#include <webp/mux.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cordgrasp/core/error.h"

namespace cordgrasp {

struct AnimationEncoder::Impl {
  WebPAnimEncoder* encoder = nullptr;
  WebPConfig config;
  AnimationParams params;
  int width = 0, height = 0;
  int frames = 0;
  double time_s = 0.0;  // start of the next frame
  bool finished = false;

  ~Impl() { WebPAnimEncoderDelete(encoder); }

  std::string error(const std::string& what) const {
    const char* e = encoder ? WebPAnimEncoderGetError(encoder) : nullptr;
    return "animation: " + what + (e && *e ? std::string(": ") + e : std::string());
  }
};

namespace {
int to_ms(double t_s) { return static_cast<int>(std::lround(t_s * 1000.0)); }
}  // namespace

AnimationEncoder::AnimationEncoder(int width_px, int height_px, const AnimationParams& params)
    : impl_(std::make_unique<Impl>()) {
  if (width_px < 1 || height_px < 1 || width_px > WEBP_MAX_DIMENSION ||
      height_px > WEBP_MAX_DIMENSION)
    throw std::invalid_argument("animation: size " + std::to_string(width_px) + "x" +
                                std::to_string(height_px) + " px outside [1, 16383]");
  if (!(params.frame_rate_hz > 0.0) || params.quality < 0 || params.quality > 100 ||
      params.effort < 0 || params.effort > 6 || params.loop_count < 0)
    throw std::invalid_argument(
        "animation: frame rate must be > 0, quality in [0, 100], effort in [0, 6], loop "
        "count >= 0");
  Impl& s = *impl_;
  s.params = params;
  s.width = width_px;
  s.height = height_px;
  WebPAnimEncoderOptions options;
  if (!WebPAnimEncoderOptionsInit(&options) || !WebPConfigInit(&s.config))
    throw std::runtime_error("animation: libwebp version mismatch");
  options.anim_params.loop_count = params.loop_count;
  options.anim_params.bgcolor = 0xffffffff;
  s.config.quality = static_cast<float>(params.quality);
  s.config.method = params.effort;
  s.config.lossless = 0;
  s.encoder = WebPAnimEncoderNew(width_px, height_px, &options);
  if (!s.encoder) throw std::runtime_error("animation: libwebp could not create an encoder");
}

AnimationEncoder::~AnimationEncoder() = default;

void AnimationEncoder::add_frame(const Image& image, double duration_s) {
  Impl& s = *impl_;
  if (s.finished) throw std::logic_error("animation: add_frame after finish");
  if (image.width != s.width || image.height != s.height)
    throw std::invalid_argument("animation: frame of " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " px in an animation of " +
                                std::to_string(s.width) + "x" + std::to_string(s.height));
  WebPPicture picture;
  if (!WebPPictureInit(&picture)) throw std::runtime_error("animation: libwebp version mismatch");
  picture.width = s.width;
  picture.height = s.height;
  picture.use_argb = 1;
  if (!WebPPictureImportRGBA(&picture, image.rgba.data(), 4 * s.width)) {
    WebPPictureFree(&picture);
    throw std::runtime_error("animation: libwebp could not import a frame (out of memory)");
  }
  const int ok = WebPAnimEncoderAdd(s.encoder, &picture, to_ms(s.time_s), &s.config);
  WebPPictureFree(&picture);
  if (!ok) throw std::runtime_error(s.error("libwebp could not encode frame " +
                                            std::to_string(s.frames)));
  s.time_s += duration_s > 0.0 ? duration_s : 1.0 / s.params.frame_rate_hz;
  ++s.frames;
}

int AnimationEncoder::frame_count() const { return impl_->frames; }

std::string AnimationEncoder::finish() {
  Impl& s = *impl_;
  if (s.finished) throw std::logic_error("animation: finish called twice");
  if (s.frames == 0) throw std::runtime_error("animation: no frames");
  s.finished = true;
  // A null frame at the end time gives the last frame its duration.
  if (!WebPAnimEncoderAdd(s.encoder, nullptr, to_ms(s.time_s), nullptr))
    throw std::runtime_error(s.error("libwebp could not end the animation"));
  WebPData data;
  WebPDataInit(&data);
  if (!WebPAnimEncoderAssemble(s.encoder, &data))
    throw std::runtime_error(s.error("libwebp could not assemble the animation"));
  std::string bytes(reinterpret_cast<const char*>(data.bytes), data.size);
  WebPDataClear(&data);
  return bytes;
}

std::vector<AnimationFrame> decode_animation(const std::string& bytes, const std::string& what) {
  WebPData data;
  data.bytes = reinterpret_cast<const uint8_t*>(bytes.data());
  data.size = bytes.size();
  WebPAnimDecoderOptions options;
  if (!WebPAnimDecoderOptionsInit(&options))
    throw std::runtime_error("animation: libwebp version mismatch");
  options.color_mode = MODE_RGBA;
  options.use_threads = 0;
  std::unique_ptr<WebPAnimDecoder, void (*)(WebPAnimDecoder*)> decoder(
      WebPAnimDecoderNew(&data, &options), WebPAnimDecoderDelete);
  WebPAnimInfo info;
  if (!decoder || !WebPAnimDecoderGetInfo(decoder.get(), &info))
    throw InputError(what + ": not a WebP image libwebp can decode");
  std::vector<AnimationFrame> frames;
  while (WebPAnimDecoderHasMoreFrames(decoder.get())) {
    uint8_t* rgba = nullptr;
    int timestamp_ms = 0;
    if (!WebPAnimDecoderGetNext(decoder.get(), &rgba, &timestamp_ms))
      throw InputError(what + ": frame " + std::to_string(frames.size()) +
                       " of the WebP image does not decode");
    AnimationFrame f;
    f.image.width = static_cast<int>(info.canvas_width);
    f.image.height = static_cast<int>(info.canvas_height);
    f.image.rgba.assign(rgba, rgba + 4 * static_cast<size_t>(f.image.width) * f.image.height);
    f.timestamp_s = timestamp_ms / 1000.0;
    frames.push_back(std::move(f));
  }
  return frames;
}

std::vector<AnimationFrame> read_animation(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("animation: cannot read '" + path + "'");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return decode_animation(bytes.str(), "animation '" + path + "'");
}

}  // namespace cordgrasp
