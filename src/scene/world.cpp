#include <algorithm>
#include <cmath>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"
#include "placement.hpp"

namespace animpak {
namespace {

using scene_detail::Placement;

// Appends instance `p` (library element `e`) to the topology and the initial state.
void append_instance(Topology& topo, SimState& state, const SpacetimeElement& e, const Placement& p, int index) {
  const int P = e.vertices_per_slice(), B = e.slice.boundary_count, n = e.slice_count;
  const auto V = static_cast<std::int32_t>(topo.element.size());
  const auto S = static_cast<std::int32_t>(topo.slice_boundary.size());
  auto key = p.keys.begin();
  for (int s = 0; s < n; ++s) {
    const bool keyed = key != p.keys.end() && key->slice == s;
    topo.slice_begin.push_back(V + s * P);
    topo.slice_boundary.push_back(B);
    topo.slice_element.push_back(index);
    const float t = static_cast<float>(s) / static_cast<float>(n - 1);
    for (int v = 0; v < P; ++v) {
      const Vec2 q = scene_detail::placed(p, e, s, v);
      std::uint8_t flags = v < B ? vertex_boundary : 0;
      std::int32_t target = -1;
      if (keyed && key->hold_angle) flags |= vertex_hold_angle;
      if (keyed && v == p.anchor) {
        flags |= vertex_anchor;
        target = static_cast<std::int32_t>(topo.target_x.size());
        topo.target_x.push_back(key->point.x);
        topo.target_y.push_back(key->point.y);
        topo.target_t.push_back(key->point.t);
      }
      topo.element.push_back(index);
      topo.slice.push_back(S + s);
      topo.flags.push_back(flags);
      topo.target.push_back(target);
      topo.rest_t.push_back(t);
      topo.rest_copy_x.push_back(static_cast<float>(q.x));
      topo.rest_copy_y.push_back(static_cast<float>(q.y));
      topo.rest_copy_t.push_back(t);
      state.x.push_back(static_cast<float>(q.x));
      state.y.push_back(static_cast<float>(q.y));
      state.t.push_back(t);
    }
    if (keyed) ++key;
    for (const Triangle& tri : e.slice.triangles) {
      topo.tri_a.push_back(V + s * P + tri[0]);
      topo.tri_b.push_back(V + s * P + tri[1]);
      topo.tri_c.push_back(V + s * P + tri[2]);
    }
  }
  for (int v = 0; v < e.vertex_count(); ++v) {
    for (int k = e.springs.offsets[v]; k < e.springs.offsets[v + 1]; ++k) {
      topo.spring_other.push_back(V + e.springs.neighbors[k]);
      topo.spring_class.push_back(static_cast<std::uint8_t>(e.springs.classes[k]));
    }
    topo.spring_begin.push_back(static_cast<std::int32_t>(topo.spring_other.size()));
  }
  for (const Triangle& tri : e.envelope) {
    topo.env_a.push_back(V + tri[0]);
    topo.env_b.push_back(V + tri[1]);
    topo.env_c.push_back(V + tri[2]);
    topo.env_element.push_back(index);
  }
  topo.element_slice_begin.push_back(S + n);
}

// Rest copy centroids and torsion rest directions: the slice's mean vertex, summed in index order
// exactly as the solver sums the current centroid.
void finish_slices(Topology& topo) {
  const std::int32_t slices = topo.slice_count();
  topo.slice_begin.push_back(topo.vertex_count());
  topo.rest_dir_x.resize(topo.vertex_count());
  topo.rest_dir_y.resize(topo.vertex_count());
  for (std::int32_t s = 0; s < slices; ++s) {
    float sx = 0.0f, sy = 0.0f;
    const std::int32_t begin = topo.slice_begin[s], end = topo.slice_begin[s + 1];
    for (std::int32_t v = begin; v < end; ++v) sx += topo.rest_copy_x[v], sy += topo.rest_copy_y[v];
    const float count = static_cast<float>(end - begin);
    topo.slice_rest_copy_cx.push_back(sx / count);
    topo.slice_rest_copy_cy.push_back(sy / count);
    for (std::int32_t v = begin; v < end; ++v) {
      const float dx = topo.rest_copy_x[v] - sx / count, dy = topo.rest_copy_y[v] - sy / count;
      const float length = std::sqrt(dx * dx + dy * dy);
      topo.rest_dir_x[v] = length > 0.0f ? dx / length : 1.0f;
      topo.rest_dir_y[v] = length > 0.0f ? dy / length : 0.0f;
    }
  }
}

// Incident slice triangles per vertex (overlap force, Eq. 3): count, scan, fill in triangle order.
void incident_triangles(Topology& topo) {
  const std::int32_t n = topo.vertex_count();
  topo.tri_begin.assign(n + 1, 0);
  for (std::size_t k = 0; k < topo.tri_a.size(); ++k)
    for (std::int32_t v : {topo.tri_a[k], topo.tri_b[k], topo.tri_c[k]}) ++topo.tri_begin[v + 1];
  for (std::int32_t v = 0; v < n; ++v) topo.tri_begin[v + 1] += topo.tri_begin[v];
  topo.tri_list.resize(topo.tri_begin[n]);
  std::vector<std::int32_t> cursor(topo.tri_begin.begin(), topo.tri_begin.end() - 1);
  for (std::size_t k = 0; k < topo.tri_a.size(); ++k)
    for (std::int32_t v : {topo.tri_a[k], topo.tri_b[k], topo.tri_c[k]})
      topo.tri_list[cursor[v]++] = static_cast<std::int32_t>(k);
}

void container_segments(Topology& topo, const Container& c) {
  auto add_ring = [&](const std::vector<Vec2>& ring) {
    topo.container.ring_begin.push_back(static_cast<std::int32_t>(topo.container.ax.size()));
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      topo.container.ax.push_back(static_cast<float>(a.x));
      topo.container.ay.push_back(static_cast<float>(a.y));
      topo.container.bx.push_back(static_cast<float>(b.x));
      topo.container.by.push_back(static_cast<float>(b.y));
    }
  };
  add_ring(c.outline);
  for (const auto& h : c.holes) add_ring(h);
  topo.container.ring_begin.push_back(static_cast<std::int32_t>(topo.container.ax.size()));
  index_container(topo.container);
}

}  // namespace

