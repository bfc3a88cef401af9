// The scalar reference backend: one step of the simulation (paper §5) as plain C++ calls, phase by
// phase in the order the OpenCL backend enqueues its kernels (src/solver/opencl/opencl_backend.cpp).
#include <limits>

#include "animpak/reference.hpp"
#include "animpak/simulation.hpp"

namespace animpak {
namespace {

class ReferenceBackend final : public Backend {
 public:
  ReferenceBackend(const Topology& topology, SimState initial, const Params& params)
      : topo_(topology), state_(std::move(initial)), params_(params), step_(step_params(params)) {
    // Before the first step: no gap, no contact, nothing grown.
    closest_.assign(topo_.vertex_count(), std::numeric_limits<float>::infinity());
    contact_.assign(topo_.vertex_count(), 0);
    changed_.assign(topo_.slice_count(), 0);
  }

  std::string name() const override { return "reference"; }

  // One step: grid, forces, integration, constraints (§5.2, then containment), growth (§5.3); each
  // phase is timed on its own.
  void step() override {
    if (state_.iteration % static_cast<std::uint64_t>(params_.forces.grid_rebuild_interval) == 0 || grid_.n == 0) {
      PhaseStopwatch w(times_.grid);
      grid_ = reference::build_collision_grid(topo_, state_, params_);
    }
    StepForces forces;
    {
      PhaseStopwatch w(times_.forces);
      forces = reference::step_forces(topo_, state_, step_, grid_, nullptr);
    }
    {
      PhaseStopwatch w(times_.integrate);
      reference::integrate(forces.total, step_, state_);
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
      reference::propose_growth(topo_, forces.contact, forces.closest, step_, state_.settling_since == 0, state_,
                                proposed_);
      grown_ = reference::grow_slices(topo_, proposed_, step_, state_, changed_);
      reference::update_rest_lengths(topo_, changed_, state_);
    }
    closest_ = std::move(forces.closest);
    contact_ = std::move(forces.contact);
    ++state_.iteration;
  }

  StepStatistics statistics() override {
    PhaseStopwatch w(times_.statistics);
    reference::slice_statistics(topo_, state_, closest_, contact_, changed_, slices_);
    StepStatistics st;
    st.iteration = state_.iteration;
    reduce_slice_statistics(slices_, state_.growth, grown_, st);
    return st;
  }

  SimState state() override { return state_; }
  void stop_growth() override {
    if (state_.settling_since == 0) state_.settling_since = state_.iteration;
  }
  bool start_secondary_growth() override {
    if (state_.secondary_since != 0 || !topo_.has_secondary()) return false;
    state_.secondary_since = state_.iteration;
    return true;
  }
  void set_progress_mark(const SimState& marks) override { copy_progress_marks(marks, state_); }
  const PhaseTimes& times() const override { return times_; }

 private:
  Topology topo_;
  SimState state_;
  Params params_;     ///< the grid's settings (grid_rebuild_interval, cell_size, far_cells)
  ForceParams step_;  ///< every float constant of the step, converted once (animpak/step_params.hpp)
  CollisionGrid grid_;
  std::vector<float> closest_;
  std::vector<std::uint8_t> contact_, changed_;
  std::vector<float> proposed_;
  SliceStatistics slices_;
  std::int32_t grown_ = 0;
  PhaseTimes times_;
};

}  // namespace

std::unique_ptr<Backend> make_reference_backend(const Topology& topology, SimState initial, const Params& params) {
  return std::make_unique<ReferenceBackend>(topology, std::move(initial), params);
}

}  // namespace animpak
