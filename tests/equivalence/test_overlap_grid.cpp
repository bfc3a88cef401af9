// The overlap test's broadphase as the OpenCL backend builds it: on the host, the reference's grid
// exactly; on the device (kernels/overlap_grid.cl), a grid of its own rule that must list every
// element whose slice-pair box meets a cell, in increasing order, or the box test would miss an
// overlap. When its lists outgrow their room the device drops the grid for the step and the forces
// stay those of the reference.
#include <algorithm>

#include "equivalence_support.hpp"

namespace animpak::test {
namespace {

// The reference's slice boxes of w's state (the device's are equal, bit for bit: the forces suite).
SliceBoxes reference_boxes(const TinyWorld& w) {
  SliceBoxes boxes;
  CurveTangents tangents;
  reference::curve_tangents(w.topo, w.state, Params{}.forces.motion_curve, tangents);
  reference::slice_boxes(w.topo, w.state, tangents, boxes);
  return boxes;
}

// What is wrong with `g` as a broadphase of `boxes`: a cell list out of order, or a slice pair whose
// element is missing from a cell its box meets; empty when nothing is.
std::string broadphase_fault(const TinyWorld& w, const SliceBoxes& boxes, const OverlapGrid& g) {
  std::ostringstream out;
  const std::size_t cells = static_cast<std::size_t>(g.nx) * g.ny * g.nt;
  if (g.cell_start.size() != cells + 1) return "cell_start has " + std::to_string(g.cell_start.size()) + " entries";
  for (std::size_t c = 0; c < cells; ++c)
    for (std::int32_t k = g.cell_start[c] + 1; k < g.cell_start[c + 1]; ++k)
      if (g.elements[k] < g.elements[k - 1]) out << "cell " << c << " out of order at " << k << "\n";
  for (std::int32_t e = 0; e < w.topo.element_count(); ++e)
    for (std::int32_t s = w.topo.element_slice_begin[e]; s + 1 < w.topo.element_slice_begin[e + 1]; ++s) {
      const float x0 = std::min(boxes.x0[s], boxes.x0[s + 1]), x1 = std::max(boxes.x1[s], boxes.x1[s + 1]);
      const float y0 = std::min(boxes.y0[s], boxes.y0[s + 1]), y1 = std::max(boxes.y1[s], boxes.y1[s + 1]);
      const float t0 = std::min(boxes.t[s], boxes.t[s + 1]), t1 = std::max(boxes.t[s], boxes.t[s + 1]);
      using reference::grid_axis_cell;
      for (std::int32_t it = grid_axis_cell(t0 - g.t0, g.cell_t, g.nt); it <= grid_axis_cell(t1 - g.t0, g.cell_t, g.nt);
           ++it)
        for (std::int32_t iy = grid_axis_cell(y0 - g.y0, g.cell, g.ny); iy <= grid_axis_cell(y1 - g.y0, g.cell, g.ny);
             ++iy)
          for (std::int32_t ix = grid_axis_cell(x0 - g.x0, g.cell, g.nx); ix <= grid_axis_cell(x1 - g.x0, g.cell, g.nx);
               ++ix) {
            const std::size_t c = (static_cast<std::size_t>(it) * g.ny + iy) * g.nx + ix;
            const auto begin = g.elements.begin() + g.cell_start[c], end = g.elements.begin() + g.cell_start[c + 1];
            if (std::find(begin, end, e) == end)
              out << "element " << e << " (slice pair " << s << ") missing from cell " << c << "\n";
          }
    }
  return out.str();
}

// How many slice pairs w has.
std::int32_t slice_pairs(const TinyWorld& w) {
  std::int32_t n = 0;
  for (std::int32_t e = 0; e < w.topo.element_count(); ++e)
    n += std::max(0, w.topo.element_slice_begin[e + 1] - w.topo.element_slice_begin[e] - 1);
  return n;
}

}  // namespace

TEST_CASE("overlap broadphase: the host's is the reference's, the device's lists every pair in every cell it meets",
          "[equivalence][opencl]") {
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  for (std::uint64_t seed = 31; seed <= 34; seed += seed_stride()) {
    RandomWorldShape shape;
    shape.elements = seed <= 32 ? 60 : 5;  // many small elements, and a few large ones crossing the container
    shape.min_radius = seed <= 32 ? 0.02f : 0.1f;
    shape.max_radius = seed <= 32 ? 0.06f : 0.25f;
    const TinyWorld w = random_world(seed, shape);
    const SliceBoxes boxes = reference_boxes(w);
    OverlapGrid expected;
    reference::build_overlap_grid(w.topo, boxes, expected);
    REQUIRE(expected.nx > 0);
    for (const DeviceChoice& d : devices) {
      INFO("seed " << seed << " on " << d.device.name);
      const OverlapGrid host =
          make_opencl_backend(w.topo, w.state, Params{}, d, GridSort::host)->build_and_read_overlap_grid();
      CHECK(host.nx == expected.nx);
      CHECK(host.ny == expected.ny);
      CHECK(host.nt == expected.nt);
      CHECK(host.cell_start == expected.cell_start);
      CHECK(host.elements == expected.elements);

      const OverlapGrid device =
          make_opencl_backend(w.topo, w.state, Params{}, d, GridSort::device)->build_and_read_overlap_grid();
      REQUIRE(device.nx > 0);  // a grid, not the every-element fallback
      CHECK(static_cast<long>(device.nx) * device.ny * device.nt <= 8L * slice_pairs(w) + 64);
      // A cell the size of the mean box: each pair meets a few cells, not all of them.
      CHECK(device.elements.size() < 16 * static_cast<std::size_t>(slice_pairs(w)));
      const std::string fault = broadphase_fault(w, boxes, device);
      INFO(fault);
      CHECK(fault.empty());
    }
  }
}

TEST_CASE("overlap broadphase: a device build that outgrows its room drops the grid for the step, then gets room",
          "[equivalence][opencl]") {
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  int overlapping = 0;
  for (std::uint64_t seed = 1; seed <= 6; seed += seed_stride()) {
    RandomWorldShape shape;
    shape.elements = 3 + static_cast<int>(seed % 4);
    shape.max_radius = 0.2f;  // elements that overlap, so the box test decides some forces
    const TinyWorld w = random_world(seed, shape);
    const Params params;
    const CollisionGrid grid = reference::build_collision_grid(w.topo, w.state, params);
    const StepForces ref = reference::step_forces(w.topo, w.state, step_params(params), grid, nullptr);
    overlapping += static_cast<int>(
        std::count_if(ref.contact.begin(), ref.contact.end(), [](auto c) { return (c & contact_overlap) != 0; }));
    for (const DeviceChoice& d : devices) {
      INFO("seed " << seed << " on " << d.device.name);
      auto backend = make_opencl_backend(w.topo, w.state, params, d, GridSort::device);
      backend->set_overlap_room(3);
      const StepForces dev = backend->evaluate_forces(nullptr);
      const std::string diff =
          bit_difference("total.x", ref.total.x, dev.total.x) + bit_difference("total.y", ref.total.y, dev.total.y) +
          bit_difference("total.t", ref.total.t, dev.total.t) + bit_difference("contact", ref.contact, dev.contact);
      INFO(diff);
      CHECK(diff.empty());
      CHECK(backend->build_and_read_overlap_grid().nx == 0);  // dropped: every query tried every element
      backend->statistics();                                  // reads the lists' total and makes room
      const OverlapGrid after = backend->build_and_read_overlap_grid();
      CHECK(after.nx > 0);
      const std::string fault = broadphase_fault(w, reference_boxes(w), after);
      INFO(fault);
      CHECK(fault.empty());
    }
  }
  CHECK(overlapping > 0);  // the box test decided some forces
}

}  // namespace animpak::test
