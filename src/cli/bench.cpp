#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "animpak/error.hpp"
#include "animpak/opencl.hpp"
#include "animpak/synthetic.hpp"
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
    // A state named directly may be a link the user made (its folder's input/ is beside the file it points
    // to); a folder's own state.bin is read as every command reads it, following no link.
    const std::filesystem::path file =
        std::filesystem::is_directory(given) ? given / "state.bin" : std::filesystem::weakly_canonical(given);
    const Checkpoint checkpoint = read_checkpoint(file);
    LoadedWorld loaded = world_from_checkpoint(checkpoint, true, packed_scene(file.parent_path(), checkpoint));
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
      std::cerr << "animpak: " << scene << ": " << s.elements << " stars x " << s.slices << " slices at initial scale "
                << s.initial_scale << ", cell_size " << s.world.params.forces.cell_size << "\n";
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
                       {"vertices", r.vertices},
                       {"neighbour_visits", r.neighbour_visits},
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
      fits.push_back({{"device", device},
                      {"series", series},
                      {"points", f.points},
                      {"ms_per_kvertex", f.slope_ms_per_kvertex},
                      {"intercept_ms", f.intercept_ms},
                      {"visits_per_vertex_min", f.min_visits_per_vertex},
                      {"visits_per_vertex_max", f.max_visits_per_vertex},
                      {"cost_ratio_largest_to_smallest", f.cost_ratio},
                      {"visit_cost_ratio", f.visit_cost_ratio},
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

int bench(const BenchOptions& options, const BenchPlotter& plot) {
  // Every device name is resolved before minutes of world building, so a typo fails at once.
  const bool both = options.grid_sort == "both";
  const std::vector<BenchTarget> targets = bench_targets(
      options.devices, both ? GridSort::automatic : parse_grid_sort(options.grid_sort, "--grid-sort"), both);

  std::vector<BenchRow> rows;
  for (const BenchWorld& w : bench_worlds(options)) {
    const BenchWorldView view{w.scene, w.series, w.elements, w.world.topology, w.world.state, w.world.params};
    const auto progress = [&](const BenchTarget& target, int round) {
      std::cerr << "animpak: timing " << w.scene << " (" << w.world.topology.vertex_count() << " vertices) on "
                << target.label << (options.repeat > 1 ? ", round " + std::to_string(round + 1) : std::string())
                << "\n";
    };
    for (BenchRow& row : bench_world(view, targets, options.repeat, options.warmup, options.steps, progress))
      rows.push_back(std::move(row));
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
    std::printf(
        "%s, %s series: %.4f ms per 1k vertices (intercept %.3f ms) over %d sizes, visits per vertex "
        "%.1f to %.1f; per-vertex cost, largest / smallest size: %.2f\n",
        d, s, f.slope_ms_per_kvertex, f.intercept_ms, f.points, f.min_visits_per_vertex, f.max_visits_per_vertex,
        f.cost_ratio);
    const PhaseTimes& r = f.phase_ratios;
    std::printf(
        "%s, %s series: per-vertex cost ratio by phase: grid %.2f, forces %.2f, integrate %.2f, "
        "constraints %.2f, loop %.2f, growth %.2f, statistics %.2f\n",
        d, s, r.grid, r.forces, r.integrate, r.constraints, r.loop, r.growth, r.statistics);
    if (f.visit_cost_ratio > 0)
      std::printf(
          "%s, %s series: forces cost per neighbour visit, largest / smallest size: %.2f (at or below 1: "
          "the force phase grows with the neighbours it must visit, not with an accidental quadratic loop)\n",
          d, s, f.visit_cost_ratio);
  }
  if (options.json) write_json(rows, *options.json);
  if (plot) plot(rows);
  return 0;
}

}  // namespace animpak::cli
