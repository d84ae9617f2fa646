#include "Sweep/SweepCollect.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "Base/Error.h"
#include "Scene/Suggest.h"
#include "Sweep/SvgPlot.h"
#include "Sweep/SweepFolder.h"

namespace soak {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string numberText(double v) {
  if (std::isnan(v)) return "";
  char b[32];
  std::snprintf(b, sizeof(b), "%.9g", v);
  return b;
}

// What a named figure stands for.
std::string expand(const std::string& figure) {
  for (const auto& named : sweepFigureNames())
    if (named.first == figure) return named.second;
  return figure;
}
}  // namespace

const std::vector<std::pair<std::string, std::string>>& sweepFigureNames() {
  static const std::vector<std::pair<std::string, std::string>> names = {
      {"held", "final:held_water_mass"},
      {"buffered", "final:buffered_water_mass"},
      {"drained", "final:drained_water_mass"},
      {"free", "final:free_water_mass"},
      {"evaporated", "final:evaporated_water_mass"},
      {"drips", "final:drips_spawned"},
      {"max_saturation", "final:max_saturation"},
      {"worst_strain", "max:strain_p99_*"},
      {"worst_stretch", "max:max_stretch"},
      {"steps", "final:step"},
      {"simulated_s", "final:time"},
      {"wall_s", "the point's recorded wall time"},
  };
  return names;
}

std::vector<std::string> defaultSweepFigures() {
  return {"held", "buffered", "drained", "drips", "worst_strain", "steps", "wall_s"};
}

StatsTable readStatsCsv(const std::string& path) {
  StatsTable t;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return t;
  std::istringstream header(line);
  for (std::string c; std::getline(header, c, ',');) t.columns.push_back(c);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) row.push_back(std::strtod(c.c_str(), nullptr));
    if (row.size() == t.columns.size()) t.rows.push_back(row);  // a half-written last row is left out
  }
  return t;
}

double sweepFigure(const std::string& figure, const StatsTable& stats, double wallSeconds) {
  if (figure == "wall_s") return wallSeconds;
  const std::string spec = expand(figure);
  const std::size_t colon = spec.find(':');
  const std::string agg = colon == std::string::npos ? "" : spec.substr(0, colon);
  if (agg != "final" && agg != "max" && agg != "min" && agg != "mean") {
    std::vector<std::string> names;
    for (const auto& n : sweepFigureNames()) names.push_back(n.first);
    throw InputError("unknown figure '" + figure + "'" + suggestionText(figure, names) +
                     " (or AGGREGATE:COLUMN, AGGREGATE one of final, max, min, mean, COLUMN a stats.csv column)");
  }
  std::string column = spec.substr(colon + 1);
  const bool prefix = !column.empty() && column.back() == '*';
  if (prefix) column.pop_back();
  std::vector<std::size_t> picked;
  for (std::size_t c = 0; c < stats.columns.size(); ++c)
    if (prefix ? stats.columns[c].rfind(column, 0) == 0 : stats.columns[c] == column) picked.push_back(c);
  if (picked.empty() || stats.rows.empty()) return kNaN;
  double result = agg == "min" ? INFINITY : agg == "max" ? -INFINITY : 0.0;
  std::size_t count = 0;
  for (std::size_t r = agg == "final" ? stats.rows.size() - 1 : 0; r < stats.rows.size(); ++r)
    for (std::size_t c : picked) {
      const double v = stats.rows[r][c];
      if (agg == "max" || (agg == "final" && prefix)) result = count == 0 ? v : std::max(result, v);
      else if (agg == "min") result = std::min(result, v);
      else result += v;
      ++count;
    }
  if (agg == "mean") result /= double(count);
  return result;
}

CollectedSweep collectSweep(const std::string& dir, const std::vector<std::string>& figures) {
  const SweepState s = loadSweep(dir);
  CollectedSweep c;
  for (const SweepParameter& p : s.description.parameters) c.parameters.push_back(p.name);
  c.figures = figures.empty() ? defaultSweepFigures() : figures;
  const StatsTable none;
  for (const std::string& f : c.figures) sweepFigure(f, none, 0.0);  // an unknown figure is refused up front
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    CollectedSweep::Row row;
    row.id = s.points[i].id;
    row.repeat = s.points[i].repeat;
    row.values = s.points[i].values;
    row.status = s.records[i].status;
    const bool done = row.status == "done";
    const StatsTable stats = done ? readStatsCsv(s.layout.runDir(row.id) + "/stats.csv") : none;
    for (const std::string& f : c.figures)
      row.figures.push_back(done ? sweepFigure(f, stats, s.records[i].wallSeconds) : kNaN);
    c.rows.push_back(row);
  }
  return c;
}

std::string collectedCsv(const CollectedSweep& c) {
  std::ostringstream o;
  o << "point,repeat";
  for (const std::string& p : c.parameters) o << "," << csvField(p);
  o << ",status";
  for (const std::string& f : c.figures) o << "," << csvField(f);
  o << "\n";
  for (const CollectedSweep::Row& r : c.rows) {
    o << r.id << "," << r.repeat;
    for (const std::string& v : r.values) o << "," << csvField(v);
    o << "," << r.status;
    for (double v : r.figures) o << "," << numberText(v);
    o << "\n";
  }
  return o.str();
}

std::string collectedPlotSvg(const CollectedSweep& c, const std::string& figure, const std::string& against) {
  std::size_t fx = c.parameters.size(), fy = c.figures.size();
  for (std::size_t k = 0; k < c.parameters.size(); ++k)
    if (c.parameters[k] == against) fx = k;
  for (std::size_t k = 0; k < c.figures.size(); ++k)
    if (c.figures[k] == figure) fy = k;
  if (fx == c.parameters.size())
    throw InputError("the plot's x, '" + against + "', is not a varying value of the sweep" +
                     suggestionText(against, c.parameters));
  if (fy == c.figures.size())
    throw InputError("the plot's figure, '" + figure + "', is not among the figures collected" +
                     suggestionText(figure, c.figures));
  PlotData plot;
  plot.xLabel = against;
  plot.yLabel = figure == expand(figure) ? figure : figure + " (" + expand(figure) + ")";
  for (const CollectedSweep::Row& r : c.rows) {
    char* end = nullptr;
    const double x = std::strtod(r.values[fx].c_str(), &end);
    if (*end || r.values[fx].empty())
      throw InputError("the plot's x, '" + against + "', takes a value that is not a number: " + r.values[fx]);
    if (std::isnan(r.figures[fy])) continue;
    std::string series;
    for (std::size_t k = 0; k < c.parameters.size(); ++k)
      if (k != fx) series += (series.empty() ? "" : ", ") + c.parameters[k] + " = " + r.values[k];
    plot.add(series, x, r.figures[fy]);
  }
  return svgPlot(plot);
}

}  // namespace soak
