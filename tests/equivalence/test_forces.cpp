// Per-force equivalence: every component of Eq. 7 from the device against reference::step_forces, bit
// for bit, on seeded random worlds and on hand-made edge cases. A failure names the force, the axis,
// the vertex, both values and their distance in ULPs.
#include <algorithm>

#include "equivalence_support.hpp"

namespace animpak::test {
namespace {

struct Coverage {
  int inside = 0, crossing = 0, wall = 0, boundary = 0, target = 0, repulsion = 0;
  int yield = 0, paused = 0;  // overlapping vertices that give way, and that only pause
  int ignored = 0;            // overlapping vertices of a primary element that meet only secondary ones
};

// Compares one world's forces on every device; returns what the world exercised.
Coverage check_forces(const TinyWorld& w, const Params& params, const std::string& label) {
  const CollisionGrid grid = reference::build_collision_grid(w.topo, w.state, params);
  ForceBreakdown ref_parts;
  const StepForces ref = reference::step_forces(w.topo, w.state, step_params(params), grid, &ref_parts);
  Coverage c;
  for (std::size_t v = 0; v < ref.contact.size(); ++v) {
    c.inside += (ref.contact[v] & contact_inside) != 0;
    c.crossing += (ref.contact[v] & (contact_overlap | contact_inside)) == contact_overlap;
    c.yield += (ref.contact[v] & contact_yield) != 0;
    c.paused +=
        (ref.contact[v] & (contact_overlap | contact_block | contact_yield)) == (contact_overlap | contact_block);
    c.ignored += (ref.contact[v] & (contact_overlap | contact_block)) == contact_overlap;
    c.wall += (ref.contact[v] & contact_wall) != 0;
    c.boundary += ref_parts.boundary.x[v] != 0.0f;
    c.target += ref_parts.target.x[v] != 0.0f;
    c.repulsion += ref_parts.repulsion.x[v] != 0.0f;
  }
  for (const DeviceChoice& d : devices_under_test())
    for (const GridSort sort : grid_sorts) {
      auto backend = make_opencl_backend(w.topo, w.state, params, d, sort);
      ForceBreakdown dev_parts;
      const StepForces dev = backend->evaluate_forces(&dev_parts);
      const std::string diff =
          breakdown_difference(ref_parts, dev_parts) + bit_difference("total.x", ref.total.x, dev.total.x) +
          bit_difference("total.y", ref.total.y, dev.total.y) + bit_difference("total.t", ref.total.t, dev.total.t) +
          bit_difference("closest", ref.closest, dev.closest) + bit_difference("contact", ref.contact, dev.contact);
      INFO(label << " on " << d.device.name << ", grid sorted on the " << grid_sort_name(sort) << "\n" << diff);
      CHECK(diff.empty());
    }
  return c;
}

bool have_devices() { return !skip_without_devices(devices_under_test()); }

// The default constants and the paper's; under a seed stride (Oclgrind, scripts/oclgrind-check.sh) the
// defaults only, for the suite's two largest worlds: the paper's constants run the same kernel code.
std::vector<Params> constants_under_test() {
  std::vector<Params> out{Params{}};
  if (seed_stride() == 1) out.push_back(paper_params());
  return out;
}

// A ring of `count` vertices at the given points, repeated on every slice time.
std::vector<TinySlice> tube(const Ring& ring, const std::vector<float>& times) {
  std::vector<TinySlice> slices;
  for (const float t : times) slices.push_back({ring, t});
  return slices;
}

TinyWorld finish(WorldBuilder& b) {
  TinyWorld w = b.build();
  fill_reference_copy(w);
  return w;
}

// How the overlap test's broadphase served a world's boundary vertices (their own points and edges):
// candidates tried in all, and queries whose edge's box meets two cells, or four.
struct BroadphaseUse {
  long queries = 0, candidates = 0, two_cells = 0, four_cells = 0;
};

BroadphaseUse broadphase_use(const TinyWorld& w) {
  SliceBoxes boxes;
  CurveTangents tangents;
  reference::curve_tangents(w.topo, w.state, Params{}.forces.motion_curve, tangents);
  reference::slice_boxes(w.topo, w.state, tangents, boxes);
  OverlapGrid g;
  reference::build_overlap_grid(w.topo, boxes, g);
  BroadphaseUse u;
  std::vector<std::int32_t> found;
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    const std::int32_t lo = w.topo.slice_begin[w.topo.slice[v]], count = w.topo.slice_boundary[w.topo.slice[v]];
    if (v - lo >= count) continue;
    const std::int32_t next = v - lo + 1 == count ? lo : v + 1;
    const float ex0 = std::min(w.state.x[v], w.state.x[next]), ex1 = std::max(w.state.x[v], w.state.x[next]);
    const float ey0 = std::min(w.state.y[v], w.state.y[next]), ey1 = std::max(w.state.y[v], w.state.y[next]);
    reference::overlap_candidates(g, w.topo.element_count(), ex0, ex1, ey0, ey1, w.state.t[v], found);
    const int cells_x =
        reference::grid_axis_cell(ex1 - g.x0, g.cell, g.nx) - reference::grid_axis_cell(ex0 - g.x0, g.cell, g.nx) + 1;
    const int cells_y =
        reference::grid_axis_cell(ey1 - g.y0, g.cell, g.ny) - reference::grid_axis_cell(ey0 - g.y0, g.cell, g.ny) + 1;
    ++u.queries;
    u.candidates += static_cast<long>(found.size());
    u.two_cells += cells_x * cells_y == 2;
    u.four_cells += cells_x * cells_y == 4;
  }
  return u;
}

}  // namespace

