// The measurements behind `animpak bench` (animpak/bench.hpp).
#include "animpak/bench.hpp"

#include <algorithm>
#include <memory>

#include "animpak/simulation.hpp"

namespace animpak {
namespace {

// Every device animpak can time; a new backend adds one branch here and one name in run.cpp.
std::unique_ptr<Backend> make_backend(const BenchTarget& target, const BenchWorldView& world, std::string& grid_sort) {
  const DeviceChoice choice = choose_device(target.device);
  grid_sort = "";
  if (choice.reference) return make_reference_backend(world.topology, world.state, world.params);
  auto backend = make_opencl_backend(world.topology, world.state, world.params, choice, target.sort);
  grid_sort = grid_sort_name(backend->grid_sort());
  return backend;
}

}  // namespace

std::vector<BenchTarget> bench_targets(const std::vector<std::string>& devices, GridSort sort, bool both) {
  std::vector<BenchTarget> targets{{"reference", GridSort::automatic, "reference"}};
  for (const std::string& d : devices) {
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

std::vector<BenchRow> bench_world(const BenchWorldView& w, const std::vector<BenchTarget>& targets, int repeat_rounds,
                                  int warmup, int steps,
                                  const std::function<void(const BenchTarget&, int round)>& progress) {
  const int repeat = std::max(1, repeat_rounds);
  std::vector<std::unique_ptr<Backend>> backends;
  std::vector<std::string> grid_sorts(targets.size());
  std::vector<std::vector<StepTiming>> rounds(targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i) backends.push_back(make_backend(targets[i], w, grid_sorts[i]));
  // Round by round, every device in turn; each backend steps on from where its last round ended.
  for (int round = 0; round < repeat; ++round)
    for (std::size_t i = 0; i < targets.size(); ++i) {
      if (progress) progress(targets[i], round);
      rounds[i].push_back(time_steps(*backends[i], w.params, round == 0 ? warmup : 0, steps));
    }
  // The reference is always the first target (bench_targets).
  std::vector<BenchRow> rows;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    BenchRow row{targets[i].label,
                 w.scene,
                 w.series,
                 w.topology.vertex_count(),
                 w.elements,
                 median_round(rounds[i]),
                 median_round(rounds[0]).ms_per_iter,
                 0,
                 grid_sorts[i],
                 {},
                 {}};
    for (std::size_t r = 0; r < rounds[i].size(); ++r) {
      row.rounds_ms.push_back(rounds[i][r].ms_per_iter);
      row.rounds_speedup.push_back(rounds[0][r].ms_per_iter / rounds[i][r].ms_per_iter);
    }
    row.neighbour_visits = neighbour_visits(w.topology, backends[i]->state(), w.params);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace animpak
