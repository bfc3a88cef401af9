// `animpak validate`'s comparison: the reference and an OpenCL device stepped side by side from one
// state, every force of Eq. 7 and every state array compared bit for bit (the kernels promise the
// reference's exact numbers: docs/architecture.md, "The twin rule"). The CLI only prints the result.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "animpak/opencl.hpp"
#include "animpak/params.hpp"
#include "animpak/state.hpp"

namespace animpak {

/// The worst of one error measure over every compared state: its value and where it occurs.
struct WorstError {
  double value = 0.0;
  std::int64_t state = -1;  ///< states after this many steps (0: the initial state)
  std::int32_t vertex = -1;
  char axis = ' ';  ///< 'x', 'y' or 't'
};

/// One force of Eq. 7 (or the total) compared at every checked state.
struct ForceComparison {
  std::string name;
  std::size_t differing = 0;      ///< vertex components whose bits differ, summed over the checked states
  std::int64_t first_state = -1;  ///< the first checked state where it differs
  WorstError abs, rel, ulp;
};

/// One SimState array or scalar (index "scalar": size 1, ulp 0) that differs after the first differing step.
struct StateMismatch {
  std::string array, index;  ///< e.g. "vx", "vertex"
  std::size_t count = 0, size = 0;
  std::size_t first = 0;                 ///< the first differing entry
  double reference = 0.0, device = 0.0;  ///< a float array's entry, or the scalar (a counter is exact)
  std::int64_t ulp = 0;
};

struct DeviceValidation {
  DeviceInfo device;
  std::string error;  ///< the OpenCL error that stopped the comparison; empty when it ran
  int steps = 0;
  std::vector<std::int64_t> checked_states;  ///< states whose forces were compared
  std::vector<ForceComparison> forces;       ///< the forces of Eq. 7 (breakdown_forces), then "total"
  std::int64_t first_differing_step = -1;    ///< -1: the states stayed identical
  std::vector<StateMismatch> mismatches;     ///< at first_differing_step

  std::int64_t max_ulp() const;
  bool identical() const { return error.empty() && max_ulp() == 0 && first_differing_step < 0; }
  /// "bit-identical", "error: ...", or "DIFFERS: " and the forces that differ first (at which state),
  /// else the first differing step: where to look first.
  std::string verdict() const;
};

/// Steps the reference and `device` `steps` times from `initial`, comparing the forces where both sides
/// rebuild their grid anyway (and at the last state) and the states after every step until they first
/// differ. OpenclError and std::invalid_argument (a topology the kernels cannot run) come through.
DeviceValidation validate_device(const Topology& topology, const SimState& initial, const Params& params,
                                 const DeviceInfo& device, int steps, GridSort sort);

}  // namespace animpak