TEST_CASE("forces: random worlds, default and paper constants", "[equivalence][opencl]") {
  if (!have_devices()) return;
  Coverage total;
  for (std::uint64_t seed = 1; seed <= 6; seed += seed_stride()) {
    RandomWorldShape shape;
    shape.elements = 3 + static_cast<int>(seed % 4);
    shape.max_radius = 0.2f;  // large enough that elements overlap and cross the container
    const TinyWorld w = random_world(seed, shape);
    for (const Params& params : {Params{}, paper_params()}) {
      const Coverage c = check_forces(w, params, "seed " + std::to_string(seed));
      total.inside += c.inside, total.crossing += c.crossing, total.wall += c.wall;
      total.boundary += c.boundary, total.target += c.target, total.repulsion += c.repulsion;
    }
  }
  // The worlds must exercise every branch that differs between forces, or the comparison says little.
  CHECK(total.inside > 0);
  CHECK(total.crossing > 0);
  CHECK(total.wall > 0);
  CHECK(total.boundary > 0);
  CHECK(total.target > 0);
  CHECK(total.repulsion > 0);
}

TEST_CASE("forces: vertices on cell borders and the grid's edge", "[equivalence][opencl]") {
  if (!have_devices()) return;
  WorldBuilder b;
  // Multiples of the 0.04 cell edge, where floor(c / cell) decides between two cells; t on 0 and 1.
  b.add_element(tube({{0.40f, 0.40f}, {0.48f, 0.40f}, {0.48f, 0.48f}, {0.40f, 0.48f}}, {0.0f, 0.44f, 1.0f}));
  b.add_element(tube({{0.52f, 0.40f}, {0.60f, 0.40f}, {0.60f, 0.48f}, {0.52f, 0.48f}}, {0.0f, 0.48f, 1.0f}));
  // On and beyond the cube's faces: clamped into the border cells, and outside the container.
  b.add_element(tube({{0.0f, 0.0f}, {0.04f, -0.01f}, {0.04f, 0.04f}, {-0.02f, 0.04f}}, {0.0f, 0.5f, 1.0f}));
  b.add_element(tube({{0.96f, 0.96f}, {1.02f, 0.96f}, {1.0f, 1.0f}, {0.96f, 1.0f}}, {0.0f, 0.96f, 1.0f}));
  const TinyWorld w = finish(b);
  for (const Params& params : {Params{}, paper_params()}) check_forces(w, params, "cell borders");
}

TEST_CASE("forces: many small elements spread out, the overlap broadphase leaving most out", "[equivalence][opencl]") {
  if (!have_devices()) return;
  Coverage total;
  for (std::uint64_t seed = 21; seed <= 22; seed += seed_stride()) {
    RandomWorldShape shape;
    shape.elements = 60;
    shape.min_radius = 0.02f;
    shape.max_radius = 0.06f;
    const TinyWorld w = random_world(seed, shape);
    const BroadphaseUse u = broadphase_use(w);
    CHECK(u.candidates * 10 < u.queries * shape.elements);  // fewer than a tenth of the elements tried
    for (const Params& params : constants_under_test()) {
      const Coverage c = check_forces(w, params, "spread, seed " + std::to_string(seed));
      total.inside += c.inside, total.crossing += c.crossing;
    }
  }
  CHECK(total.inside > 0);
  CHECK(total.crossing > 0);
}

