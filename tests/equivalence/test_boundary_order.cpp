// The repulsion kernel's work order (src/solver/opencl/boundary_order.hpp): the boundary vertices
// sorted by grid cell, on the host from positions read back or on the device with the collision grid's
// counting-sort kernels. The order does not change the forces (the equivalence suite's steps run both
// places against the reference); these cases check that each place gives every boundary vertex once,
// in cell order, and that a device step then reads nothing back to the host.
#include <algorithm>

#include "equivalence_support.hpp"

namespace animpak::test {
namespace {

// What is wrong with `order` as w's boundary vertices sorted by `grid`'s cells: a vertex missing or
// twice, or a cell smaller than the one before; empty when nothing is.
std::string order_fault(const TinyWorld& w, const CollisionGrid& grid, std::vector<std::int32_t> order) {
  std::vector<std::int32_t> boundary;
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v)
    if ((w.topo.flags[v] & vertex_boundary) != 0) boundary.push_back(v);
  std::ostringstream out;
  std::int32_t last = -1;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::int32_t v = order[i];
    if (v < 0 || v >= w.topo.vertex_count()) return "entry " + std::to_string(i) + " is no vertex";
    const std::int32_t cell = grid_linear_cell(w.state.x[v], w.state.y[v], w.state.t[v], grid.cell, grid.n);
    if (cell < last) out << "entry " << i << " (vertex " << v << ") in cell " << cell << " after cell " << last << "\n";
    last = cell;
  }
  std::sort(order.begin(), order.end());
  if (order != boundary) out << order.size() << " entries are not the " << boundary.size() << " boundary vertices\n";
  return out.str();
}

}  // namespace

TEST_CASE("repulsion order: the host and the device list every boundary vertex once, by grid cell",
          "[equivalence][opencl]") {
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  for (std::uint64_t seed = 41; seed <= 44; seed += seed_stride()) {
    RandomWorldShape shape;
    shape.elements = seed <= 42 ? 60 : 5;  // many small elements, and a few large ones crossing the container
    shape.min_radius = seed <= 42 ? 0.02f : 0.1f;
    shape.max_radius = seed <= 42 ? 0.06f : 0.25f;
    const TinyWorld w = random_world(seed, shape);
    const Params params;
    const CollisionGrid grid = reference::build_collision_grid(w.topo, w.state, params);
    for (const DeviceChoice& d : devices)
      for (const GridSort sort : {GridSort::host, GridSort::device}) {
        INFO("seed " << seed << " on " << d.device.name << ", sorted on the " << grid_sort_name(sort));
        auto backend = make_opencl_backend(w.topo, w.state, params, d, sort);
        const std::string fault = order_fault(w, grid, backend->refresh_and_read_boundary_order());
        INFO(fault);
        CHECK(fault.empty());
      }
  }
}

TEST_CASE("repulsion order: a device step reads nothing back, a host one refreshes the order from positions read",
          "[equivalence][opencl]") {
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  RandomWorldShape shape;
  shape.elements = 8;
  const TinyWorld w = random_world(45, shape);
  for (const DeviceChoice& d : devices)
    for (const GridSort sort : {GridSort::host, GridSort::device}) {
      INFO(d.device.name << ", grids on the " << grid_sort_name(sort));
      auto backend = make_opencl_backend(w.topo, w.state, Params{}, d, sort);
      for (int i = 0; i < 3; ++i) backend->step();
      backend->finish();
      std::vector<std::string> host_rows, device_sort;
      for (const KernelTime& k : backend->kernel_times()) {
        if (k.name.rfind("host:", 0) == 0) host_rows.push_back(k.name);
        if (k.name == "boundary_cells") device_sort.push_back(k.name);
      }
      if (sort == GridSort::device) {
        CHECK(host_rows.empty());  // neither grid, nor the repulsion order, waits for the host
        CHECK(device_sort.size() == 1);
      } else {
        CHECK(std::find(host_rows.begin(), host_rows.end(), "host: repulsion order") != host_rows.end());
        CHECK(device_sort.empty());
      }
    }
}

}  // namespace animpak::test
