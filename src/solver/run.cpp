#include "animpak/run.hpp"

#include <algorithm>
#include <chrono>

#include "animpak/step_params.hpp"

namespace animpak {

const char* stop_reason_name(StopReason r) {
  switch (r) {
    case StopReason::running:
      return "running";
    case StopReason::gap:
      return "gap";
    case StopReason::stalled:
      return "stalled";
    case StopReason::unsettled:
      return "unsettled";
    case StopReason::growth:
      return "growth";
    case StopReason::max_iterations:
      return "max_iterations";
    case StopReason::interrupted:
      return "interrupted";
    case StopReason::non_finite:
      return "non_finite";
  }
  return "unknown";
}

RunResult run_simulation(Backend& backend, const Params& params, const RunControl& control) {
  const auto start = std::chrono::steady_clock::now();
  RunResult result;
  result.last_good = backend.state();
  std::uint64_t iteration = result.last_good.iteration;
  const auto rebuild = static_cast<std::uint64_t>(params.forces.grid_rebuild_interval);
  const auto check = static_cast<std::uint64_t>(params.stop.check_interval);
  const auto max_iterations = static_cast<std::uint64_t>(std::max(params.stop.max_iterations, 0));
  // The gap the step's contact test uses (the wall's contact_wall), from the same block.
  const float stop_gap = step_params(params).stop_gap;
  // Nothing overlapping another element and nothing outside the container: what a settling run waits for.
  const auto clean_step = [](const StepStatistics& st) {
    return st.overlapping_vertices == 0 && st.outside_vertices == 0;
  };
  const std::uint64_t first = iteration;
  auto last_checkpoint = start;
  for (;;) {
    // A checkpoint where an interrupt would save (a grid-rebuild boundary) and only right after a finite
    // check, so that it never holds a NaN the next check would have caught.
    if (control.on_checkpoint && iteration != first && iteration == result.last_good.iteration &&
        iteration % rebuild == 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_checkpoint).count() >=
            control.checkpoint_seconds) {
      control.on_checkpoint(backend.state());
      last_checkpoint = std::chrono::steady_clock::now();
    }
    // An interrupt is honoured on a grid-rebuild boundary, so a resumed run rebuilds the grid at the
    // same steps as an uninterrupted one and stays bit-identical.
    if (control.interrupt && control.interrupt->load() && iteration % rebuild == 0) {
      result.reason = StopReason::interrupted;
      break;
    }
    if (iteration >= max_iterations) {
      result.reason = StopReason::max_iterations;
      break;
    }
    backend.step();
    ++iteration;
    // While settling, the overlaps left flicker in and out as the meshes relax, so a statistics check
    // every check_interval steps rarely lands on a clean step: a settling run reads the statistics after
    // every step (docs/parameters.md, "Stop test"). Between the checks only a clean, finite step goes on
    // to the checks below (where it stops the run); the others wait for the next regular check, so the
    // marks and the last good state stay on its grid.
    const bool at_check = iteration % check == 0;
    if (!at_check && result.last_good.settling_since == 0) continue;
    const StepStatistics now = backend.statistics();
    if (!at_check && !(now.finite && clean_step(now))) continue;
    result.last = now;
    if (!result.last.finite) {
      result.reason = StopReason::non_finite;
      break;
    }
    result.last_good = backend.state();
    if (control.on_check) control.on_check(result.last);
    // §5.3's gap test ends growth; then the packing settles without growing until nothing overlaps or
    // spills (docs/parameters.md, "Stop test"), so a packing that stops is one the solver sees as correct.
    const bool clean = clean_step(result.last);
    std::uint64_t settling_since = result.last_good.settling_since;
    // The stall test's progress mark, here and in the state the backend saves: the mean g now, the
    // marks before it moved one back (`fresh`: none before it, as when the secondary elements start).
    const auto mark_progress = [&](bool fresh) {
      SimState& m = result.last_good;
      m.mark_growth_3 = fresh ? 0.0 : m.mark_growth_2;
      m.mark_growth_2 = fresh ? 0.0 : m.mark_growth_1;
      m.mark_growth_1 = fresh || m.mark_iteration == 0 ? 0.0 : m.mark_growth;
      m.mark_iteration = iteration;
      m.mark_growth = result.last.mean_growth;
      backend.set_progress_mark(m);
    };
    // Growth can also stall short of the gap test, in a steady exchange of slices that grow into a
    // neighbour and shrink back: the mean g then no longer rises over a window of stall_window steps.
    // The test runs stall_tests times per window, a mark each time, and compares the mean g with the
    // mark one window back (docs/parameters.md, "Stop test").
    bool stalled = false;
    const auto window = static_cast<std::uint64_t>(params.stop.stall_window);
    const int tests = std::clamp(params.stop.stall_tests, 1, 4);
    const std::uint64_t spacing = std::max<std::uint64_t>(1, window / static_cast<std::uint64_t>(tests));
    if (settling_since == 0 && window > 0 && iteration >= result.last_good.mark_iteration + spacing) {
      const SimState& m = result.last_good;
      const double back[4] = {m.mark_iteration != 0 ? m.mark_growth : 0.0, m.mark_growth_1, m.mark_growth_2,
                              m.mark_growth_3};
      const double window_ago = back[tests - 1];  // 0: the run is not a window in yet
      stalled = window_ago > 0.0 && !(result.last.mean_growth > window_ago * (1.0 + params.stop.stall_growth));
      if (!stalled) mark_progress(false);
    }
    // A clean stop is `gap` when every slice touches a neighbour or the wall, `stalled` otherwise.
    const bool touching = result.last.max_slice_gap < stop_gap;
    if (settling_since == 0 && (stalled || touching)) {
      // Secondary elements (docs/parameters.md, "Secondary elements") wait for the primary ones to stop;
      // then they grow, and the stall test starts a fresh window for them.
      if (backend.start_secondary_growth()) {
        result.last_good.secondary_since = iteration;
        mark_progress(true);
        continue;
      }
      if (clean) {
        result.reason = touching ? StopReason::gap : StopReason::stalled;
        break;
      }
      backend.stop_growth();
      settling_since = iteration;
      result.last_good.settling_since = settling_since;
    } else if (settling_since != 0 && clean) {
      result.reason = touching ? StopReason::gap : StopReason::stalled;
      break;
    }
    if (settling_since != 0 &&
        iteration - settling_since >= static_cast<std::uint64_t>(params.stop.settle_iterations)) {
      result.reason = StopReason::unsettled;
      break;
    }
    if (params.stop.stop_growth > 0.0 && result.last.min_growth >= static_cast<float>(params.stop.stop_growth)) {
      result.reason = StopReason::growth;
      break;
    }
  }
  // last_good is the present state unless steps ran since the last check.
  if (result.reason != StopReason::non_finite && result.last_good.iteration != iteration)
    result.last_good = backend.state();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace animpak
