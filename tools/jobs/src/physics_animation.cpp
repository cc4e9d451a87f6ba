#include "cordgrasp/jobs/physics_animation.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/render/animation.h"
#include "cordgrasp/render/text.h"

namespace cordgrasp {
namespace {

// Sample `s` belongs to phase `name` ("shake" covers its segments "shake x" ...).
bool in_phase(const PhaseSnapshot& s, const std::string& name) {
  return s.phase == name || s.phase.rfind(name + " ", 0) == 0;
}

const Rgba kFailRed(0.82, 0.12, 0.10, 1.0);
const Rgba kHeldGreen(0.10, 0.55, 0.20, 1.0);

// Verdict of the whole grasp, e.g. "held through lift, shake" or "slipped in shake (shake y)".
std::string verdict(const SimResult& r) {
  if (r.held()) {
    std::string tests;
    for (const PhaseResult& p : r.phases)
      if (p.name != "settle" && p.name != "close")
        tests += (tests.empty() ? "" : ", ") + p.name;
    return tests.empty() ? "held after closing" : "held through " + tests;
  }
  const PhaseResult* p = r.failed_phase();
  if (!p) return to_string(r.outcome);
  return std::string(to_string(p->outcome)) + " in " + p->name +
         (p->detail.empty() ? std::string() : " (" + p->detail + ")");
}

// Frame border of `width` px in `rgba`.
void draw_border(Image& image, int width, const Rgba& rgba) {
  fill_rect(image, 0, 0, image.width, width, rgba);
  fill_rect(image, 0, image.height - width, image.width, width, rgba);
  fill_rect(image, 0, 0, width, image.height, rgba);
  fill_rect(image, image.width - width, 0, width, image.height, rgba);
}

// Lightens rows [y, y + h) toward white by `amount` in [0, 1], so text over the hand reads.
void lighten_rows(Image& image, int y, int h, double amount) {
  for (int row = std::max(0, y); row < std::min(image.height, y + h); ++row)
    for (int x = 0; x < image.width; ++x) {
      std::uint8_t* p = image.pixel(x, row);
      for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(p[c] + amount * (255 - p[c]));
    }
}

/// A frame is drawn again only when some mesh's bounding box corner would move this far on
/// screen; otherwise the last picture is reused (a held grasp barely moves in the hand's view).
constexpr double kRedrawPx = 0.5;

/// Bounding box corners of every mesh of `scene`, in world, less `shift_W`.
std::vector<Eigen::Vector3d> box_corners(const Scene& scene, const Eigen::Vector3d& shift_W,
                                         std::map<const Mesh*, Eigen::AlignedBox3d>& boxes) {
  std::vector<Eigen::Vector3d> p;
  for (const SceneMesh& m : scene.meshes) {
    if (!m.mesh) continue;
    auto it = boxes.find(m.mesh.get());
    if (it == boxes.end()) {
      const Aabb b = mesh_bounds(*m.mesh);
      it = boxes.emplace(m.mesh.get(), Eigen::AlignedBox3d(b.min, b.max)).first;
    }
    for (int c = 0; c < 8; ++c)
      p.push_back(m.X_WM * it->second.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) -
                  shift_W);
  }
  return p;
}

}  // namespace

std::optional<FailureMoment> failure_moment(const std::vector<PhaseSnapshot>& samples,
                                            const SimResult& result, const SimParams& limits) {
  const PhaseResult* failed = result.failed_phase();
  if (!failed) return std::nullopt;
  std::optional<FailureMoment> last;
  for (size_t i = 0; i < samples.size(); ++i) {
    const PhaseSnapshot& s = samples[i];
    if (!in_phase(s, failed->name)) continue;
    const FailureMoment here{s.phase, s.sim_time_s, i};
    if (s.object_shift_m > limits.held_translation_m ||
        s.object_turn_rad > limits.held_rotation_rad || s.contact_count == 0 ||
        !std::isfinite(s.object_shift_m))
      return here;
    last = here;
  }
  return last;
}

