#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "animpak/error.hpp"
#include "animpak/opencl.hpp"
#include "bench_report.hpp"
#include "commands.hpp"
#include "pack_output.hpp"

namespace animpak::cli {
namespace {

struct BenchWorld {
  std::string scene;
  std::string series;  ///< as BenchRow::series
  int elements = 0;
  World world;
};

// One column of the table: a device, and for OpenCL devices where the grid is sorted.
struct BenchTarget {
  std::string device;  ///< name fragment as given
  GridSort sort = GridSort::automatic;
  std::string label;   ///< the table's and the JSON's device name: "pocl", or "pocl:host" under --grid-sort both
};

// Every device animpak can time; a new backend adds one branch here and one name in run.cpp.
std::unique_ptr<Backend> make_backend(const BenchTarget& target, const World& world, std::string& grid_sort) {
  const DeviceChoice choice = choose_device(target.device);
  grid_sort = "";
  if (choice.reference) return make_reference_backend(world.topology, world.state, world.params);
  auto backend = make_opencl_backend(world.topology, world.state, world.params, choice, target.sort);
  grid_sort = grid_sort_name(backend->grid_sort());
  return backend;
}

std::vector<BenchTarget> bench_targets(const BenchOptions& options) {
  // The reference backend is always timed: it is the baseline every speedup is measured against.
  std::vector<BenchTarget> targets{{"reference", GridSort::automatic, "reference"}};
  const bool both = options.grid_sort == "both";
  const GridSort sort = both ? GridSort::automatic : parse_grid_sort(options.grid_sort, "--grid-sort");
  for (const std::string& d : options.devices) {
    if (choose_device(d).reference) continue;  // resolved now: a typo fails at once
    const bool seen = std::any_of(targets.begin(), targets.end(), [&](const BenchTarget& t) { return t.device == d; });
    if (seen) continue;
    if (both) {
      targets.push_back({d, GridSort::host, d + ":host"});
      targets.push_back({d, GridSort::device, d + ":device"});
    } else {
      targets.push_back({d, sort, d});
    }
  }
  return targets;
}

// The synthetic series to time: with --scene given, none unless --series asks for them.
std::vector<std::string> bench_series(const BenchOptions& options) {
  const std::string series =
      options.series.value_or(options.scenes.empty() && options.states.empty() ? "constant" : "");
  if (series.empty()) return {};
  if (series == "both") return {"constant", "dense"};
  return {series};
}

void print_notes(const BenchWorld& w) {
  for (const std::string& note : w.world.notes) std::cerr << "animpak: " << w.scene << ": " << note << "\n";
}

std::vector<BenchWorld> bench_worlds(const BenchOptions& options) {
  std::vector<BenchWorld> worlds;
  // The user's scenes first: a wrong path or field fails before minutes of synthetic world building.
  for (const std::filesystem::path& file : options.scenes) {
    World w = make_world(load_scene(file));
    const int elements = static_cast<int>(w.elements.size());
    worlds.push_back({file.string(), "scene", elements, std::move(w)});
    print_notes(worlds.back());
  }
  // Packed states: the world rebuilt from the scene inside the checkpoint, at its packed state.
  for (const std::filesystem::path& given : options.states) {
    const std::filesystem::path file = std::filesystem::is_directory(given) ? given / "state.bin" : given;
    LoadedWorld loaded = world_from_checkpoint(read_checkpoint(file), true);
    const int elements = static_cast<int>(loaded.world.elements.size());
    worlds.push_back({given.string(), "state", elements, std::move(loaded.world)});
    print_notes(worlds.back());
  }
  const std::vector<std::string> series = bench_series(options);
  const auto star = options.examples / "default" / "star.svg";
  if (!series.empty() && !std::filesystem::exists(star))
    throw InputError(star.string() + ": not found; run from the source folder or pass --examples DIR");
  for (const std::string& name : series)
    for (int size : options.sizes) {
      SyntheticSpec spec;
      spec.element_art = star;
      spec.target_vertices = size;
      spec.slices = options.slices;
      spec.density = name == "constant" ? SyntheticDensity::constant : SyntheticDensity::dense;
      SyntheticWorld s = make_synthetic_world(spec);
      const std::string scene = name + "-" + std::to_string(size);
      std::cerr << "animpak: " << scene << ": " << s.elements << " stars x " << s.slices
                << " slices at initial scale " << s.initial_scale << ", cell_size " << s.world.params.cell_size
                << "\n";
      worlds.push_back({scene, name, s.elements, std::move(s.world)});
      print_notes(worlds.back());
    }
  if (options.example_scenes && options.scenes.empty() && options.states.empty())
    for (const char* name : {"default", "aquarium", "annulus"}) {
      World w = make_world(load_scene(options.examples / name / "scene.json"));
      const int elements = static_cast<int>(w.elements.size());
      worlds.push_back({name, "example", elements, std::move(w)});
    }
  return worlds;
}

// Every (device, synthetic series) pair with rows, in row order.
std::vector<std::pair<std::string, std::string>> fitted_lines(const std::vector<BenchRow>& rows) {
  std::vector<std::pair<std::string, std::string>> lines;
  for (const BenchRow& r : rows) {
    const std::pair<std::string, std::string> line{r.device, r.series};
    if (r.synthetic() && std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
  }
  return lines;
}

nlohmann::json phases_json(const PhaseTimes& p) {
  nlohmann::json out = nlohmann::json::object();
  for (const NamedPhase& phase : phase_fields) out[phase.name] = p.*phase.seconds;
  return out;
}

void write_json(const std::vector<BenchRow>& rows, const std::filesystem::path& file) {
  nlohmann::json results = nlohmann::json::array();
  for (const BenchRow& r : rows)
    results.push_back({{"device", r.device},
                       {"scene", r.scene},
                       {"series", r.series},
                       {"synthetic", r.synthetic()},
                       {"vertices", r.vertices}, {"neighbour_visits", r.neighbour_visits},
                       {"visits_per_vertex", r.visits_per_vertex()},
                       {"elements", r.elements},
                       {"steps", r.timing.steps},
                       {"ms_per_iter", r.timing.ms_per_iter},
                       {"reference_ms_per_iter", r.reference_ms_per_iter},
                       {"grid_sort", r.grid_sort.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.grid_sort)},
                       {"speedup", r.speedup()},
                       {"rounds_ms_per_iter", r.rounds_ms},
                       {"rounds_speedup", r.rounds_speedup},
                       {"phases", phases_json(r.timing.phases_ms)}});
  nlohmann::json fits = nlohmann::json::array();
  for (const auto& [device, series] : fitted_lines(rows)) {
    const LinearFit f = fit_series(rows, device, series);
    if (f.points >= 2)
      fits.push_back({{"device", device}, {"series", series}, {"points", f.points},
                      {"ms_per_kvertex", f.slope_ms_per_kvertex}, {"intercept_ms", f.intercept_ms},
                      {"visits_per_vertex_min", f.min_visits_per_vertex},
                      {"visits_per_vertex_max", f.max_visits_per_vertex},
                      {"cost_ratio_largest_to_smallest", f.cost_ratio}, {"visit_cost_ratio", f.visit_cost_ratio},
                      {"phase_cost_ratios", phases_json(f.phase_ratios)}});
  }
  std::ofstream out(file);
  if (!out) throw InputError(file.string() + ": cannot write; check that the folder exists and is writable");
  out << nlohmann::json{{"results", results}, {"fits", fits}}.dump(2) << "\n";
  if (!out) throw InputError(file.string() + ": writing failed; check free disk space");
}

void print_table(const std::vector<BenchRow>& rows) {
  // A --scene path can be long; the column fits the longest name.
  int width = 18;
  for (const BenchRow& r : rows) width = std::max(width, static_cast<int>(r.scene.size()));
  std::printf("%-*s %-14s %8s %5s %9s %10s %8s %8s %8s %8s %9s %11s %7s %7s %10s\n", width, "scene", "device",
              "vertices", "elem", "visits/v", "ms/iter", "spread%", "speedup", "grid", "forces", "integrate",
              "constraints", "loop", "growth", "statistics");
  for (const BenchRow& r : rows) {
    const PhaseTimes& p = r.timing.phases_ms;
    std::printf("%-*s %-14s %8d %5d %9.1f %10.3f %8.1f %8.2f %8.3f %8.3f %9.3f %11.3f %7.3f %7.3f %10.3f\n", width,
                r.scene.c_str(), r.device.c_str(), r.vertices, r.elements, r.visits_per_vertex(), r.timing.ms_per_iter,
                r.spread_percent(), r.speedup(), p.grid, p.forces, p.integrate, p.constraints, p.loop, p.growth,
                p.statistics);
  }
}

}  // namespace

StepTiming median_round(const std::vector<StepTiming>& rounds) {
  if (rounds.empty()) return {};
  std::vector<const StepTiming*> order;
  for (const StepTiming& r : rounds) order.push_back(&r);
  std::stable_sort(order.begin(), order.end(),
                   [](const StepTiming* a, const StepTiming* b) { return a->ms_per_iter < b->ms_per_iter; });
  return *order[(order.size() - 1) / 2];
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double BenchRow::speedup() const { return median(rounds_speedup); }

double BenchRow::spread_percent() const {
  if (rounds_ms.empty()) return 0.0;
  const auto [lo, hi] = std::minmax_element(rounds_ms.begin(), rounds_ms.end());
  return 100.0 * (*hi - *lo) / timing.ms_per_iter;
}

LinearFit fit_series(const std::vector<BenchRow>& rows, const std::string& device, const std::string& series) {
  std::vector<const BenchRow*> pts;
  for (const BenchRow& r : rows)
    if (r.series == series && r.device == device) pts.push_back(&r);
  LinearFit f;
  f.points = static_cast<int>(pts.size());
  if (f.points < 2) return f;
  auto by_visits = [](const BenchRow* a, const BenchRow* b) { return a->visits_per_vertex() < b->visits_per_vertex(); };
  f.min_visits_per_vertex = (*std::min_element(pts.begin(), pts.end(), by_visits))->visits_per_vertex();
  f.max_visits_per_vertex = (*std::max_element(pts.begin(), pts.end(), by_visits))->visits_per_vertex();
  double mx = 0, my = 0;
  for (const BenchRow* r : pts) mx += r->vertices / 1000.0, my += r->timing.ms_per_iter;
  mx /= f.points, my /= f.points;
  double sxy = 0, sxx = 0;
  for (const BenchRow* r : pts) {
    const double dx = r->vertices / 1000.0 - mx;
    sxy += dx * (r->timing.ms_per_iter - my);
    sxx += dx * dx;
  }
  f.slope_ms_per_kvertex = sxx > 0 ? sxy / sxx : 0.0;
  f.intercept_ms = my - f.slope_ms_per_kvertex * mx;
  auto by_size = [](const BenchRow* a, const BenchRow* b) { return a->vertices < b->vertices; };
  const BenchRow* lo = *std::min_element(pts.begin(), pts.end(), by_size);
  const BenchRow* hi = *std::max_element(pts.begin(), pts.end(), by_size);
  f.cost_ratio = (hi->timing.ms_per_iter / hi->vertices) / (lo->timing.ms_per_iter / lo->vertices);
  auto ratio = [&](double PhaseTimes::*phase) {
    const double small = lo->timing.phases_ms.*phase / lo->vertices;
    return small > 0 ? (hi->timing.phases_ms.*phase / hi->vertices) / small : 0.0;
  };
  for (const NamedPhase& phase : phase_fields) f.phase_ratios.*phase.seconds = ratio(phase.seconds);
  // Rows whose elements have (almost) no neighbour in reach cost only springs and the overlap test;
  // compare the ones that visit at least once per vertex (a dense world of 25,000 vertices visits 0.4).
  std::vector<const BenchRow*> visiting;
  for (const BenchRow* r : pts)
    if (r->visits_per_vertex() >= 1.0) visiting.push_back(r);
  if (visiting.size() >= 2) {
    const BenchRow* vlo = *std::min_element(visiting.begin(), visiting.end(), by_size);
    const BenchRow* vhi = *std::max_element(visiting.begin(), visiting.end(), by_size);
    f.visit_cost_ratio = (vhi->timing.phases_ms.forces / double(vhi->neighbour_visits)) /
                         (vlo->timing.phases_ms.forces / double(vlo->neighbour_visits));
  }
  return f;
}

int bench(const BenchOptions& options, const BenchPlotter& plot) {
  // Every device name is resolved before minutes of world building, so a typo fails at once.
  const std::vector<BenchTarget> targets = bench_targets(options);

  std::vector<BenchRow> rows;
  const int repeat = std::max(1, options.repeat);
  for (const BenchWorld& w : bench_worlds(options)) {
    std::vector<std::unique_ptr<Backend>> backends;
    std::vector<std::string> grid_sorts(targets.size());
    std::vector<std::vector<StepTiming>> rounds(targets.size());
    for (std::size_t i = 0; i < targets.size(); ++i) backends.push_back(make_backend(targets[i], w.world, grid_sorts[i]));
    // Round by round, every device in turn; each backend steps on from where its last round ended.
    for (int round = 0; round < repeat; ++round)
      for (std::size_t i = 0; i < targets.size(); ++i) {
        std::cerr << "animpak: timing " << w.scene << " (" << w.world.topology.vertex_count() << " vertices) on "
                  << targets[i].label << (repeat > 1 ? ", round " + std::to_string(round + 1) : std::string()) << "\n";
        rounds[i].push_back(time_steps(*backends[i], w.world.params, round == 0 ? options.warmup : 0, options.steps));
      }
    // The reference is always the first target (bench_targets).
    for (std::size_t i = 0; i < targets.size(); ++i) {
      BenchRow row{targets[i].label, w.scene, w.series, w.world.topology.vertex_count(), w.elements,
                   median_round(rounds[i]), median_round(rounds[0]).ms_per_iter, 0, grid_sorts[i], {}, {}};
      for (std::size_t r = 0; r < rounds[i].size(); ++r) {
        row.rounds_ms.push_back(rounds[i][r].ms_per_iter);
        row.rounds_speedup.push_back(rounds[0][r].ms_per_iter / rounds[i][r].ms_per_iter);
      }
      row.neighbour_visits = neighbour_visits(w.world.topology, backends[i]->state(), w.world.params);
      rows.push_back(row);
    }
  }

  print_table(rows);
  for (const auto& [device, series] : fitted_lines(rows)) {
    const LinearFit f = fit_series(rows, device, series);
    const char* d = device.c_str();
    const char* s = series.c_str();
    if (f.points < 2) {
      std::printf("%s, %s series: linear fit needs two or more --sizes\n", d, s);
      continue;
    }
    // A ratio near 1 means the cost per vertex does not grow with size: no quadratic step.
    std::printf("%s, %s series: %.4f ms per 1k vertices (intercept %.3f ms) over %d sizes, visits per vertex "
                "%.1f to %.1f; per-vertex cost, largest / smallest size: %.2f\n",
                d, s, f.slope_ms_per_kvertex, f.intercept_ms, f.points, f.min_visits_per_vertex,
                f.max_visits_per_vertex, f.cost_ratio);
    const PhaseTimes& r = f.phase_ratios;
    std::printf("%s, %s series: per-vertex cost ratio by phase: grid %.2f, forces %.2f, integrate %.2f, "
                "constraints %.2f, loop %.2f, growth %.2f, statistics %.2f\n",
                d, s, r.grid, r.forces, r.integrate, r.constraints, r.loop, r.growth, r.statistics);
    if (f.visit_cost_ratio > 0)
      std::printf("%s, %s series: forces cost per neighbour visit, largest / smallest size: %.2f (at or below 1: "
                  "the force phase grows with the neighbours it must visit, not with an accidental quadratic loop)\n",
                  d, s, f.visit_cost_ratio);
  }
  if (options.json) write_json(rows, *options.json);
  if (plot) plot(rows);
  return 0;
}

}  // namespace animpak::cli