TEST_CASE("forces: slice-pair boxes across the overlap broadphase's cell borders", "[equivalence][opencl]") {
  if (!have_devices()) return;
  WorldBuilder b;
  // Squares and diamonds of one size, so the broadphase's cell (the mean pair box's extent) is their
  // box, 0.08: placed half a cell apart, their boxes straddle cell borders and their corners lie on
  // them; the diamonds' slanted edges meet four cells, the squares' edges two.
  const std::vector<float> times = {0.0f, 0.3f, 0.7f, 1.0f};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const float cx = 0.3f + 0.06f * static_cast<float>(i), cy = 0.3f + 0.06f * static_cast<float>(j);
      if ((i + j) % 2 == 0)
        b.add_element(square_tube(cx, cy, 0.04f, times));
      else
        b.add_element(tube({{cx, cy - 0.04f}, {cx + 0.04f, cy}, {cx, cy + 0.04f}, {cx - 0.04f, cy}}, times));
    }
  const TinyWorld w = finish(b);
  const BroadphaseUse u = broadphase_use(w);
  CHECK(u.two_cells > 0);
  CHECK(u.four_cells > 0);
  for (const Params& params : constants_under_test()) {
    const Coverage c = check_forces(w, params, "cell borders of the overlap broadphase");
    CHECK(c.inside > 0);
  }
}

TEST_CASE("forces: nearly degenerate envelope triangles", "[equivalence][opencl]") {
  if (!have_devices()) return;
  WorldBuilder b;
  // Two slices 1e-7 apart in t and a nearly collinear ring: slivers in every Voronoi region.
  b.add_element(
      tube({{0.30f, 0.30f}, {0.34f, 0.300001f}, {0.38f, 0.30f}, {0.34f, 0.34f}}, {0.0f, 0.5f, 0.5000001f, 1.0f}));
  b.add_element(tube({{0.33f, 0.29f}, {0.37f, 0.29f}, {0.37f, 0.33f}, {0.33f, 0.33f}}, {0.0f, 0.5f, 1.0f}));
  b.add_element(tube({{0.35f, 0.31f}, {0.35f, 0.31f}, {0.36f, 0.32f}, {0.35f, 0.32f}}, {0.0f, 0.49f, 1.0f}));
  const TinyWorld w = finish(b);
  for (const Params& params : {Params{}, paper_params()}) check_forces(w, params, "degenerate");
}

// The longest run of consecutive grid slots that one boundary vertex's near block walks in one row
// (three cells in x) while holding another element's triangle: the kernel takes such runs AP_LANES
// slots at a time (closest_point_on_triangles in kernels/closest_point.cl).
std::int32_t longest_near_row(const TinyWorld& w, const Params& params) {
  const CollisionGrid g = reference::build_collision_grid(w.topo, w.state, params);
  std::int32_t longest = 0;
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    if ((w.topo.flags[v] & vertex_boundary) == 0) continue;
    const std::int32_t qx = reference::grid_axis_cell(w.state.x[v], g.cell, g.n);
    const std::int32_t qy = reference::grid_axis_cell(w.state.y[v], g.cell, g.n);
    const std::int32_t qt = reference::grid_axis_cell(w.state.t[v], g.cell, g.n);
    for (std::int32_t dz = -1; dz <= 1; ++dz)
      for (std::int32_t dy = -1; dy <= 1; ++dy) {
        const std::int32_t cy = qy + dy, ct = qt + dz;
        if (cy < 0 || ct < 0 || cy >= g.n || ct >= g.n) continue;
        const std::int32_t x0 = std::max(qx - 1, 0), x1 = std::min(qx + 1, g.n - 1);
        const std::int32_t row = (ct * g.n + cy) * g.n;
        bool other = false;
        for (std::int32_t k = g.cell_start[row + x0]; k < g.cell_start[row + x1 + 1]; ++k)
          other = other || w.topo.env_element[g.sorted_triangles[k]] != w.topo.element[v];
        if (other) longest = std::max(longest, g.cell_start[row + x1 + 1] - g.cell_start[row + x0]);
      }
  }
  return longest;
}