std::string physics_animation(Renderer& renderer, const HandModel& hand,
                              std::shared_ptr<const Mesh> object,
                              const std::vector<PhaseSnapshot>& samples, const SimResult& result,
                              const SimParams& limits, const std::string& title,
                              const VideoParams& video) {
  if (samples.empty()) throw std::invalid_argument("physics animation: no samples");
  const HandMeshes meshes = make_hand_meshes(hand);
  const auto scene_of = [&](const PhaseSnapshot& s) {
    Scene scene;
    if (object) add_object(scene, object, s.X_WO);
    add_hand(scene, meshes, s.X_WL);
    scene.ground = Ground::kNone;
    scene.caption = " ";  // the band is drawn; its text is written below
    return scene;
  };
  // Framing: hand and object at the end of closing (else the first sample), from then on
  // following the hand's base link, so the object's motion in the hand shows.
  size_t anchor = 0;
  for (size_t i = 0; i < samples.size(); ++i)
    if (samples[i].phase == "close") anchor = i;
  RenderParams params;
  params.width_px = video.width_px;
  params.height_px = video.height_px;
  params.supersample = 1;
  params.view.margin = 0.10;
  params.caption_size_px = std::max(11.0, video.height_px / 30.0);
  const Camera base = frame_on_grasp(hand, meshes, object, samples[anchor].X_WO,
                                     samples[anchor].X_WL, params, true);
  const Eigen::Vector3d anchor_p = samples[anchor].X_WL.empty()
                                       ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                       : Eigen::Vector3d(samples[anchor].X_WL.front().translation());

  const std::optional<FailureMoment> failure = failure_moment(samples, result, limits);
  const int text_px = static_cast<int>(params.caption_size_px);
  const int border_px = std::max(3, video.height_px / 80);
  AnimationParams anim;
  anim.frame_rate_hz = video.frame_rate_hz;
  anim.quality = video.quality;
  AnimationEncoder encoder(video.width_px, video.height_px, anim);
  const double frame_s = 1.0 / video.frame_rate_hz;
  double shown_until = -1.0;  // simulated time of the last frame drawn (per world)
  std::map<const Mesh*, Eigen::AlignedBox3d> boxes;
  Image drawn;  // the last picture rendered, without text
  std::vector<Eigen::Vector3d> drawn_corners;  // its meshes' box corners (hand-following)
  RenderInfo info;
  for (size_t i = 0; i < samples.size(); ++i) {
    const PhaseSnapshot& s = samples[i];
    const bool last = i + 1 == samples.size();
    // Phase ends come between the regular samples: keep frames ≥ half a frame apart. A new
    // world (gravity6) starts its clock again.
    if (s.sim_time_s < shown_until) shown_until = -1.0;
    if (!last && shown_until >= 0.0 && s.sim_time_s - shown_until < 0.5 * frame_s) continue;
    double duration = frame_s;
    if (!last) {
      const double gap = samples[i + 1].sim_time_s - s.sim_time_s;
      if (gap > 0.5 * frame_s) duration = gap;
    }
    shown_until = s.sim_time_s;

    RenderParams p = params;
    p.camera = base;
    const Eigen::Vector3d move =
        s.X_WL.empty() ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                       : Eigen::Vector3d(s.X_WL.front().translation() - anchor_p);
    p.camera->eye_W += move;
    p.camera->target_W += move;
    const Scene scene = scene_of(s);
    std::vector<Eigen::Vector3d> corners = box_corners(scene, move, boxes);
    bool redraw = drawn.rgba.empty() || corners.size() != drawn_corners.size();
    for (size_t c = 0; c < corners.size() && !redraw; ++c)
      redraw = (project_to_pixel(base, video.width_px, info.view_height_px, corners[c]) -
                project_to_pixel(base, video.width_px, info.view_height_px, drawn_corners[c]))
                   .norm() > kRedrawPx;
    if (redraw) {
      drawn = renderer.render(scene, p, &info);
      drawn_corners = std::move(corners);
    }
    Image image = drawn;
    const bool failed = failure && i >= failure->sample;
    const Rgba& state = failed ? kFailRed : Rgba(0.15, 0.15, 0.15, 1.0);
    std::string status = s.phase + " · t = " + fixed(s.sim_time_s, 2) + " s · shift " +
                         fixed(1e3 * s.object_shift_m, 1) + " mm · turn " +
                         fixed(s.object_turn_rad * 180.0 / M_PI, 1) + "° · " +
                         std::to_string(s.contact_count) + " contacts";
    const int band_y = info.view_height_px;
    draw_text_centered(image, status, 0, band_y, video.width_px, video.height_px - band_y,
                       text_px, 8, state);
    lighten_rows(image, 0, border_px + 3 * text_px + 12, 0.7);  // title, failure, verdict
    draw_text(image, title, border_px + 6, border_px + text_px + 4, text_px);
    if (failed) draw_border(image, border_px, kFailRed);
    if (failed && !last) {
      draw_text(image,
                std::string(to_string(result.outcome)) + " in " + failure->phase + " at t = " +
                    fixed(failure->sim_time_s, 2) + " s",
                border_px + 6, border_px + 2 * text_px + 10, text_px, kFailRed);
    }
    if (last) {
      encoder.add_frame(image, duration);
      // The verdict, held on screen.
      draw_text_centered(image, verdict(result), 0, border_px + 3 * text_px / 2,
                         video.width_px, 2 * text_px, static_cast<int>(1.5 * text_px), 8,
                         result.held() ? kHeldGreen : kFailRed);
      encoder.add_frame(image, video.final_hold_s);
    } else {
      encoder.add_frame(image, duration);
    }
  }
  return encoder.finish();
}

}  // namespace cordgrasp
