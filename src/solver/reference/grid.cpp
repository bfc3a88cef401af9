// Collision grid of paper §5.1: envelope-triangle centroids in a uniform grid over the unit cube,
// queried by the 3×3×3 block ("near": exact closest points, overlap tests) and the outer shell of
// the 5×5×5 block ("far": centroids only). Built as count → exclusive scan → stable scatter so the
// kernels can build the same arrays and every run visits triangles in the same order.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "../counting_sort.hpp"
#include "animpak/reference/grid.hpp"

namespace animpak::reference {

std::int32_t grid_cells_per_axis(double cell_size) {
  if (!(cell_size > 0.0 && cell_size <= 1.0))
    throw std::invalid_argument("collision grid: cell_size must be in (0, 1]");
  // The tolerance keeps 1 / 0.04 at 25 cells rather than 26 when the quotient rounds just above 25.
  return static_cast<std::int32_t>(std::ceil(1.0 / cell_size - 1e-9));
}

Vec3f envelope_centroid(const Topology& topo, const SimState& state, std::int32_t i) {
  const std::int32_t a = topo.env_a[i], b = topo.env_b[i], c = topo.env_c[i];
  return {(state.x[a] + state.x[b] + state.x[c]) / 3.0f, (state.y[a] + state.y[b] + state.y[c]) / 3.0f,
          (state.t[a] + state.t[b] + state.t[c]) / 3.0f};
}

CollisionGrid build_collision_grid(const Topology& topo, const SimState& state, const Params& params) {
  CollisionGrid g;
  g.n = grid_cells_per_axis(params.forces.cell_size);
  g.cell = static_cast<float>(params.forces.cell_size);
  const std::int32_t count = topo.envelope_count();
  const std::int32_t cells = g.n * g.n * g.n;
  g.cx.resize(count);
  g.cy.resize(count);
  g.ct.resize(count);
  g.triangle_cell.resize(count);

  // Insert: centroid and cell of every triangle; then the shared stable counting sort.
  for (std::int32_t i = 0; i < count; ++i) {
    const Vec3f c = envelope_centroid(topo, state, i);
    g.cx[i] = c.x;
    g.cy[i] = c.y;
    g.ct[i] = c.t;
    g.triangle_cell[i] = grid_linear_cell(c.x, c.y, c.t, g.cell, g.n);
  }
  counting_sort(g.triangle_cell, cells, g.cell_start, g.sorted_triangles);
  fill_slot_elements(topo, g);
  if (params.forces.far_cells != 0) build_far_runs(g);
  return g;
}

void fill_slot_elements(const Topology& topo, CollisionGrid& g) {
  g.slot_element.resize(g.sorted_triangles.size());
  for (std::size_t k = 0; k < g.sorted_triangles.size(); ++k)
    g.slot_element[k] = topo.env_element[g.sorted_triangles[k]];
}

void build_far_runs(CollisionGrid& g) {
  const std::size_t slots = g.sorted_triangles.size();
  g.far_cells = true;
  g.run_next.assign(slots, 0);
  g.run_cx.assign(slots, 0.0f), g.run_cy.assign(slots, 0.0f), g.run_ct.assign(slots, 0.0f);
  const std::int32_t cells = static_cast<std::int32_t>(g.cell_start.size()) - 1;
  for (std::int32_t c = 0; c < cells; ++c) {
    const std::int32_t end = g.cell_start[c + 1];
    for (std::int32_t head = g.cell_start[c]; head < end;) {
      const std::int32_t owner = g.slot_element[head];
      float sx = 0.0f, sy = 0.0f, st = 0.0f;
      std::int32_t k = head;
      for (; k < end && g.slot_element[k] == owner; ++k) {
        const std::int32_t tri = g.sorted_triangles[k];
        sx = sx + g.cx[tri];
        sy = sy + g.cy[tri];
        st = st + g.ct[tri];
      }
      const float count = static_cast<float>(k - head);
      g.run_next[head] = k;
      g.run_cx[head] = sx / count, g.run_cy[head] = sy / count, g.run_ct[head] = st / count;
      head = k;
    }
  }
}

namespace {

// Calls visit(c) for each cell c of the (2r+1)³ block around q's cell whose Chebyshev distance from it
// is at least `min_ring`, in dz, dy, dx ascending order; cells outside the grid are skipped.
template <class Visit>
void for_block_cells(const CollisionGrid& grid, Vec3f q, std::int32_t r, std::int32_t min_ring, Visit visit) {
  const std::int32_t qx = grid_axis_cell(q.x, grid.cell, grid.n);
  const std::int32_t qy = grid_axis_cell(q.y, grid.cell, grid.n);
  const std::int32_t qt = grid_axis_cell(q.t, grid.cell, grid.n);
  for (std::int32_t dz = -r; dz <= r; ++dz) {
    for (std::int32_t dy = -r; dy <= r; ++dy) {
      for (std::int32_t dx = -r; dx <= r; ++dx) {
        const std::int32_t ring = std::max(std::abs(dz), std::max(std::abs(dy), std::abs(dx)));
        if (ring < min_ring) continue;
        const std::int32_t cx = qx + dx, cy = qy + dy, ct = qt + dz;
        if (cx < 0 || cy < 0 || ct < 0 || cx >= grid.n || cy >= grid.n || ct >= grid.n) continue;
        visit((ct * grid.n + cy) * grid.n + cx);
      }
    }
  }
}

// The slots of other elements' triangles in those cells (with `own_only`, of own_element's instead), in
// sorted order within a cell.
void collect(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::int32_t r, std::int32_t min_ring,
             std::vector<std::int32_t>& out, bool own_only = false) {
  out.clear();
  for_block_cells(grid, q, r, min_ring, [&](std::int32_t c) {
    for (std::int32_t k = grid.cell_start[c]; k < grid.cell_start[c + 1]; ++k) {
      if ((grid.slot_element[k] == own_element) == own_only) out.push_back(k);
    }
  });
}

// Slots to the triangles in them, in place.
void slots_to_triangles(const CollisionGrid& grid, std::vector<std::int32_t>& slots) {
  for (std::int32_t& k : slots) k = grid.sorted_triangles[k];
}

}  // namespace

void repulsion_near_slots(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out,
                          bool own_only) {
  collect(grid, q, own_element, 1, 0, out, own_only);
}

void near_triangles(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out) {
  repulsion_near_slots(grid, q, own_element, out);
  slots_to_triangles(grid, out);
}

void far_triangles(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out) {
  collect(grid, q, own_element, 2, 2, out);
  slots_to_triangles(grid, out);
}

void repulsion_far_slots(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out,
                         bool own_only) {
  out.clear();
  for_block_cells(grid, q, 2, 2, [&](std::int32_t c) {
    for (std::int32_t k = grid.cell_start[c]; k < grid.cell_start[c + 1];) {
      const std::int32_t next = grid.far_cells ? grid.run_next[k] : k + 1;
      if ((grid.slot_element[k] == own_element) == own_only) out.push_back(k);
      k = next;
    }
  });
}

}  // namespace animpak::reference