TEST_CASE("forces: near rows and outlines long enough for the kernel's lanes, with slivers and repeated points",
          "[equivalence][opencl]") {
  if (!have_devices()) return;
  // A simulator takes the one-slot paths (device_build_options), which the other worlds cover, and this
  // world's long rows cost it minutes: skipped there.
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (std::all_of(devices.begin(), devices.end(), [](const DeviceChoice& d) { return d.device.simulator; })) return;
  // Five jittered 24-gons around one point, on eleven slices each (two of them 1e-7 apart), some points
  // repeated and one ring nearly collinear: rows of dozens of slots, every Voronoi region of the
  // closest-point test among them, and triangles degenerate enough that the face region fails; and
  // overlapping outlines of 27 edges, which the overlap test's walk takes 16 at a time.
  std::mt19937 rng(7);
  auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
  WorldBuilder b;
  for (int e = 0; e < 5; ++e) {
    const float cx = 0.5f + uniform(-0.04f, 0.04f), cy = 0.5f + uniform(-0.04f, 0.04f);
    const float squash = e == 3 ? 1e-4f : 1.0f;  // a sliver ring
    std::vector<TinySlice> slices;
    for (int s = 0; s <= 10; ++s) {
      TinySlice sl;
      sl.t = s == 6 ? slices.back().t + 1e-7f : std::min(1.0f, 0.1f * float(s) + uniform(0.0f, 0.01f));
      for (int i = 0; i < 24; ++i) {
        const float a = 6.2831853f * float(i) / 24.0f, r = uniform(0.02f, 0.05f);
        sl.ring.push_back({cx + r * std::cos(a), cy + squash * r * std::sin(a)});
        if (i % 7 == 3) sl.ring.push_back(sl.ring.back());  // a zero-length edge
      }
      slices.push_back(sl);
    }
    b.add_element(slices);
  }
  const TinyWorld w = finish(b);
  for (const Params& params : {Params{}, paper_params()}) {
    REQUIRE(longest_near_row(w, params) >= 64);
    const Coverage c = check_forces(w, params, "lanes");
    CHECK(c.inside > 0);
    CHECK(c.crossing > 0);
  }
}

TEST_CASE("forces: elements touching the container and a hole", "[equivalence][opencl]") {
  if (!have_devices()) return;
  WorldBuilder b;
  b.set_container({square(0.5f, 0.5f, 0.45f), square(0.5f, 0.5f, 0.1f), square(0.2f, 0.8f, 0.05f)});
  b.add_element(square_tube(0.05f, 0.5f, 0.06f, {0.0f, 0.5f, 1.0f}));  // across the outline
  b.add_element(square_tube(0.5f, 0.5f, 0.05f, {0.0f, 0.5f, 1.0f}));   // inside the hole
  b.add_element(square_tube(0.62f, 0.5f, 0.04f, {0.0f, 0.5f, 1.0f}));  // across the hole's edge
  b.add_element(square_tube(0.2f, 0.8f, 0.06f, {0.0f, 0.5f, 1.0f}));   // around the second hole
  const TinyWorld w = finish(b);
  for (const Params& params : {Params{}, paper_params()}) check_forces(w, params, "container");
}

TEST_CASE("forces: the wall as the element's mirror image, at the outline, a hole and a corner",
          "[equivalence][opencl]") {
  if (!have_devices()) return;
  // Slices as close in t as a scene's, so the element's own triangles are within the repulsion's reach.
  const std::vector<float> times = {0.42f, 0.47f, 0.52f, 0.57f};
  WorldBuilder b;
  b.set_container({{{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.5f, 0.7f}, {0.0f, 1.0f}}, square(0.5f, 0.4f, 0.1f)});
  b.add_element(square_tube(0.05f, 0.5f, 0.03f, times));    // near the outline's left side
  b.add_element(square_tube(0.5f, 0.25f, 0.04f, times));    // just below the hole
  b.add_element(square_tube(0.93f, 0.06f, 0.03f, times));   // in a corner
  b.add_element(square_tube(0.5f, 0.6f, 0.05f, times));     // between the hole and the notch
  b.add_element(square_tube(0.09f, 0.55f, 0.008f, times));  // a neighbour of the first
  const TinyWorld w = finish(b);
  for (Params params : {Params{}, paper_params()}) {
    params.forces.wall_mirror = 1.0;
    params.forces.wall_range = 0.08;
    check_forces(w, params, "mirror");
    params.forces.wall_repulsion = 0.0;
    params.forces.wall_mirror = 2.5;
    check_forces(w, params, "mirror alone");
    // Not vacuous: the mirror changes the wall's force on some vertices.
    const CollisionGrid grid = reference::build_collision_grid(w.topo, w.state, params);
    ForceBreakdown on, off;
    reference::step_forces(w.topo, w.state, step_params(params), grid, &on);
    params.forces.wall_mirror = 0.0;
    reference::step_forces(w.topo, w.state, step_params(params), grid, &off);
    int changed = 0;
    for (std::size_t v = 0; v < on.boundary.x.size(); ++v)
      changed += on.boundary.x[v] != off.boundary.x[v] || on.boundary.t[v] != off.boundary.t[v];
    CHECK(changed > 20);
  }
}

