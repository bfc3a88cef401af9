// The run loop's stop test (docs/parameters.md, "Stop test") on a scripted backend whose statistics are
// chosen step by step: the gap test or a stall ends growth, the run then settles without growth until
// nothing overlaps or spills, and a settling that never comes clean ends as `unsettled`.
#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <limits>

#include "animpak/run.hpp"

using namespace animpak;

namespace {

// Statistics as a function of the iteration and of whether growth has stopped.
using Script = std::function<StepStatistics(std::uint64_t iteration, bool settling)>;

class ScriptedBackend final : public Backend {
 public:
  explicit ScriptedBackend(Script script, bool secondary = false) : script_(std::move(script)), secondary_(secondary) {}
  std::string name() const override { return "scripted"; }
  void step() override { ++state_.iteration; }
  StepStatistics statistics() override {
    StepStatistics st = script_(state_.iteration, state_.settling_since != 0);
    st.iteration = state_.iteration;
    return st;
  }
  SimState state() override { return state_; }
  void stop_growth() override {
    if (state_.settling_since == 0) state_.settling_since = state_.iteration;
  }
  bool start_secondary_growth() override {
    if (!secondary_ || state_.secondary_since != 0) return false;
    state_.secondary_since = state_.iteration;
    return true;
  }
  void set_progress_mark(const SimState& marks) override { copy_progress_marks(marks, state_); }
  const PhaseTimes& times() const override { return times_; }
  const SimState& current() const { return state_; }

 private:
  Script script_;
  bool secondary_ = false;
  SimState state_;
  PhaseTimes times_;
};

StepStatistics growing(double mean, float gap, std::int64_t overlapping) {
  StepStatistics st;
  st.mean_growth = mean;
  st.max_slice_gap = gap;
  st.overlapping_vertices = overlapping;
  return st;
}

Params run_params() {
  Params p;
  p.stop.check_interval = 10;
  p.stop.stall_window = 100;
  p.stop.stall_growth = 0.01;
  p.stop.stall_tests = 1;
  p.stop.settle_iterations = 300;
  return p;
}

RunResult run(Backend& backend, const Params& p) { return run_simulation(backend, p, RunControl{}); }

}  // namespace

TEST_CASE("run: the gap test with overlaps left starts settling, which stops when they are gone") {
  // Gap test passes at 500 with 7 overlapping vertices; settling clears them 120 steps later.
  ScriptedBackend b([](std::uint64_t i, bool settling) {
    const float gap = i >= 500 ? 0.001f : 0.1f;
    return growing(1.0 + 0.001 * double(i), gap, settling && i >= 620 ? 0 : 7);
  });
  const RunResult r = run(b, run_params());
  CHECK(r.reason == StopReason::gap);
  CHECK(r.last_good.settling_since == 500);
  CHECK(r.last_good.iteration == 620);
}

TEST_CASE("run: settling tests every step, so an overlap that flickers stops at its first clean step") {
  // The gap test passes at 500; settling leaves 3 vertices overlapping at every step but 617, between two
  // checks. A check every 10 steps alone never sees a clean step and ends unsettled at 800.
  ScriptedBackend b([](std::uint64_t i, bool settling) {
    const float gap = i >= 500 ? 0.001f : 0.1f;
    return growing(1.0 + 0.001 * double(i), gap, settling && i == 617 ? 0 : 3);
  });
  const RunResult r = run(b, run_params());
  CHECK(r.reason == StopReason::gap);
  CHECK(r.last_good.settling_since == 500);
  CHECK(r.last_good.iteration == 617);
  CHECK(r.last.iteration == 617);  // the statistics of the step it stopped on
}

TEST_CASE("run: a clean step between the checks that is not finite does not stop the settling") {
  // 613 reports nothing overlapping but a non-finite vertex: no stop there (a NaN that stays is the next
  // check's to report); the run goes on to the first clean, finite step.
  ScriptedBackend b([](std::uint64_t i, bool settling) {
    StepStatistics st = growing(1.0 + 0.001 * double(i), i >= 500 ? 0.001f : 0.1f, settling && i >= 640 ? 0 : 3);
    if (i == 613) st.overlapping_vertices = 0, st.finite = false, st.first_bad_vertex = 4;
    return st;
  });
  const RunResult r = run(b, run_params());
  CHECK(r.reason == StopReason::gap);
  CHECK(r.last_good.iteration == 640);
}

TEST_CASE("run: growing, the statistics are read only every check_interval steps") {
  // Nothing overlaps at 413, before growth has stopped: that is no stop, and no read between the checks.
  int reads = 0;
  ScriptedBackend b([&](std::uint64_t i, bool settling) {
    ++reads;
    return growing(1.0 + 0.001 * double(i), i >= 500 ? 0.001f : 0.1f, i == 413 || (settling && i >= 700) ? 0 : 3);
  });
  const RunResult r = run(b, run_params());
  CHECK(r.last_good.settling_since == 500);
  CHECK(r.last_good.iteration == 700);
  CHECK(reads == 50 + 200);  // checks at 10 ... 500, then every settling step 501 ... 700
}

TEST_CASE("run: growth that stalls short of the gap test settles and stops as stalled") {
  // Mean g rises until 400, then wobbles by less than 1 % per window; the gap never closes.
  ScriptedBackend b([](std::uint64_t i, bool settling) {
    const double mean = i < 400 ? 1.0 + 0.01 * double(i) : 5.0 + ((i / 10) % 2 ? 0.01 : 0.0);
    return growing(mean, 0.02f, settling && i >= 560 ? 0 : 3);
  });
  const RunResult r = run(b, run_params());
  CHECK(r.reason == StopReason::stalled);
  // Marks at 100, 200, 300, 400 (still rising); 500 compares with 400's 5.0: stalled.
  CHECK(r.last_good.settling_since == 500);
  CHECK(r.last_good.iteration == 560);
  CHECK(r.last_good.secondary_since == 0);  // no secondary elements: the stall settles at once
}

