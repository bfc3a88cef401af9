// Shared pieces of the equivalence suite (docs/architecture.md, "The twin rule"): the devices under
// test, bit-for-bit comparison of arrays with the worst mismatch in ULPs, and seeded random worlds
// built with the solver tests' WorldBuilder.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "animpak/compare.hpp"
#include "animpak/opencl.hpp"
#include "skip.hpp"
#include "solver/tiny_worlds.hpp"

namespace animpak::test {

/// Both places the grids (the collision grid's counting sort, the overlap test's broadphase) can be
/// built; every device is tested with each, since a device may use either (automatic picks by device
/// type, --grid-sort overrides).
inline constexpr GridSort grid_sorts[] = {GridSort::host, GridSort::device};

/// The OpenCL devices to test: the one ANIMPAK_TEST_DEVICE names, or every device present but
/// simulators (Oclgrind takes tens of minutes over the suite; scripts/oclgrind-check.sh names it).
inline std::vector<DeviceChoice> devices_under_test() {
  std::vector<DeviceChoice> out;
  if (const char* wanted = std::getenv("ANIMPAK_TEST_DEVICE"); wanted != nullptr && *wanted != '\0') {
    DeviceChoice c = choose_device(wanted);
    if (!c.reference) out.push_back(c);
    return out;
  }
  for (const DeviceInfo& d : list_devices()) {
    if (d.simulator) continue;
    DeviceChoice c;
    c.reference = false;
    c.device = d;
    out.push_back(c);
  }
  return out;
}

/// Every how many seeds the cases over several random worlds check: 1 (each) unless
/// ANIMPAK_EQUIVALENCE_SEED_STRIDE asks for more. scripts/oclgrind-check.sh sets 2: on the simulator,
/// whose checks are of memory access and not of numbers, half the worlds cover the same kernel code
/// in half the time (docs/testing.md).
inline std::uint64_t seed_stride() {
  const char* text = std::getenv("ANIMPAK_EQUIVALENCE_SEED_STRIDE");
  if (text == nullptr || *text == '\0') return 1;
  const long stride = std::strtol(text, nullptr, 10);
  return stride >= 1 ? static_cast<std::uint64_t>(stride) : 1;
}

/// True, after skipping the test (tests/skip.hpp), when there is no device to test (none installed, or
/// none that ANIMPAK_TEST_DEVICE names); the caller returns at once.
inline bool skip_without_devices(const std::vector<DeviceChoice>& devices) {
  if (!devices.empty()) return false;
  skip(
      "no OpenCL device (or none matching ANIMPAK_TEST_DEVICE; Debian package pocl-opencl-icd): "
      "nothing was compared");
  return true;
}

/// Empty when `actual` matches `expected` bit for bit; otherwise names the array, the number of
/// differing entries, the first and the worst (index, both values, ULPs).
template <typename T>
std::string bit_difference(const std::string& what, const std::vector<T>& expected, const std::vector<T>& actual) {
  std::ostringstream s;
  s.precision(9);
  if (expected.size() != actual.size()) {
    s << what << ": " << expected.size() << " reference values, " << actual.size() << " device values";
    return s.str();
  }
  std::size_t count = 0, first = 0, worst = 0;
  std::int64_t worst_ulps = -1;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    std::int64_t ulps = 0;
    if constexpr (std::is_same_v<T, float>)
      ulps = ulp_distance(expected[i], actual[i]);
    else
      ulps = expected[i] == actual[i] ? 0 : 1;
    if (ulps == 0) continue;
    if (count++ == 0) first = i;
    if (ulps > worst_ulps) worst_ulps = ulps, worst = i;
  }
  if (count == 0) return {};
  auto entry = [&](std::size_t i) {
    std::ostringstream e;
    e.precision(9);
    e << "[" << i << "] reference " << +expected[i] << " device " << +actual[i];
    if constexpr (std::is_same_v<T, float>) e << " (" << ulp_distance(expected[i], actual[i]) << " ulp)";
    return e.str();
  };
  s << what << ": " << count << " of " << expected.size() << " differ; first " << entry(first) << "; worst "
    << entry(worst);
  return s.str();
}

/// Compares every force component of two breakdowns; returns all differences, one line each.
inline std::string breakdown_difference(const ForceBreakdown& ref, const ForceBreakdown& dev) {
  std::string out;
  for (const NamedForce& force : breakdown_forces) {
    const std::string n(force.name);
    const ForceField &r = ref.*force.field, &d = dev.*force.field;
    for (const std::string& line :
         {bit_difference(n + ".x (vertex)", r.x, d.x), bit_difference(n + ".y (vertex)", r.y, d.y),
          bit_difference(n + ".t (vertex)", r.t, d.t)})
      if (!line.empty()) out += line + "\n";
  }
  return out;
}

