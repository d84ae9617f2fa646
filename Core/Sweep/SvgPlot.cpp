#include "Sweep/SvgPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace soak {

namespace {
const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else o += c;
  }
  return o;
}

std::string label(double v) {
  char b[32];
  std::snprintf(b, sizeof(b), "%.4g", v);
  return b;
}
}  // namespace

void PlotData::add(const std::string& name, double x, double y) {
  auto s = std::find_if(series.begin(), series.end(), [&](const PlotSeries& e) { return e.name == name; });
  if (s == series.end()) s = series.insert(series.end(), PlotSeries{name, {}});
  s->points.emplace_back(x, y);
}

std::vector<double> niceTicks(double lo, double hi, int count) {
  if (!(hi > lo)) return {lo};
  const double raw = (hi - lo) / std::max(1, count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step)
    ticks.push_back(std::fabs(t) < step * 1e-9 ? 0.0 : t);
  return ticks;
}

std::string svgPlot(const PlotData& plot) {
  const double width = 720, height = 440, left = 90, right = 20, top = 40, bottom = 60;
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const PlotSeries& s : plot.series)
    for (const auto& p : s.points) {
      x0 = std::min(x0, p.first), x1 = std::max(x1, p.first);
      y0 = std::min(y0, p.second), y1 = std::max(y1, p.second);
    }
  const bool empty = !(x0 <= x1);
  if (empty) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  const bool logX = x0 > 0 && x1 / x0 >= 20;
  if (x1 == x0) x0 -= 0.5, x1 += 0.5;
  if (y1 == y0) y0 -= std::max(0.5, std::fabs(y0) * 0.1), y1 += std::max(0.5, std::fabs(y1) * 0.1);
  const double pad = 0.05 * (y1 - y0);
  y0 -= pad, y1 += pad;
  auto fx = [&](double x) {
    const double s = logX ? (std::log10(x) - std::log10(x0)) / (std::log10(x1) - std::log10(x0)) : (x - x0) / (x1 - x0);
    return left + s * (width - left - right);
  };
  auto fy = [&](double y) { return top + (1.0 - (y - y0) / (y1 - y0)) * (height - top - bottom); };

  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!plot.title.empty())
    o << "<text x=\"" << width / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">" << escape(plot.title)
      << "</text>\n";
  o << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << width - left - right << "\" height=\""
    << height - top - bottom << "\" fill=\"none\" stroke=\"#444\"/>\n";
  std::vector<double> xt;
  if (logX)
    for (double d = std::pow(10.0, std::floor(std::log10(x0))); d <= x1 * 1.0001; d *= 10)
      for (double m : {1.0, 2.0, 5.0})
        if (m * d >= x0 * 0.9999 && m * d <= x1 * 1.0001) xt.push_back(m * d);
  if (xt.size() < 2) xt = niceTicks(x0, x1, 6);
  for (double t : xt)
    o << "<line x1=\"" << fx(t) << "\" x2=\"" << fx(t) << "\" y1=\"" << height - bottom << "\" y2=\""
      << height - bottom + 5 << "\" stroke=\"#444\"/><text x=\"" << fx(t) << "\" y=\"" << height - bottom + 18
      << "\" text-anchor=\"middle\">" << label(t) << "</text>\n";
  for (double t : niceTicks(y0, y1, 6))
    o << "<line x1=\"" << left - 5 << "\" x2=\"" << width - right << "\" y1=\"" << fy(t) << "\" y2=\"" << fy(t)
      << "\" stroke=\"#ddd\"/><text x=\"" << left - 8 << "\" y=\"" << fy(t) + 4 << "\" text-anchor=\"end\">"
      << label(t) << "</text>\n";
  o << "<text x=\"" << (left + width - right) / 2 << "\" y=\"" << height - 18 << "\" text-anchor=\"middle\">"
    << escape(plot.xLabel) << (logX ? " (log scale)" : "") << "</text>\n";
  o << "<text transform=\"translate(18," << (top + height - bottom) / 2
    << ") rotate(-90)\" text-anchor=\"middle\">" << escape(plot.yLabel) << "</text>\n";
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    std::vector<std::pair<double, double>> pts = plot.series[k].points;
    std::sort(pts.begin(), pts.end());
    const char* colour = kColours[k % (sizeof(kColours) / sizeof(kColours[0]))];
    o << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"";
    for (const auto& p : pts) o << fx(p.first) << "," << fy(p.second) << " ";
    o << "\"/>\n";
    for (const auto& p : pts)
      o << "<circle cx=\"" << fx(p.first) << "\" cy=\"" << fy(p.second) << "\" r=\"3.5\" fill=\"" << colour << "\"/>\n";
    if (!plot.series[k].name.empty())
      o << "<text x=\"" << left + 12 << "\" y=\"" << top + 18 + 16 * double(k) << "\" fill=\"" << colour << "\">"
        << escape(plot.series[k].name) << "</text>\n";
  }
  if (empty)
    o << "<text x=\"" << width / 2 << "\" y=\"" << height / 2 << "\" text-anchor=\"middle\">no point done yet</text>\n";
  o << "</svg>\n";
  return o.str();
}

}  // namespace soak
