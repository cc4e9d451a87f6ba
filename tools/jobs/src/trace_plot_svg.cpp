#include "cordgrasp/jobs/trace_plot_svg.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cordgrasp/jobs/text_format.h"
#include "html_text.h"
#include "svg_axis.h"

namespace cordgrasp {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kLeft_px = 56, kRight_px = 56, kTop_px = 22, kBottom_px = 34;
constexpr const char* kShiftColor = "#1f6fb4";
constexpr const char* kTurnColor = "#d95f02";

/// The phase a sample belongs to: "shake x" (a segment's end) belongs to "shake".
std::string phase_of(const TraceSample& s) { return s.phase.substr(0, s.phase.find(' ')); }

/// A run of samples of one phase: indices [begin, end) and the time span it shades.
struct PhaseSpan {
  std::string name;
  size_t begin = 0, end = 0;
  double t0_s = 0.0, t1_s = 0.0;
};

std::vector<PhaseSpan> phase_spans(const std::vector<TraceSample>& trace) {
  std::vector<PhaseSpan> spans;
  for (size_t i = 0; i < trace.size(); ++i) {
    const std::string name = phase_of(trace[i]);
    if (spans.empty() || spans.back().name != name) {
      PhaseSpan span;
      span.name = name;
      span.begin = i;
      span.t0_s = spans.empty() ? trace[i].sim_time_s : spans.back().t1_s;
      spans.push_back(span);
    }
    spans.back().end = i + 1;
    spans.back().t1_s = trace[i].sim_time_s;
  }
  return spans;
}

}  // namespace

