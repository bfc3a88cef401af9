// Containment (docs/parameters.md, "Containment"): the container's wall is a neighbour in the slice gap
// of §5.3, a slice at the wall stops growing, and a vertex that a step leaves outside is put back.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>

#include "animpak/run.hpp"
#include "animpak/scene.hpp"
#include "scene/tiny_scenes.hpp"
#include "tiny_worlds.hpp"

using namespace animpak;
using namespace animpak::reference;
using animpak::test::WorldBuilder;

TEST_CASE("containment: a vertex outside the container or inside a hole moves just inside, and stops") {
  WorldBuilder b;
  b.set_container({test::square(0.5f, 0.5f, 0.5f), test::square(0.5f, 0.5f, 0.1f)});  // a hole in the middle
  b.add_element({{{{1.2f, 0.5f}, {0.52f, 0.47f}, {0.3f, 0.3f}}, 0.5f}}, false);
  test::TinyWorld w = b.build();
  w.state.vx = {1.0f, 2.0f, 3.0f};
  w.state.vy = {1.0f, 2.0f, 3.0f};
  apply_containment(w.topo, w.state);
  // Vertex 0 was 0.2 right of the outline: it lands a hair left of x = 1.
  CHECK(w.state.x[0] < 1.0f);
  CHECK(w.state.x[0] == Approx(1.0f - containment_margin).epsilon(1e-6));
  CHECK(w.state.y[0] == 0.5f);
  // Vertex 1 was in the hole [0.4, 0.6]², 0.07 below its top edge y = 0.4 and 0.08 from its right edge
  // x = 0.6: it leaves through the top.
  CHECK(w.state.x[1] == 0.52f);
  CHECK(w.state.y[1] < 0.4f);
  CHECK(w.state.y[1] == Approx(0.4f - containment_margin).epsilon(1e-6));
  // Both are now inside, and stopped; vertex 2 was inside and keeps everything.
  for (int v : {0, 1}) {
    CHECK(container_query(w.topo.container, w.state.x[v], w.state.y[v], false).inside);
    CHECK((w.state.vx[v] == 0.0f && w.state.vy[v] == 0.0f));
  }
  CHECK((w.state.x[2] == 0.3f && w.state.y[2] == 0.3f && w.state.vx[2] == 3.0f));
}

TEST_CASE("containment: a slice whose boundary touches the wall is flagged and stops growing") {
  // The wall's gap is the distance d to it with the point wall, and 2d, the gap to the element's mirror
  // image, with the image (the default): either way, a slice whose gap is below stop_gap touches.
  for (const bool mirror : {false, true}) {
    INFO((mirror ? "mirror image" : "point wall"));
    Params p = test::paper_params();
    p.forces.wall_mirror = mirror ? 1.0 : 0.0;
    const float scale = mirror ? 2.0f : 1.0f;
    WorldBuilder b;
    std::vector<float> times;
    for (int k = 0; k <= 25; ++k) times.push_back(static_cast<float>(k) / 25.0f);
    std::vector<test::TinySlice> slices = test::square_tube(0.5f, 0.5f, 0.05f, times);
    // Slice 7's gap is half stop_gap; slice 8 is 0.45 from x = 1 then, and slice 9 spills past the wall.
    slices[7].ring = test::square(0.95f - static_cast<float>(p.stop.stop_gap) / (2.0f * scale), 0.5f, 0.05f);
    slices[9].ring = test::square(0.97f, 0.5f, 0.05f);
    b.add_element(slices);
    const test::TinyWorld w = b.build();
    const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
    const StepForces f = step_forces(w.topo, w.state, step_params(p), g, nullptr);
    for (int s = 0; s < 26; ++s) {
      std::uint8_t bits = 0;
      float gap = std::numeric_limits<float>::infinity();
      for (int v = s * 4; v < s * 4 + 4; ++v) bits |= f.contact[v], gap = std::min(gap, f.closest[v]);
      INFO("slice " << s);
      CHECK(((bits & contact_wall) != 0) == (s == 7 || s == 9));
      CHECK(((bits & contact_outside) != 0) == (s == 9));
      // Nothing else is near, so the gap is the wall's: 0.45 for the centred slices (twice with the image).
      if (s != 7 && s != 9) CHECK(gap == Approx(0.45f * scale).epsilon(1e-5));
      if (s == 9) CHECK(gap == 0.0f);
    }
    SimState state = w.state;
    Params grow = p;
    grow.growth.growth_ratio = 100.0;
    std::vector<std::uint8_t> changed;
    test::grow_step(w.topo, f.contact, grow, true, state, changed);
    CHECK(changed[7] == growth_kept);
    CHECK(changed[9] == growth_kept);  // at g = 1 already: a spilling slice cannot shrink below the start
    CHECK(changed[8] == growth_grew);
  }
}

