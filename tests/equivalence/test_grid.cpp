// Grid equivalence: envelope centroids and cells computed by the envelope_cells kernel, sorted by the
// host's counting sort and by the device's, against reference::build_collision_grid.
#include "equivalence_support.hpp"

namespace animpak::test {
namespace {

void check_grid(const TinyWorld& w, const Params& params, const std::string& label) {
  const CollisionGrid ref = reference::build_collision_grid(w.topo, w.state, params);
  for (const DeviceChoice& d : devices_under_test())
    for (const GridSort sort : grid_sorts) {
      const CollisionGrid dev = make_opencl_backend(w.topo, w.state, params, d, sort)->build_and_read_grid();
      CHECK(dev.n == ref.n);
      CHECK(dev.cell == ref.cell);
      const std::string diff = bit_difference("centroid x", ref.cx, dev.cx) +
                               bit_difference("centroid y", ref.cy, dev.cy) +
                               bit_difference("centroid t", ref.ct, dev.ct) +
                               bit_difference("triangle_cell", ref.triangle_cell, dev.triangle_cell) +
                               bit_difference("cell_start", ref.cell_start, dev.cell_start) +
                               bit_difference("sorted_triangles", ref.sorted_triangles, dev.sorted_triangles) +
                               bit_difference("slot_element", ref.slot_element, dev.slot_element);
      INFO(label << " on " << d.device.name << ", grid sorted on the " << grid_sort_name(sort) << "\n" << diff);
      CHECK(diff.empty());
    }
}

}  // namespace

TEST_CASE("grid: centroids, cells and the stable sort match the reference", "[equivalence][opencl]") {
  if (skip_without_devices(devices_under_test())) return;
  for (std::uint64_t seed = 21; seed <= 24; ++seed) {
    RandomWorldShape shape;
    shape.elements = 6;
    shape.max_radius = 0.25f;  // some vertices beyond the cube's faces, clamped into border cells
    const TinyWorld w = random_world(seed, shape);
    Params coarse;
    coarse.forces.cell_size = 0.3;  // few cells: many triangles share one, so the within-cell order matters
    check_grid(w, Params{}, "seed " + std::to_string(seed));
    check_grid(w, coarse, "seed " + std::to_string(seed) + ", coarse cells");
  }
}

}  // namespace animpak::test