std::string trace_plot_svg(const std::vector<TraceSample>& trace, const SimResult* result,
                           const TracePlotParams& params) {
  if (trace.empty()) return "";
  const double w = params.width_px, h = params.height_px;
  const double plot_w = w - kLeft_px - kRight_px, plot_h = h - kTop_px - kBottom_px;
  double t0 = trace.front().sim_time_s, t1 = t0, max_shift_mm = 0.0, max_turn_deg = 0.0;
  for (const TraceSample& s : trace) {
    t0 = std::min(t0, s.sim_time_s);
    t1 = std::max(t1, s.sim_time_s);
    if (std::isfinite(s.object_shift_m))
      max_shift_mm = std::max(max_shift_mm, 1e3 * s.object_shift_m);
    if (std::isfinite(s.object_turn_rad))
      max_turn_deg = std::max(max_turn_deg, s.object_turn_rad * 180.0 / kPi);
  }
  if (!(t1 > t0)) t1 = t0 + 1.0;
  const Axis shift(max_shift_mm), turn(max_turn_deg);
  const auto x = [&](double t) { return kLeft_px + plot_w * (t - t0) / (t1 - t0); };
  const auto y = [&](double v, const Axis& a) {
    return kTop_px + plot_h * (1.0 - std::clamp(v / a.top, 0.0, 1.0));
  };
  const auto px = [](double v) { return format_number(v, "%.1f"); };

  std::ostringstream svg;
  svg << "<svg class=\"trace\" width=\"" << w << "\" height=\"" << h << "\" viewBox=\"0 0 " << w
      << " " << h << "\" role=\"img\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<title>Object shift [mm] and turn [°] in the hand against simulated time [s]</title>\n";
  // Phases: shaded bands, named at the top.
  const std::vector<PhaseSpan> spans = phase_spans(trace);
  for (size_t i = 0; i < spans.size(); ++i) {
    const PhaseSpan& p = spans[i];
    const double xa = x(p.t0_s), xb = x(p.t1_s);
    svg << "<rect class=\"phase\" x=\"" << px(xa) << "\" y=\"" << kTop_px << "\" width=\""
        << px(std::max(0.0, xb - xa)) << "\" height=\"" << px(plot_h) << "\" fill=\""
        << (i % 2 ? "#e6e6e6" : "#f3f3f3") << "\"/>\n";
    if (xb - xa >= 6.0 * static_cast<double>(p.name.size()))
      svg << "<text x=\"" << px(0.5 * (xa + xb)) << "\" y=\"" << kTop_px - 6
          << "\" text-anchor=\"middle\" fill=\"#444\">" << html_escaped(p.name) << "</text>\n";
  }
  // Axes, ticks and grid.
  svg << "<g stroke=\"#999\" stroke-width=\"1\" fill=\"none\"><rect x=\"" << kLeft_px << "\" y=\""
      << kTop_px << "\" width=\"" << px(plot_w) << "\" height=\"" << px(plot_h) << "\"/></g>\n";
  for (double v = 0.0; v <= shift.top * (1.0 + 1e-9); v += shift.step)
    svg << "<line x1=\"" << kLeft_px - 4 << "\" x2=\"" << kLeft_px << "\" y1=\"" << px(y(v, shift))
        << "\" y2=\"" << px(y(v, shift)) << "\" stroke=\"" << kShiftColor << "\"/><text x=\""
        << kLeft_px - 6 << "\" y=\"" << px(y(v, shift) + 4) << "\" text-anchor=\"end\" fill=\""
        << kShiftColor << "\">" << format_number(v) << "</text>\n";
  for (double v = 0.0; v <= turn.top * (1.0 + 1e-9); v += turn.step)
    svg << "<line x1=\"" << px(w - kRight_px) << "\" x2=\"" << px(w - kRight_px + 4) << "\" y1=\""
        << px(y(v, turn)) << "\" y2=\"" << px(y(v, turn)) << "\" stroke=\"" << kTurnColor
        << "\"/><text x=\"" << px(w - kRight_px + 6) << "\" y=\"" << px(y(v, turn) + 4)
        << "\" fill=\"" << kTurnColor << "\">" << format_number(v) << "</text>\n";
  const double t_step = Axis(t1 - t0).step;  // round times: multiples of the step
  for (double v = t_step * std::ceil(t0 / t_step - 1e-9); v <= t1 + 1e-9 * t_step; v += t_step)
    svg << "<line x1=\"" << px(x(v)) << "\" x2=\"" << px(x(v)) << "\" y1=\"" << px(kTop_px + plot_h)
        << "\" y2=\"" << px(kTop_px + plot_h + 4) << "\" stroke=\"#999\"/><text x=\"" << px(x(v))
        << "\" y=\"" << px(h - kBottom_px + 15) << "\" text-anchor=\"middle\" fill=\"#444\">"
        << format_number(std::abs(v) < 1e-9 * t_step ? 0.0 : v) << "</text>\n";
  svg << "<text x=\"" << px(kLeft_px + 0.5 * plot_w) << "\" y=\"" << px(h - 4)
      << "\" text-anchor=\"middle\" fill=\"#444\">simulated time [s]</text>\n"
      << "<text transform=\"translate(14 " << px(kTop_px + 0.5 * plot_h)
      << ") rotate(-90)\" text-anchor=\"middle\" fill=\"" << kShiftColor << "\">shift [mm]</text>\n"
      << "<text transform=\"translate(" << px(w - 10) << " " << px(kTop_px + 0.5 * plot_h)
      << ") rotate(-90)\" text-anchor=\"middle\" fill=\"" << kTurnColor << "\">turn [°]</text>\n";
  // The curves, one polyline per phase: the reference pose changes between phases.
  for (const PhaseSpan& p : spans) {
    std::ostringstream shift_pts, turn_pts;
    for (size_t i = p.begin; i < p.end; ++i) {
      const TraceSample& s = trace[i];
      shift_pts << px(x(s.sim_time_s)) << "," << px(y(1e3 * s.object_shift_m, shift)) << " ";
      turn_pts << px(x(s.sim_time_s)) << "," << px(y(s.object_turn_rad * 180.0 / kPi, turn)) << " ";
    }
    svg << "<polyline class=\"shift\" fill=\"none\" stroke=\"" << kShiftColor
        << "\" stroke-width=\"1.5\" points=\"" << shift_pts.str() << "\"/>\n"
        << "<polyline class=\"turn\" fill=\"none\" stroke=\"" << kTurnColor
        << "\" stroke-width=\"1.5\" points=\"" << turn_pts.str() << "\"/>\n";
  }
  // The failure: the end of the phase that did not hold.
  const PhaseResult* failed = result && !result->held() ? result->failed_phase() : nullptr;
  for (auto it = spans.rbegin(); failed && it != spans.rend(); ++it) {
    if (it->name != failed->name) continue;
    const double xf = x(it->t1_s);
    const bool left = xf < kLeft_px + 0.4 * plot_w;  // caption to the right of the line
    const std::string caption = std::string(to_string(failed->outcome)) + " in " + failed->name +
                                (failed->detail.empty() ? "" : " (" + failed->detail + ")");
    svg << "<line class=\"failure\" x1=\"" << px(xf) << "\" x2=\"" << px(xf) << "\" y1=\""
        << kTop_px << "\" y2=\"" << px(kTop_px + plot_h)
        << "\" stroke=\"#c00\" stroke-width=\"2\" stroke-dasharray=\"5 3\"/>\n"
        << "<text x=\"" << px(left ? xf + 4 : xf - 4) << "\" y=\"" << kTop_px + 14
        << "\" text-anchor=\"" << (left ? "start" : "end")
        << "\" fill=\"#c00\" font-weight=\"bold\">" << html_escaped(caption) << "</text>\n";
    break;
  }
  svg << "</svg>";
  return svg.str();
}

}  // namespace cordgrasp