std::uint64_t element_seed(std::uint64_t scene_seed, std::size_t index) {
  Rng rng(scene_seed ^ (0x9e3779b97f4a7c15ull * (index + 1)));
  return rng.next();
}

World build_world(const SceneSpec& scene, Container container, std::vector<SpacetimeElement> library) {
  World world;
  world.params = scene.params;
  world.seed = scene.seed;
  world.loop = scene.loop;
  if (scene.loop)
    for (const LibraryElementSpec& spec : scene.elements)
      if (!spec.animation.loop)
        throw InputError(scene.file.string() + ": element \"" + spec.name +
                         "\" has a non-looping animation but the scene loops; set its animation.loop to true or the "
                         "scene's loop to false");

  // Envelope-triangle centroids sit a third of a slice gap off each slice; the 3×3×3 block reaches at
  // least one cell, so slices more than three cells apart in t never see each other's envelopes.
  const double slice_gap = 1.0 / (scene.params.element.slices - 1);
  if (slice_gap > 3.0 * scene.params.forces.cell_size)
    world.notes.push_back("warning: slices are " + std::to_string(slice_gap) + " apart in t, more than three " +
                          "collision-grid cells (cell_size " + std::to_string(scene.params.forces.cell_size) +
                          "): elements will not see each other; use at least " +
                          std::to_string(static_cast<int>(std::ceil(1.0 / (3.0 * scene.params.forces.cell_size))) + 1) +
                          " slices or params.cell_size >= " + std::to_string(slice_gap / 3.0));

  // A scripted motion that the curve between the scene's slices cannot follow within 1 % of the element's
  // size (docs/parameters.md, "How many slices a motion needs").
  for (const SpacetimeElement& e : library)
    if (const std::string warning = slice_advice_warning(e); !warning.empty())
      world.notes.push_back("warning: " + warning);

  Rng rng(scene.seed);
  std::vector<Placement> placements = scene_detail::place_guided(scene, container, library, world.notes);
  const Rng unguided_rng = rng;
  std::vector<Placement> unguided =
      scene_detail::place_unguided(scene, container, library, placements, rng, world.notes);
  for (Placement& p : unguided) {
    if (scene.loop) p.loop_partner = static_cast<int>(placements.size());
    placements.push_back(std::move(p));
  }
  if (placements.empty())
    throw InputError(scene.file.string() +
                     ": the scene places no element; give elements a count or weight, or add guided elements");
  scene_detail::check_placements(scene, container, library, placements, unguided_rng);

  Topology& topo = world.topology;
  topo.spring_begin.push_back(0);
  topo.element_slice_begin.push_back(0);
  for (std::size_t i = 0; i < placements.size(); ++i) {
    const Placement& p = placements[i];
    const SpacetimeElement& e = library[p.library];
    const auto [smallest, largest] = std::minmax_element(p.scale.begin(), p.scale.end());
    world.elements.push_back({p.name, p.library, p.guided, p.secondary, topo.vertex_count(), topo.slice_count(),
                              p.guided ? p.offset.front() : p.seed, p.angle.front(),
                              p.guided ? 1.0 : *smallest / *largest});
    topo.element_secondary.push_back(p.secondary ? 1 : 0);
    append_instance(topo, world.state, e, p, static_cast<int>(i));
  }
  finish_slices(topo);
  incident_triangles(topo);
  container_segments(topo, container);

  for (std::size_t i = 0; i < placements.size(); ++i) {
    const int partner = placements[i].loop_partner;
    if (partner < 0) continue;
    const SpacetimeElement& e = library[placements[i].library];
    const int last = e.slice_count - 1;
    for (int v = 0; v < e.vertices_per_slice(); ++v) {
      topo.loop_end.push_back(world.elements[i].vertex_begin + e.id(last, v));
      topo.loop_start.push_back(world.elements[partner].vertex_begin + v);
    }
  }

  world.curve = curve_links(topo);
  world.chains = curve_chains(topo, world.curve);

  SimState& state = world.state;
  const std::size_t n = state.x.size();
  state.vx.assign(n, 0.0f);
  state.vy.assign(n, 0.0f);
  state.vt.assign(n, 0.0f);
  state.growth.assign(topo.slice_count(), 1.0f);
  state.spring_rest.resize(topo.spring_other.size());
  for (std::int32_t v = 0; v < topo.vertex_count(); ++v)
    for (std::int32_t k = topo.spring_begin[v]; k < topo.spring_begin[v + 1]; ++k)
      state.spring_rest[k] = rest_copy_length(topo, state.growth, v, k);

  world.container = std::move(container);
  world.library = std::move(library);
  return world;
}