/// Compares every array and scalar of two states bit for bit; returns all differences, one line each.
inline std::string state_difference(const SimState& ref, const SimState& dev) {
  std::string out;
  for (const NamedStateArray& a : state_arrays) {
    const std::string d = bit_difference(a.name, ref.*a.array, dev.*a.array);
    if (!d.empty()) out += d + "\n";
  }
  for (const NamedStateScalar& s : state_scalars) {
    if (s.bits(ref) == s.bits(dev)) continue;
    std::ostringstream line;
    line.precision(17);
    line << s.name << ": reference " << s.value(ref) << " device " << s.value(dev) << "\n";
    out += line.str();
  }
  return out;
}

/// The rest copy growth scales (rest_copy_x, slice_rest_copy_cx, ...), taken from the state as built.
inline void fill_reference_copy(TinyWorld& w) {
  w.topo.rest_copy_x = w.state.x;
  w.topo.rest_copy_y = w.state.y;
  w.topo.rest_copy_t = w.state.t;
  reference::slice_centroids(w.topo, w.state, w.topo.slice_rest_copy_cx, w.topo.slice_rest_copy_cy);
}

struct RandomWorldShape {
  int elements = 4;
  int slices = 5;
  int ring = 6;  ///< boundary vertices per slice
  float min_radius = 0.03f, max_radius = 0.12f;
  bool hole = true;     ///< a square hole in the container
  bool targets = true;  ///< target points on element 0's first and last slices, which hold their angle
};

/// Ring elements at random places (so some overlap, some cross the container or the hole), random
/// extra springs of every class, random velocities and growth, loop pairs on every element.
inline TinyWorld random_world(std::uint64_t seed, const RandomWorldShape& shape = {}) {
  std::mt19937 rng(static_cast<std::uint32_t>(seed));
  auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
  WorldBuilder b;
  if (shape.hole) b.set_container({square(0.5f, 0.5f, 0.5f), square(uniform(0.3f, 0.7f), uniform(0.3f, 0.7f), 0.08f)});
  for (int e = 0; e < shape.elements; ++e) {
    const float cx = uniform(0.0f, 1.0f), cy = uniform(0.0f, 1.0f), r = uniform(shape.min_radius, shape.max_radius);
    std::vector<TinySlice> slices;
    for (int s = 0; s < shape.slices; ++s) {
      TinySlice sl;
      const float base = shape.slices > 1 ? float(s) / float(shape.slices - 1) : 0.0f;
      sl.t = std::min(1.0f, std::max(0.0f, base + uniform(-0.02f, 0.02f)));
      const float dx = uniform(-0.03f, 0.03f), dy = uniform(-0.03f, 0.03f);
      for (int k = 0; k < shape.ring; ++k) {
        const float a = 6.2831853f * (float(k) + uniform(-0.2f, 0.2f)) / float(shape.ring);
        const float rr = r * uniform(0.6f, 1.2f);
        sl.ring.push_back({cx + dx + rr * std::cos(a), cy + dy + rr * std::sin(a)});
      }
      slices.push_back(sl);
    }
    b.add_element(slices);
  }
  const std::int32_t per_element = shape.slices * shape.ring;
  for (int e = 0; e < shape.elements; ++e) {
    const std::int32_t base = e * per_element;
    for (int k = 0; k < shape.ring; ++k) b.add_loop(base + (shape.slices - 1) * shape.ring + k, base + k);
    for (int s = 0; s < shape.slices; ++s) {
      const std::int32_t first = base + s * shape.ring;
      b.add_spring(first, first + shape.ring / 2, SpringClass::shear);
      b.add_spring(first + 1, first + shape.ring / 2 + 1, SpringClass::negative_space, uniform(0.0f, 0.1f));
    }
  }
  const bool targets = shape.targets && shape.elements > 0;
  // Targets on keyed slices only (paper §4): the first and last slice of element 0, none in between.
  const std::int32_t last_slice = (shape.slices - 1) * shape.ring;
  if (targets) b.add_target(0, uniform(0.2f, 0.8f), uniform(0.2f, 0.8f), 0.0f);
  if (targets && last_slice > 0) b.add_target(last_slice, uniform(0.2f, 0.8f), uniform(0.2f, 0.8f), 1.0f);
  TinyWorld out = b.build();
  if (targets)
    for (int k = 0; k < shape.ring; ++k) {
      out.topo.flags[k] |= vertex_hold_angle;
      out.topo.flags[last_slice + k] |= vertex_hold_angle;
    }
  fill_reference_copy(out);
  for (std::size_t v = 0; v < out.state.x.size(); ++v) {
    out.state.vx[v] = uniform(-0.001f, 0.001f);
    out.state.vy[v] = uniform(-0.001f, 0.001f);
    out.state.vt[v] = uniform(-0.001f, 0.001f);
  }
  for (float& g : out.state.growth) g = uniform(1.0f, 1.5f);
  return out;
}

}  // namespace animpak::test