TEST_CASE("containment: a boundary edge across a reflex corner of the container counts as outside") {
  // A square container with a notch: its top edge dips to a reflex corner at (0.5, 0.7).
  const Params p = test::paper_params();
  const test::Ring notched{{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.5f, 0.7f}, {0.0f, 1.0f}};
  std::vector<float> times{0.0f, 0.5f, 1.0f};
  for (const bool indexed : {true, false}) {
    INFO((indexed ? "with" : "without") << " the container index");
    WorldBuilder b;
    b.set_container({notched});
    // Slice 1 straddles the notch: its four corners are inside, its top edge (vertex 2 to 3, y = 0.75)
    // passes above the corner. Slices 0 and 2 sit lower, clear of it.
    std::vector<test::TinySlice> slices = test::square_tube(0.5f, 0.5f, 0.1f, times);
    slices[1].ring = test::square(0.5f, 0.65f, 0.1f);
    b.add_element(slices);
    test::TinyWorld w = b.build();
    if (!indexed) w.topo.container.index = {};
    for (int v = 4; v < 8; ++v) REQUIRE(container_query(w.topo.container, w.state.x[v], w.state.y[v], false).inside);
    CHECK(edge_crosses_container(w.topo.container, 0.6f, 0.75f, 0.4f, 0.75f));
    CHECK_FALSE(edge_crosses_container(w.topo.container, 0.6f, 0.55f, 0.4f, 0.55f));
    CHECK_FALSE(edge_crosses_container(w.topo.container, 0.6f, 0.75f, 0.6f, 0.55f));
    // An edge that leaves through the outline with one end outside crosses too.
    CHECK(edge_crosses_container(w.topo.container, 0.9f, 0.5f, 1.1f, 0.5f));

    const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
    const StepForces f = step_forces(w.topo, w.state, step_params(p), g, nullptr);
    for (int v = 0; v < 12; ++v) {
      INFO("vertex " << v);
      CHECK(((f.contact[v] & contact_outside) != 0) == (v == 6));
    }
    CHECK(f.closest[6] == 0.0f);
    // The slice shrinks back, as a spilling slice does; its neighbours may grow.
    SimState state = w.state;
    for (float& g_s : state.growth) g_s = 2.0f;
    Params grow = p;
    grow.growth.growth_ratio = 100.0;
    grow.growth.neighbour_growth_ratio = 100.0;
    std::vector<std::uint8_t> changed;
    test::grow_step(w.topo, f.contact, grow, true, state, changed);
    CHECK((changed[1] & growth_shrank) != 0);
    CHECK(state.growth[1] < 2.0f);
  }
}

TEST_CASE("containment: a lone element in a large container stops at the wall, inside it") {
  // One star in the heart. Without the wall as a neighbour its slice gap stays infinite, the stop test
  // never passes and it grows to max_growth, far past the heart. Seeded in the heart's middle (a count's
  // seeds are spread, docs/parameters.md "Seeds for a fixed count"), it stops at g ≈ 6 by the stall test,
  // its slices within 1.5 stop_gap of the wall (before the fold guard it reached g ≈ 7.5 by the gap test,
  // with its tips folded over against the wall: docs/parameters.md, "Folds").
  const World w = make_world(parse_scene(
      test::star_scene(1, 5, 2, {"", R"("cell_size": 0.2, "interior_spacing": 0.5, "max_iterations": 60000)"}),
      "tiny.json", "/"));
  REQUIRE(w.elements.size() == 1);
  auto backend = make_reference_backend(w.topology, w.state, w.params);
  const RunResult r = run_simulation(*backend, w.params, RunControl{});
  INFO("stopped: " << stop_reason_name(r.reason) << " after " << r.last_good.iteration << " iterations, gap "
                   << r.last.max_slice_gap << ", g " << r.last.min_growth << " to " << r.last.max_growth);
  REQUIRE((r.reason == StopReason::gap || r.reason == StopReason::stalled));
  CHECK(r.last.max_slice_gap < 2.0f * static_cast<float>(w.params.stop.stop_gap));
  CHECK(r.last.max_growth < 0.75f * static_cast<float>(w.params.growth.max_growth));
  CHECK(r.last.max_growth > 3.0f);  // it did grow to the wall: a tenth of the heart's width at least
  int outside = 0;
  for (std::int32_t v = 0; v < w.topology.vertex_count(); ++v)
    outside += !w.container.contains({r.last_good.x[v], r.last_good.y[v]});
  CHECK(outside == 0);
}