World make_world(const SceneSpec& scene) {
  Container container =
      make_container(load_art(scene.container.art, {scene.params.art.flatten_tolerance}), scene.container);
  if (scene.mirror) container = mirror_container(container, *scene.mirror, scene.file.string());
  std::vector<SpacetimeElement> library;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const LibraryElementSpec& spec = scene.elements[i];
    const ArtShape art = load_art(spec.art, {scene.params.art.flatten_tolerance});
    library.push_back(build_element(spec.name, art, spec.animation, scene.params, element_seed(scene.seed, i)));
  }
  return build_world(scene, std::move(container), std::move(library));
}

}  // namespace animpak

namespace animpak {

double unit_mesh_density(const World& world) {
  const double container = world.container.area();
  if (!(container > 0)) return 0.0;
  double sum = 0.0;
  for (const ElementInstance& e : world.elements) {
    const SpacetimeElement& lib = world.library[e.library];
    const int per_slice = lib.vertices_per_slice();
    double area = 0.0;
    for (int s = 0; s < lib.slice_count; ++s)
      for (const Triangle& t : lib.slice.triangles) {
        const auto at = [&](int v) {
          const int id = e.vertex_begin + s * per_slice + v;
          return Vec2{world.topology.rest_copy_x[id], world.topology.rest_copy_y[id]};
        };
        const Vec2 a = at(t[0]), b = at(t[1]), c = at(t[2]);
        area += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
      }
    if (lib.slice_count > 0) sum += area / lib.slice_count;
  }
  return sum / container;
}

}  // namespace animpak