TEST_CASE("forces: boundary edges across a reflex corner of the container, both ends inside", "[equivalence][opencl]") {
  if (!have_devices()) return;
  WorldBuilder b;
  b.set_container({{{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.5f, 0.7f}, {0.0f, 1.0f}}});
  b.add_element(square_tube(0.5f, 0.65f, 0.1f, {0.0f, 0.5f, 1.0f}));  // straddles the notch
  b.add_element(square_tube(0.2f, 0.3f, 0.05f, {0.0f, 0.5f, 1.0f}));  // clear of it
  const TinyWorld w = finish(b);
  for (const Params& params : {Params{}, paper_params()}) check_forces(w, params, "notch");
}

TEST_CASE("forces: deep overlaps and edges that cross with no vertex inside", "[equivalence][opencl]") {
  if (!have_devices()) return;
  WorldBuilder b;
  b.add_element(square_tube(0.5f, 0.5f, 0.005f, {0.0f, 0.5f, 1.0f}));  // deep inside the next one
  b.add_element(square_tube(0.5f, 0.5f, 0.12f, {0.0f, 0.4f, 1.0f}));
  // A plus sign of two bars: only edges cross.
  b.add_element(tube({{0.2f, 0.78f}, {0.4f, 0.78f}, {0.4f, 0.8f}, {0.2f, 0.8f}}, {0.0f, 0.5f, 1.0f}));
  b.add_element(tube({{0.29f, 0.7f}, {0.31f, 0.7f}, {0.31f, 0.9f}, {0.29f, 0.9f}}, {0.0f, 0.6f, 1.0f}));
  TinyWorld w = finish(b);
  // Unequal g, so that the overlapping vertices of the larger element of each pair yield and those of
  // the smaller only pause (docs/parameters.md, "Growth").
  for (std::int32_t s = 0; s < w.topo.slice_count(); ++s)
    w.state.growth[s] = 1.0f + 0.25f * static_cast<float>(w.topo.slice_element[s]);
  for (const Params& params : {Params{}, paper_params()}) {
    const Coverage c = check_forces(w, params, "deep and crossing");
    CHECK(c.inside > 0);
    CHECK(c.crossing > 0);
    CHECK(c.yield > 0);
    CHECK(c.paused > 0);
  }
}

TEST_CASE("forces: secondary elements give way to primary ones", "[equivalence][opencl]") {
  if (!have_devices()) return;
  WorldBuilder b;
  b.add_element(square_tube(0.5f, 0.5f, 0.005f, {0.0f, 0.5f, 1.0f}));  // primary, deep inside the next
  b.add_element(square_tube(0.5f, 0.5f, 0.12f, {0.0f, 0.4f, 1.0f}));   // secondary
  b.add_element(tube({{0.2f, 0.78f}, {0.4f, 0.78f}, {0.4f, 0.8f}, {0.2f, 0.8f}}, {0.0f, 0.5f, 1.0f}));    // secondary
  b.add_element(tube({{0.29f, 0.7f}, {0.31f, 0.7f}, {0.31f, 0.9f}, {0.29f, 0.9f}}, {0.0f, 0.6f, 1.0f}));  // primary
  TinyWorld w = finish(b);
  w.topo.element_secondary = {0, 1, 1, 0};
  for (std::int32_t s = 0; s < w.topo.slice_count(); ++s)
    w.state.growth[s] = 1.0f + 0.25f * static_cast<float>(w.topo.slice_element[s]);
  for (const Params& params : {Params{}, paper_params()}) {
    const Coverage c = check_forces(w, params, "secondary");
    CHECK(c.ignored > 0);  // the primary elements' vertices
    CHECK(c.yield > 0);    // the secondary elements', the larger of the crossing bars included
    CHECK(c.paused == 0);  // every overlap here is between a primary and a secondary element
  }
}

