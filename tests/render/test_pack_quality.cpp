// A tiny real scene packs to the paper's stop criterion (§5.3: every slice's gap to its nearest
// neighbour below stop_gap), and the packed slices show no overlapping art, no art outside the container
// (both measured exactly, docs/quality.md) and far more coverage than the shrunken start; no slice
// triangle folded over and no art outside its own element's outline (docs/parameters.md, "Folds").
#include <catch2/catch.hpp>

#include "animpak/render.hpp"
#include "animpak/run.hpp"
#include "animpak/scene.hpp"
#include "scene/tiny_scenes.hpp"
#include "solver/folded_triangles.hpp"

using namespace animpak;

namespace {

// The largest share of an element's art outside its own boundary polygon at frame time tf.
double art_outside_own_outline(const World& w, const SimState& state, double tf) {
  double worst = 0.0;
  for (int e = 0; e < static_cast<int>(w.elements.size()); ++e) {
    const std::vector<Vec2> p = element_at(w, state, e, tf);
    const ElementArt art = element_art(w, e, p);
    const Region drawn = art_region(w.library[w.elements[e].library].art.art, art.points, art.stroke_scale);
    const int boundary = w.topology.slice_boundary[w.topology.element_slice_begin[e]];
    Region outline;
    outline.rings.push_back(std::vector<Vec2>(p.begin(), p.begin() + boundary));
    worst = std::max(worst, measure_regions({drawn}, outline, Measures::no_evenness).outside_share[0]);
  }
  return worst;
}

}  // namespace

TEST_CASE("run_simulation: three stars in the heart pack to the gap criterion without overlapping or spilled art") {
  // Three still stars over five slices. The collision grid finds neighbours only within one cell, and
  // envelope-triangle centroids lie 1/12 and 1/6 of the loop away from a slice here (Δt = 1/4), so the
  // paper's 0.04 cells would find none at all: cells of 0.2 restore the paper's assumption that
  // envelope triangles are small against a cell. Three elements and coarse interior sampling keep it to about
  // ten thousand cheap steps. The default growth rate matters: growing faster than the velocity cap
  // lets a vertex move (a radius gain above 5e-5 per step) pushes stars through the container and each
  // other with nothing able to push back, which this test caught at 5× and 20× the default. So does
  // boundary sampling coarser than the default: a 0.2 spacing cuts the stars' tips off their slice
  // outline and the art overlaps where the outlines do not.
  const int slices = 5;
  World w = make_world(parse_scene(animpak::test::star_scene(3, slices, 1, {"", R"("cell_size": 0.2,
                                        "interior_spacing": 0.5, "max_iterations": 60000)"},
                                                             "{}"),
                                   "tiny.json", "/"));
  double initial = 0.0;
  for (int s = 0; s < slices; ++s)
    initial = std::max(initial, measure_frame(w, w.state, s / double(slices - 1)).coverage);
  // At 7 % of full size three stars cover about 1.2 % of the heart.
  CHECK(initial < 0.03);

  auto backend = make_reference_backend(w.topology, w.state, w.params);
  const RunResult r = run_simulation(*backend, w.params, RunControl{});
  INFO("stopped: " << stop_reason_name(r.reason) << " after " << r.last_good.iteration << " iterations, gap "
                   << r.last.max_slice_gap);
  REQUIRE(r.reason == StopReason::gap);
  CHECK(r.last_good.iteration < static_cast<std::uint64_t>(w.params.stop.max_iterations));
  CHECK(r.last.max_slice_gap < static_cast<float>(w.params.stop.stop_gap));

  w.state = r.last_good;
  for (int s = 0; s < slices; ++s) {
    const FrameMetrics m = measure_frame(w, w.state, s / double(slices - 1));
    INFO("slice " << s << ": coverage " << m.coverage << ", worst overlap " << m.worst_overlap().share
                  << ", worst outside " << m.worst_outside().share);
    CHECK(m.overlapping().empty());
    CHECK(m.elements_outside().empty());
    // Measured 0.40 at every slice (seed 1). 0.25 leaves room for harmless changes to the forces but
    // is twenty times the 1.2 % start, so elements that stop growing or get pushed apart fail it.
    CHECK(m.coverage > 0.25);
    // The art is bound to the slice triangles (§3.1); a folded triangle carries its art out of the outline
    // that the overlap test and the channel see (docs/parameters.md, "Folds").
    const double outside_own = art_outside_own_outline(w, w.state, s / double(slices - 1));
    INFO("art outside its own outline: " << outside_own);
    CHECK(outside_own < 1e-3);
  }
  CHECK(test::folded_triangles(w.topology, w.state) == 0);
}
