// soak-neighbour-bench: neighbourhood search timings (grid build + reorder +
// a full neighbour count) on the point sets of Doc/performance.md.
//
//   soak-neighbour-bench [--device cpu|cuda|all] [--repeat R] [--json FILE] [--lattice N...] [--random N...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "Backend/Primitives.h"
#include "Neighbours/NeighbourGrid.h"

using namespace soak;

namespace {

struct PointSet {
  std::string name;
  std::vector<Vec3> points;
  float radius;
};

// N^3 lattice on [-0.15, 0.15]^3 clipped to the ball of radius 0.15, shuffled;
// radius = 2 lattice spacings (the set neighbourhood-search libraries use).
PointSet latticeSet(int n) {
  PointSet s;
  s.name = "lattice N=" + std::to_string(n);
  const float step = 2.f * 0.15f / float(n - 1);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        Vec3 p(-0.15f + i * step, -0.15f + j * step, -0.15f + k * step);
        if (length(p) <= 0.15f) s.points.push_back(p);
      }
  std::mt19937 rng(42);
  std::shuffle(s.points.begin(), s.points.end(), rng);
  s.radius = 2.f * step;
  return s;
}

// Uniform random points at water density (spacing 0.02 m, h = 0.04 m).
PointSet randomSet(int n) {
  PointSet s;
  s.name = "random fluid N=" + std::to_string(n);
  const float side = std::cbrt(float(n)) * 0.02f;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.f, side);
  for (int i = 0; i < n; ++i) s.points.push_back(Vec3(u(rng), u(rng), u(rng)));
  s.radius = 0.04f;
  return s;
}

struct Result {
  std::string set, device;
  int points;
  double buildMs, countMs, totalMs, meanNeighbours;
};

Result measure(const PointSet& set, Device d, int repeat) {
  std::vector<ParticleInit> init(set.points.size());
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    init[i].position = set.points[i];
    init[i].mass = 1.f;
    init[i].radius = set.radius;
  }
  std::vector<double> build, count;
  double mean = 0.0;
  for (int r = 0; r < repeat + 1; ++r) {  // first run is warm-up
    ParticleState ps(d);
    ps.append(init);
    NeighbourGrid grid(d);
    Buffer<int> counts(d, ps.count());
    Buffer<float> countsF(d, ps.count());
    synchronize(d);
    auto t0 = std::chrono::steady_clock::now();
    grid.build(ps, set.radius);
    synchronize(d);
    auto t1 = std::chrono::steady_clock::now();
    countNeighbours(d, grid.view(), ps.view(), counts.data());
    synchronize(d);
    auto t2 = std::chrono::steady_clock::now();
    if (r > 0) {
      build.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      count.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    }
    std::vector<int> c = counts.download();
    double sum = 0;
    for (int v : c) sum += v;
    mean = c.empty() ? 0.0 : sum / double(c.size());
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  Result res{set.name, deviceName(d), int(set.points.size()), median(build), median(count), 0.0, mean};
  res.totalMs = res.buildMs + res.countMs;
  return res;
}

}  // namespace

int main(int argc, char** argv) {
  std::string device = "all", json;
  int repeat = 10;
  std::vector<int> lattice, random;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--device") device = next();
    else if (a == "--repeat") repeat = std::max(1, std::atoi(next().c_str()));
    else if (a == "--json") json = next();
    else if (a == "--lattice") lattice.push_back(std::atoi(next().c_str()));
    else if (a == "--random") random.push_back(std::atoi(next().c_str()));
    else {
      std::fprintf(stderr, "usage: %s [--device cpu|cuda|all] [--repeat R] [--json FILE] [--lattice N] [--random N]\n",
                   argv[0]);
      return 2;
    }
  }
  if (lattice.empty() && random.empty()) {
    lattice = {56, 120};
    random = {100000, 1000000};
  }
  std::vector<Device> devices;
  if (device == "cpu" || device == "all") devices.push_back(Device::Cpu);
  if (device == "cuda" || device == "all") {
    std::string why;
    if (cudaDeviceAvailable(&why)) devices.push_back(Device::Cuda);
    else if (device == "cuda") {
      std::fprintf(stderr, "cuda: %s\n", why.c_str());
      return 3;
    } else std::fprintf(stderr, "note: no GPU (%s); CPU only\n", why.c_str());
  }
  std::vector<PointSet> sets;
  for (int n : lattice) sets.push_back(latticeSet(n));
  for (int n : random) sets.push_back(randomSet(n));

  std::vector<Result> results;
  std::printf("%-24s %-5s %10s %10s %10s %10s %9s\n", "set", "dev", "points", "build ms", "count ms", "total ms",
              "mean nbrs");
  for (Device d : devices)
    for (const PointSet& s : sets) {
      Result r = measure(s, d, repeat);
      results.push_back(r);
      std::printf("%-24s %-5s %10d %10.3f %10.3f %10.3f %9.2f\n", r.set.c_str(), r.device.c_str(), r.points,
                  r.buildMs, r.countMs, r.totalMs, r.meanNeighbours);
      std::fflush(stdout);
    }
  if (!cudaDeviceDescription().empty()) std::printf("GPU: %s\n", cudaDeviceDescription().c_str());
  if (!json.empty()) {
    std::ofstream o(json);
    o << "[\n";
    for (std::size_t i = 0; i < results.size(); ++i) {
      const Result& r = results[i];
      o << "  {\"set\": \"" << r.set << "\", \"device\": \"" << r.device << "\", \"points\": " << r.points
        << ", \"build_ms\": " << r.buildMs << ", \"count_ms\": " << r.countMs << ", \"total_ms\": " << r.totalMs
        << ", \"mean_neighbours\": " << r.meanNeighbours << "}" << (i + 1 < results.size() ? "," : "") << "\n";
    }
    o << "]\n";
  }
  return 0;
}