TEST_CASE("run: a stall test run four times a window stalls sooner after the rise ends") {
  // Mean g rises 0.01 a step to 5.3 at 430, then stays; windows of 80 steps, a 1 % rise. Four tests per
  // window test every 20 steps against the mark 80 back: 500 against 420's 5.2 (1.9 %) grows on, 520
  // against 440's 5.3 stalls. One test per window tests at 480 (against 400's 5.0) and 560 (480's 5.3).
  for (const int tests : {4, 1}) {
    Params p = run_params();
    p.stop.stall_window = 80;
    p.stop.stall_tests = tests;
    ScriptedBackend b([](std::uint64_t i, bool settling) {
      return growing(1.0 + 0.01 * double(std::min<std::uint64_t>(i, 430)), 0.02f, settling ? 0 : 3);
    });
    const RunResult r = run(b, p);
    INFO(tests << " tests per window");
    CHECK(r.reason == StopReason::stalled);
    CHECK(r.last_good.settling_since == (tests == 4 ? 520u : 560u));
  }
}

TEST_CASE("run: the stall test's marks are saved, so a resumed run tests against the same marks") {
  Params p = run_params();
  p.stop.stall_window = 80;
  p.stop.stall_tests = 4;
  auto script = [](std::uint64_t i, bool settling) {
    return growing(1.0 + 0.01 * double(std::min<std::uint64_t>(i, 430)), 0.02f, settling ? 0 : 3);
  };
  ScriptedBackend first(script);
  Params stopped_early = p;
  stopped_early.stop.max_iterations = 470;
  const RunResult part = run(first, stopped_early);
  REQUIRE(part.reason == StopReason::max_iterations);
  // Marks at 400, 420, 440, 460: the newest and the three before it.
  CHECK(part.last_good.mark_iteration == 460);
  CHECK(part.last_good.mark_growth == Approx(5.3));
  CHECK(part.last_good.mark_growth_1 == Approx(5.3));
  CHECK(part.last_good.mark_growth_2 == Approx(5.2));
  CHECK(part.last_good.mark_growth_3 == Approx(5.0));
  CHECK(first.current().mark_growth_3 == part.last_good.mark_growth_3);  // the backend holds them for its state
  ScriptedBackend resumed(script);
  resumed.set_progress_mark(part.last_good);
  for (std::uint64_t i = 0; i < 470; ++i) resumed.step();
  const RunResult r = run(resumed, p);
  CHECK(r.last_good.settling_since == 520);  // as without the interruption
}

TEST_CASE("run: settling that never comes clean ends as unsettled after settle_iterations") {
  ScriptedBackend b([](std::uint64_t i, bool) { return growing(1.0 + 0.001 * double(i), i >= 200 ? 0.0f : 0.1f, 2); });
  const RunResult r = run(b, run_params());
  CHECK(r.reason == StopReason::unsettled);
  CHECK(r.last_good.settling_since == 200);
  CHECK(r.last_good.iteration == 500);
}

TEST_CASE("run: a stall window of 0 turns the stall test off") {
  Params p = run_params();
  p.stop.stall_window = 0;
  p.stop.max_iterations = 1000;
  ScriptedBackend b([](std::uint64_t, bool) { return growing(2.0, 0.02f, 0); });
  const RunResult r = run(b, p);
  CHECK(r.reason == StopReason::max_iterations);
  CHECK(r.last_good.iteration == 1000);
}

TEST_CASE("run: params.stop.max_iterations counts from the start of the packing, not of this run") {
  Params p = run_params();
  p.stop.stall_window = 0;
  ScriptedBackend b([](std::uint64_t, bool) { return growing(2.0, 0.02f, 0); });
  for (int i = 0; i < 300; ++i) b.step();  // a resumed state
  p.stop.max_iterations = 350;
  const RunResult r = run(b, p);
  CHECK(r.reason == StopReason::max_iterations);
  CHECK(r.last_good.iteration == 350);
  p.stop.max_iterations = 320;  // already past it: no step
  const RunResult again = run(b, p);
  CHECK(again.reason == StopReason::max_iterations);
  CHECK(again.last_good.iteration == 350);
}

TEST_CASE("run: with secondary elements, the first stop starts their growth and a fresh stall window") {
  // Primary growth stalls at 400 (as in the test above); the secondary elements then grow the mean g
  // until 900, after which it wobbles. Settling clears the overlaps 60 steps after it starts.
  std::uint64_t started = 0;
  ScriptedBackend* self = nullptr;
  ScriptedBackend b(
      [&](std::uint64_t i, bool settling) {
        if (started == 0 && self->current().secondary_since != 0) started = self->current().secondary_since;
        double mean = i < 400 ? 1.0 + 0.01 * double(i) : 5.0 + ((i / 10) % 2 ? 0.01 : 0.0);
        if (started != 0) mean += 0.002 * double(std::min<std::uint64_t>(i, 900) - started);
        return growing(mean, 0.02f, settling && i >= 1060 ? 0 : 3);
      },
      true);
  self = &b;
  const RunResult r = run(b, run_params());
  CHECK(r.reason == StopReason::stalled);
  // 500 compares with 400's mark: stalled, so the secondary elements start instead of settling, with a
  // new mark at 500; marks at 600 ... 900 still rise; 1000 compares with 900: stalled, settling.
  CHECK(r.last_good.secondary_since == 500);
  CHECK(r.last_good.settling_since == 1000);
  CHECK(r.last_good.iteration == 1060);
}
