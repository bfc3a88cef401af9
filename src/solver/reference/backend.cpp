#include <chrono>
#include <cmath>
#include <limits>

#include "animpak/reference.hpp"
#include "animpak/simulation.hpp"

namespace animpak {
namespace {

class ReferenceBackend final : public Backend {
 public:
  ReferenceBackend(const Topology& topology, SimState initial, const Params& params)
      : topo_(topology), state_(std::move(initial)), params_(params) {
    slice_gap_.assign(topo_.slice_count(), std::numeric_limits<float>::infinity());
    contact_.assign(topo_.vertex_count(), 0);
  }

  std::string name() const override { return "reference"; }

  // One step: grid, forces, integration, constraints (§5.2, then containment), growth (§5.3); each
  // phase is timed on its own.
  void step() override {
    if (state_.iteration % static_cast<std::uint64_t>(params_.grid_rebuild_interval) == 0 || grid_.n == 0) {
      PhaseStopwatch w(times_.grid);
      grid_ = reference::build_collision_grid(topo_, state_, params_);
    }
    reference::StepForces forces;
    {
      PhaseStopwatch w(times_.forces);
      forces = reference::step_forces(topo_, state_, params_, grid_, nullptr);
    }
    {
      PhaseStopwatch w(times_.integrate);
      reference::integrate(forces.total, params_, state_);
    }
    {
      PhaseStopwatch w(times_.constraints);
      for (std::int32_t e = 0; e < topo_.element_count(); ++e) {
        reference::apply_end_to_end(topo_, state_, e);
        reference::apply_simultaneity(topo_, state_, e);
      }
    }
    {
      PhaseStopwatch w(times_.loop);
      reference::apply_loop(topo_, state_);
    }
    {
      PhaseStopwatch w(times_.constraints);
      reference::apply_containment(topo_, state_);
    }
    {
      PhaseStopwatch w(times_.growth);
      grown_ = reference::grow_slices(topo_, forces.contact, params_, state_.settling_since == 0, state_, changed_);
      reference::update_rest_lengths(topo_, changed_, state_);
    }
    {
      PhaseStopwatch w(times_.statistics);
      for (std::int32_t s = 0; s < topo_.slice_count(); ++s) {
        float gap = std::numeric_limits<float>::infinity();
        for (std::int32_t v = topo_.slice_begin[s]; v < topo_.slice_begin[s + 1]; ++v)
          gap = forces.closest[v] < gap ? forces.closest[v] : gap;
        // A slice its element's growth_ratio holds back cannot grow: it counts as touching.
        slice_gap_[s] = (changed_[s] & reference::growth_held) != 0 ? 0.0f : gap;
      }
      contact_ = std::move(forces.contact);
    }
    ++state_.iteration;
  }

  StepStatistics statistics() override {
    PhaseStopwatch w(times_.statistics);
    StepStatistics st;
    st.iteration = state_.iteration;
    reduce_slice_statistics(slice_gap_, state_.growth, grown_, st);
    for (const std::uint8_t c : contact_) {
      st.overlapping_vertices += (c & contact_overlap) != 0;
      st.outside_vertices += (c & contact_outside) != 0;
    }
    for (std::int32_t v = 0; v < topo_.vertex_count() && st.finite; ++v) {
      const bool ok = std::isfinite(state_.x[v]) && std::isfinite(state_.y[v]) && std::isfinite(state_.t[v]) &&
                      std::isfinite(state_.vx[v]) && std::isfinite(state_.vy[v]) && std::isfinite(state_.vt[v]);
      if (!ok) st.finite = false, st.first_bad_vertex = v;
    }
    return st;
  }

  SimState state() override { return state_; }
  void stop_growth() override {
    if (state_.settling_since == 0) state_.settling_since = state_.iteration;
  }
  void set_progress_mark(std::uint64_t iteration, double mean_growth) override {
    state_.mark_iteration = iteration;
    state_.mark_growth = mean_growth;
  }
  const PhaseTimes& times() const override { return times_; }

 private:
  Topology topo_;
  SimState state_;
  Params params_;
  reference::CollisionGrid grid_;
  std::vector<float> slice_gap_;
  std::vector<std::uint8_t> contact_, changed_;
  std::int32_t grown_ = 0;
  PhaseTimes times_;
};

}  // namespace

void reduce_slice_statistics(const std::vector<float>& slice_gap, const std::vector<float>& growth,
                             std::int32_t grown, StepStatistics& st) {
  st.max_slice_gap = 0.0f;
  st.min_slice_gap = std::numeric_limits<float>::infinity();
  for (const float g : slice_gap) {
    st.max_slice_gap = g > st.max_slice_gap ? g : st.max_slice_gap;
    st.min_slice_gap = g < st.min_slice_gap ? g : st.min_slice_gap;
  }
  st.growing_share = slice_gap.empty() ? 0.0 : double(grown) / double(slice_gap.size());
  st.min_growth = st.max_growth = growth.empty() ? 1.0f : growth[0];
  double sum = 0.0;
  for (const float g : growth) {
    st.min_growth = g < st.min_growth ? g : st.min_growth;
    st.max_growth = g > st.max_growth ? g : st.max_growth;
    sum += g;
  }
  st.mean_growth = growth.empty() ? 1.0 : sum / double(growth.size());
}

const char* stop_reason_name(StopReason r) {
  switch (r) {
    case StopReason::running: return "running";
    case StopReason::gap: return "gap";
    case StopReason::stalled: return "stalled";
    case StopReason::unsettled: return "unsettled";
    case StopReason::growth: return "growth";
    case StopReason::max_iterations: return "max_iterations";
    case StopReason::interrupted: return "interrupted";
    case StopReason::non_finite: return "non_finite";
  }
  return "unknown";
}

std::unique_ptr<Backend> make_reference_backend(const Topology& topology, SimState initial, const Params& params) {
  return std::make_unique<ReferenceBackend>(topology, std::move(initial), params);
}

}  // namespace animpak
