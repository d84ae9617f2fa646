#pragma once
// A small line plot written as SVG text: points joined per series, axes
// with round tick values, a legend. Enough for a sweep's figure against one
// value; anything finer belongs in the user's own tools (the CSV).
#include <string>
#include <vector>

namespace soak {

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // sorted by x when drawn
};

struct PlotData {
  std::string xLabel, yLabel, title;
  std::vector<PlotSeries> series;
  // Adds (x, y) to the series named `name`, made when missing.
  void add(const std::string& name, double x, double y);
};

// Logarithmic x when every x is positive and they span a factor of 20 or more.
std::string svgPlot(const PlotData& plot);

// Round tick values covering [lo, hi] (about `count` of them).
std::vector<double> niceTicks(double lo, double hi, int count);

}  // namespace soak