namespace {

// A ring of `n` points on an ellipse about (cx, cy), wobbling in radius so the segments differ in length.
test::Ring wobbly_ring(float cx, float cy, float rx, float ry, int n, float wobble, bool reverse) {
  test::Ring r;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * 3.14159265358979 * k / n;
    const double s = 1.0 + wobble * std::sin(5.0 * a);
    r.push_back({static_cast<float>(cx + rx * s * std::cos(a)), static_cast<float>(cy + ry * s * std::sin(a))});
  }
  if (reverse) std::reverse(r.begin(), r.end());
  return r;
}

bool same_float(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("containment: the container index answers every query exactly as trying every segment does") {
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> coord(-0.3f, 1.3f);
  const std::vector<std::vector<test::Ring>> containers = {
      {wobbly_ring(0.5f, 0.5f, 0.45f, 0.4f, 300, 0.05f, false), wobbly_ring(0.5f, 0.5f, 0.15f, 0.12f, 120, 0.1f, true)},
      {wobbly_ring(0.5f, 0.5f, 0.48f, 0.48f, 64, 0.0f, false)},  // a circle: its middle is near every segment
      {test::square(0.5f, 0.5f, 0.5f), test::square(0.3f, 0.3f, 0.05f), test::square(0.7f, 0.6f, 0.1f)},
  };
  for (std::size_t c = 0; c < containers.size(); ++c) {
    WorldBuilder b;
    b.set_container(containers[c]);
    const test::TinyWorld w = b.build();
    const ContainerGeometry& indexed = w.topo.container;
    REQUIRE(indexed.index.nx > 0);
    ContainerGeometry plain = indexed;
    plain.index = ContainerIndex{};
    // Random points, the segments' end points and middles, points on cell borders, outside the grid, NaN.
    std::vector<std::array<float, 2>> points;
    for (int k = 0; k < 4000; ++k) points.push_back({coord(rng), coord(rng)});
    for (std::size_t i = 0; i < indexed.ax.size(); ++i) {
      points.push_back({indexed.ax[i], indexed.ay[i]});
      points.push_back({0.5f * (indexed.ax[i] + indexed.bx[i]), 0.5f * (indexed.ay[i] + indexed.by[i])});
    }
    for (int k = 0; k <= indexed.index.nx; ++k)
      points.push_back({indexed.index.x0 + static_cast<float>(k) * indexed.index.cell, coord(rng)});
    for (int k = 0; k <= indexed.index.ny; ++k)
      points.push_back({coord(rng), indexed.index.y0 + static_cast<float>(k) * indexed.index.cell});
    points.push_back({std::nanf(""), 0.5f});
    points.push_back({0.5f, std::nanf("")});
    std::size_t inside = 0, listed = 0;
    for (const auto& p : points) {
      for (const bool nearest : {false, true}) {
        const ContainerQuery a = container_query(indexed, p[0], p[1], nearest);
        const ContainerQuery e = container_query(plain, p[0], p[1], nearest);
        INFO("container " << c << " point " << p[0] << ", " << p[1] << " nearest " << nearest);
        CHECK(a.inside == e.inside);
        CHECK(same_float(a.distance2, e.distance2));
        CHECK(same_float(a.qx, e.qx));
        CHECK(same_float(a.qy, e.qy));
        inside += a.inside ? 1 : 0;
      }
    }
    CHECK(inside > points.size() / 4);  // the points test both sides of the wall
    // The index must actually narrow the search: fewer segments per cell than the container has.
    const ContainerIndex& ix = indexed.index;
    for (std::int32_t cell = 0; cell < ix.nx * ix.ny; ++cell)
      listed += static_cast<std::size_t>(ix.data[ix.cell_start + cell + 1] - ix.data[ix.cell_start + cell]);
    CHECK(listed < static_cast<std::size_t>(ix.nx * ix.ny) * indexed.ax.size() / 2);
  }
}
