#pragma once
// Gathering a sweep's results: one row per point, its values and summary
// figures taken from its run's stats.csv (Doc/output.md, "stats.csv
// columns"), and a plot of one figure against one varying value.
//
// A figure is a name from sweepFigureNames() or AGGREGATE:COLUMN, AGGREGATE
// one of final, max, min, mean over the run's frames, COLUMN a stats.csv
// column; a COLUMN ending in * takes every column that starts so
// ("max:strain_p99_*": the worst of every cloth). wall_s is the point's
// recorded wall time.
#include <string>
#include <vector>

namespace soak {

// The named figures and what each is ("held = final:held_water_mass").
const std::vector<std::pair<std::string, std::string>>& sweepFigureNames();

// What collect writes when not told: held, buffered, drained, drips,
// worst_strain, steps, wall_s.
std::vector<std::string> defaultSweepFigures();

struct StatsTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

// A run's stats.csv; an empty table when the file is missing.
StatsTable readStatsCsv(const std::string& path);

// The figure's value over `stats`; NaN when the run has no such column or
// no frames. InputError for a figure that is neither named nor AGG:COLUMN.
double sweepFigure(const std::string& figure, const StatsTable& stats, double wallSeconds);

struct CollectedSweep {
  std::vector<std::string> parameters;  // varying value names
  std::vector<std::string> figures;
  struct Row {
    std::string id;
    int repeat = 0;
    std::vector<std::string> values;
    std::string status;
    std::vector<double> figures;  // NaN where the point is not done
  };
  std::vector<Row> rows;
};

// Reads every point of the sweep in `dir`; only done points get figures.
CollectedSweep collectSweep(const std::string& dir, const std::vector<std::string>& figures);

// The table as CSV (empty cells for NaN).
std::string collectedCsv(const CollectedSweep& c);

// An SVG plot of `figure` against the varying value `against`, one line per
// combination of the other varying values; logarithmic x when the values
// are positive and span a factor of 20 or more. InputError when either is
// not in `c`, or the values of `against` are not numbers.
std::string collectedPlotSvg(const CollectedSweep& c, const std::string& figure, const std::string& against);

}  // namespace soak