TEST_CASE("forces: sparse targets and keyed slices holding their angle, turned off their rest",
          "[equivalence][opencl]") {
  if (!have_devices()) return;
  WorldBuilder b;
  b.add_element(square_tube(0.4f, 0.5f, 0.08f, {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}));
  b.add_element(square_tube(0.7f, 0.5f, 0.06f, {0.0f, 0.5f, 1.0f}));
  b.add_target(0, 0.3f, 0.45f, 0.0f);  // element 0, slices 0 and 2 only
  b.add_target(8, 0.45f, 0.55f, 0.5f);
  TinyWorld w = finish(b);
  for (std::int32_t v : {0, 1, 2, 3, 8, 9, 10, 11}) w.topo.flags[v] |= vertex_hold_angle;
  // Turn every slice by 0.3 rad about its centre so that both torsion constants act.
  std::vector<float> cx, cy;
  reference::slice_centroids(w.topo, w.state, cx, cy);
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    const std::int32_t s = w.topo.slice[v];
    const float ux = w.state.x[v] - cx[s], uy = w.state.y[v] - cy[s];
    w.state.x[v] = cx[s] + 0.9553365f * ux - 0.2955202f * uy;
    w.state.y[v] = cy[s] + 0.2955202f * ux + 0.9553365f * uy;
  }
  for (const Params& params : {Params{}, paper_params()}) {
    const Coverage c = check_forces(w, params, "keyed slices");
    CHECK(c.target == 2);
  }
}

TEST_CASE("forces: folded and squeezed slice triangles, the fold guard", "[equivalence][opencl]") {
  if (!have_devices()) return;
  for (std::uint64_t seed = 11; seed <= 12; seed += seed_stride()) {
    RandomWorldShape shape;
    shape.elements = 3;
    TinyWorld w = random_world(seed, shape);  // its rest copy: the rings as built
    // Fold: every third boundary vertex mirrored through its slice's centroid side (across the fan's
    // opposite edges); squeeze: every second slice shrunk to 0.6 of its size about its centroid.
    std::vector<float> cx, cy;
    reference::slice_centroids(w.topo, w.state, cx, cy);
    for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
      const std::int32_t s = w.topo.slice[v];
      if (v % 3 == 0) {
        w.state.x[v] = cx[s] - 0.5f * (w.state.x[v] - cx[s]);
        w.state.y[v] = cy[s] - 0.5f * (w.state.y[v] - cy[s]);
      } else if (s % 2 == 1) {
        w.state.x[v] = cx[s] + 0.6f * (w.state.x[v] - cx[s]);
        w.state.y[v] = cy[s] + 0.6f * (w.state.y[v] - cy[s]);
      }
    }
    for (const Params& params : {Params{}, paper_params()}) {
      Params p = params;
      p.forces.k_fold = 200.0;
      int folded = 0;
      for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
        const Vec3f f = reference::fold_force(w.topo, w.state, step_params(p), v);
        folded += f.x != 0.0f || f.y != 0.0f;
      }
      CHECK(folded > w.topo.vertex_count() / 4);  // the guard acts on many vertices, or this says little
      check_forces(w, p, "folded, seed " + std::to_string(seed));
    }
  }
}

TEST_CASE("forces: more points between slices than one batch of the kernel's shared candidate walk",
          "[equivalence][opencl]") {
  if (!have_devices()) return;
  // The kernel's overlap test takes a vertex's query points in batches of at most eight (overlap_points
  // in kernels/overlap.cl): with the most points per interval (15), 8 on each side of a slice, the vertex
  // and the first side's points fill one batch and start another; with the fewest (1), one per side.
  Coverage total;
  for (const int points : {15, 1}) {
    Params params;
    params.forces.interval_points = points;
    for (std::uint64_t seed = 1; seed <= 6; seed += seed_stride()) {
      RandomWorldShape shape;
      shape.elements = 3 + static_cast<int>(seed % 4);
      shape.max_radius = 0.2f;
      const Coverage c = check_forces(random_world(seed, shape), params,
                                      std::to_string(points) + " points per interval, seed " + std::to_string(seed));
      total.inside += c.inside, total.crossing += c.crossing;
    }
  }
  CHECK(total.inside > 0);
  CHECK(total.crossing > 0);
}

TEST_CASE("forces: one element alone", "[equivalence][opencl]") {
  if (!have_devices()) return;
  WorldBuilder b;
  b.add_element(square_tube(0.5f, 0.5f, 0.1f, {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}));
  b.add_target(0, 0.3f, 0.3f, 0.0f);
  const TinyWorld w = finish(b);
  for (const Params& params : {Params{}, paper_params()}) check_forces(w, params, "alone");
}

}  // namespace animpak::test
