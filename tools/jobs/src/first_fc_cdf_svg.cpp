#include "cordgrasp/jobs/first_fc_cdf_svg.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cordgrasp/jobs/text_format.h"
#include "svg_axis.h"

namespace cordgrasp {
namespace {

constexpr int kLeft_px = 44, kRight_px = 12, kTop_px = 12, kBottom_px = 34;
constexpr const char* kCurveColor = "#1f6fb4";

}  // namespace

std::string first_fc_cdf_svg(std::vector<double> first_fc_s, int attempts,
                             const FirstFcPlotParams& params) {
  if (attempts <= 0) return "";
  first_fc_s.erase(std::remove_if(first_fc_s.begin(), first_fc_s.end(),
                                  [](double t) { return !std::isfinite(t); }),
                   first_fc_s.end());
  std::sort(first_fc_s.begin(), first_fc_s.end());
  const double w = params.width_px, h = params.height_px;
  const double plot_w = w - kLeft_px - kRight_px, plot_h = h - kTop_px - kBottom_px;
  const Axis time(first_fc_s.empty() ? 0.0 : first_fc_s.back());
  const Axis share(100.0);
  const auto x = [&](double t) { return kLeft_px + plot_w * std::clamp(t / time.top, 0.0, 1.0); };
  const auto y = [&](double percent) {
    return kTop_px + plot_h * (1.0 - std::clamp(percent / share.top, 0.0, 1.0));
  };
  const auto px = [](double v) { return format_number(v, "%.1f"); };
  const double found_percent = 100.0 * static_cast<double>(first_fc_s.size()) / attempts;

  std::ostringstream svg;
  svg << "<svg class=\"first-fc\" width=\"" << w << "\" height=\"" << h << "\" viewBox=\"0 0 "
      << w << " " << h << "\" role=\"img\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<title>Attempts that found a force-closure grasp [%] by wall time [s]</title>\n"
      << "<g stroke=\"#999\" stroke-width=\"1\" fill=\"none\"><rect x=\"" << kLeft_px
      << "\" y=\"" << kTop_px << "\" width=\"" << px(plot_w) << "\" height=\"" << px(plot_h)
      << "\"/></g>\n";
  for (double v = 0.0; v <= share.top * (1.0 + 1e-9); v += share.step)
    svg << "<line x1=\"" << kLeft_px - 4 << "\" x2=\"" << px(kLeft_px + plot_w) << "\" y1=\""
        << px(y(v)) << "\" y2=\"" << px(y(v)) << "\" stroke=\"#e3e3e3\"/><text x=\""
        << kLeft_px - 6 << "\" y=\"" << px(y(v) + 4) << "\" text-anchor=\"end\" fill=\"#444\">"
        << format_number(v) << "</text>\n";
  for (double v = 0.0; v <= time.top * (1.0 + 1e-9); v += time.step)
    svg << "<line x1=\"" << px(x(v)) << "\" x2=\"" << px(x(v)) << "\" y1=\""
        << px(kTop_px + plot_h) << "\" y2=\"" << px(kTop_px + plot_h + 4)
        << "\" stroke=\"#999\"/><text x=\"" << px(x(v)) << "\" y=\""
        << px(h - kBottom_px + 15) << "\" text-anchor=\"middle\" fill=\"#444\">"
        << format_number(v) << "</text>\n";
  svg << "<text x=\"" << px(kLeft_px + 0.5 * plot_w) << "\" y=\"" << px(h - 4)
      << "\" text-anchor=\"middle\" fill=\"#444\">first force-closure grasp by [s]</text>\n"
      << "<text transform=\"translate(12 " << px(kTop_px + 0.5 * plot_h)
      << ") rotate(-90)\" text-anchor=\"middle\" fill=\"#444\">attempts [%]</text>\n";
  // The share that found a grasp at all: the curve's ceiling.
  svg << "<line class=\"found\" x1=\"" << kLeft_px << "\" x2=\"" << px(kLeft_px + plot_w)
      << "\" y1=\"" << px(y(found_percent)) << "\" y2=\"" << px(y(found_percent))
      << "\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>\n";
  // The step curve: 0 % until the first time, one step up per attempt.
  std::ostringstream pts;
  pts << px(x(0.0)) << "," << px(y(0.0)) << " ";
  for (size_t i = 0; i < first_fc_s.size(); ++i) {
    const double before = 100.0 * static_cast<double>(i) / attempts;
    const double after = 100.0 * static_cast<double>(i + 1) / attempts;
    pts << px(x(first_fc_s[i])) << "," << px(y(before)) << " " << px(x(first_fc_s[i])) << ","
        << px(y(after)) << " ";
  }
  pts << px(kLeft_px + plot_w) << "," << px(y(found_percent));
  svg << "<polyline class=\"cdf\" fill=\"none\" stroke=\"" << kCurveColor
      << "\" stroke-width=\"1.5\" points=\"" << pts.str() << "\"/>\n</svg>";
  return svg.str();
}

}  // namespace cordgrasp
