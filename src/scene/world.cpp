#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"
#include "placement.hpp"

namespace animpak {
namespace {

using scene_detail::Placement;

// Slice s of instance `p` as placed in the container at rest, carried by the container's motion at the
// slice's time (docs/scene-format.md, "A container that moves"): the whole slice by the similarity, or,
// when the elements do not inherit the container's scale, its centroid by the similarity and its shape
// by the turn alone. A container that does not move leaves the positions as placed, bit for bit.
std::vector<Vec2> placed_slice(const Container& container, const SpacetimeElement& e, const Placement& p, int s) {
  const int P = e.vertices_per_slice();
  std::vector<Vec2> q(static_cast<std::size_t>(P));
  for (int v = 0; v < P; ++v) q[v] = scene_detail::placed(p, e, s, v);
  if (!container.motion.moves()) return q;
  const Similarity m = container.motion.at(static_cast<double>(s) / (e.slice_count - 1));
  if (container.inherit_scale) {
    for (Vec2& x : q) x = m.apply(x);
    return q;
  }
  Vec2 c;
  for (const Vec2& x : q) c = c + x;
  c = c * (1.0 / P);
  const Vec2 moved = m.apply(c);
  const double k = 1.0 / m.scale();
  for (Vec2& x : q) x = moved + m.linear(x - c) * k;
  return q;
}

// Appends instance `p` (library element `e`) to the topology and the initial state.
void append_instance(Topology& topo, SimState& state, const Container& container, const SpacetimeElement& e,
                     const Placement& p, int index) {
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
    const std::vector<Vec2> slice = placed_slice(container, e, p, s);
    for (int v = 0; v < P; ++v) {
      const Vec2 q = slice[v];
      std::uint8_t flags = v < B ? vertex_boundary : 0;
      std::int32_t target = -1;
      if (keyed && key->hold_angle) flags |= vertex_hold_angle;
      if (keyed && v == p.anchor) {
        flags |= vertex_anchor;
        target = static_cast<std::int32_t>(topo.target_x.size());
        // Targets are given in the container's frame: they move with it.
        const Vec2 goal = container.motion.moves()
                              ? container.motion.at(key->point.t).apply(Vec2{key->point.x, key->point.y})
                              : Vec2{key->point.x, key->point.y};
        topo.target_x.push_back(static_cast<float>(goal.x));
        topo.target_y.push_back(static_cast<float>(goal.y));
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
  for (const Similarity& m : c.motion.table()) {
    topo.container.motion_a.push_back(static_cast<float>(m.a));
    topo.container.motion_b.push_back(static_cast<float>(m.b));
    topo.container.motion_ex.push_back(static_cast<float>(m.ex));
    topo.container.motion_ey.push_back(static_cast<float>(m.ey));
  }
}

std::string with_commas(double value) {
  const std::string digits = std::to_string(std::llround(value));
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && digits[i - 1] != '-' && (digits.size() - i) % 3 == 0) out.push_back(',');
    out.push_back(digits[i]);
  }
  return out;
}

std::string short_number(double v) {
  std::ostringstream text;
  text << std::setprecision(3) << v;
  return text.str();
}

// docs/cli.md, "Limits": the elements and mesh vertices a scene builds, refused before the expensive
// steps, so that a scene asking for millions is refused at once instead of after hours of seeding or
// gigabytes of meshes. `per_slice[i]` is library element i's vertices per slice and every element has
// `slices` slices. Before meshing (`meshed` false) per_slice is an estimate from the params and only the
// library elements, meshed next, are counted; once they are meshed it is exact and every copy counts. A
// scene that fills seeds at params.seed_spacing: at most about one seed per √3/2 · spacing² of the
// container (discs of that spacing packed hexagonally), each counted as the largest element drawn by weight.
void check_scene_size(const SceneSpec& scene, const Container& container, const std::vector<double>& per_slice,
                      int slices, bool meshed) {
  const std::string file = scene.file.string();
  double fixed = 0.0, fixed_vertices = 0.0, weighted_largest = 0.0, library = 0.0;
  bool weighted = false;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const LibraryElementSpec& e = scene.elements[i];
    library += per_slice[i] * slices;
    if (e.count) {
      fixed += *e.count;
      fixed_vertices += *e.count * per_slice[i] * slices;
    } else if (e.weight > 0) {
      weighted = true;
      weighted_largest = std::max(weighted_largest, per_slice[i]);
    }
  }
  double guided_vertices = 0.0;
  for (const GuidedSpec& g : scene.guided)
    for (std::size_t i = 0; i < scene.elements.size(); ++i)
      if (scene.elements[i].name == g.element) guided_vertices += per_slice[i] * slices;
  const bool fill = !scene.count && weighted;
  const double spacing = scene.params.placement.seed_spacing;
  const double fill_seeds = std::floor(container.area() / (0.5 * std::sqrt(3.0) * spacing * spacing));
  const double unguided = fill ? std::max(fixed, fill_seeds) : std::max<double>(scene.count.value_or(0), fixed);
  const double elements = unguided + static_cast<double>(scene.guided.size());
  const std::string filled = fill ? "filling the container (" + short_number(container.area()) +
                                        " of the unit square) at params.seed_spacing " + short_number(spacing) +
                                        " seeds about " + with_commas(fill_seeds) + "; "
                                  : "";
  const std::string guided = std::to_string(scene.guided.size()) + " guided";
  if (elements > kMaxSceneElements)
    throw InputError(file + ": the scene would build about " + with_commas(elements) + " elements (" + filled +
                     with_commas(unguided) + " unguided, " + guided + "), more than the " +
                     with_commas(kMaxSceneElements) + " a scene may build (docs/cli.md, \"Limits\"); " +
                     (fill ? "raise params.seed_spacing or give the elements counts" : "lower the counts"));
  const double vertices =
      meshed ? library + guided_vertices + fixed_vertices + (unguided - fixed) * weighted_largest * slices : library;
  if (vertices <= kMaxSceneVertices) return;
  const auto [smallest, largest] = std::minmax_element(per_slice.begin(), per_slice.end());
  const std::string sizes =
      meshed
          ? (*smallest == *largest ? with_commas(*largest) : with_commas(*smallest) + " to " + with_commas(*largest)) +
                " vertices per slice as meshed"
          : "about " + with_commas(*largest) +
                " vertices per slice, estimated from params.interior_spacing and params.boundary_spacing";
  const std::string library_elements =
      std::to_string(scene.elements.size()) + (scene.elements.size() == 1 ? " library element" : " library elements");
  const std::string what = meshed ? filled + with_commas(elements) + " elements and " + library_elements
                                  : library_elements + ", before any copy";
  throw InputError(file + ": the scene would build about " + with_commas(vertices) + " mesh vertices (" + what + "; " +
                   std::to_string(slices) + " slices, " + sizes + "), more than the " + with_commas(kMaxSceneVertices) +
                   " a scene may build (docs/cli.md, \"Limits\"); lower the counts or `slices`, or raise "
                   "params.interior_spacing and params.boundary_spacing");
}

}  // namespace

std::uint64_t element_seed(std::uint64_t scene_seed, std::size_t index) {
  Rng rng(scene_seed ^ (0x9e3779b97f4a7c15ull * (index + 1)));
  return rng.next();
}

World build_world(const SceneSpec& given, Container container, std::vector<SpacetimeElement> library) {
  // A scene that sets no initial_scale and asks for more elements than place at the default starts them
  // smaller (docs/first-scene.md, "When the elements do not fit"); every step below sees that scale.
  SceneSpec picked;
  const std::optional<double> start = scene_detail::picked_initial_scale(given, container, library, Rng(given.seed));
  if (start) {
    picked = given;
    picked.params.placement.initial_scale = *start;
  }
  const SceneSpec& scene = start ? picked : given;
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
  for (const std::string& warning : scene_warnings(scene)) world.notes.push_back("warning: " + warning);
  if (start) {
    std::ostringstream note;
    note << "params.initial_scale is not set and the elements asked for do not all place at "
         << given.params.placement.initial_scale << ": starting them at " << *start << " ("
         << scene_detail::kPickedScaleShare << " of the largest at which they do); set params.initial_scale to choose";
    world.notes.push_back(note.str());
  }

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

  // The exact mesh sizes, before seeding and placing (docs/cli.md, "Limits").
  std::vector<double> per_slice(scene.elements.size(), 0.0);
  for (std::size_t i = 0; i < per_slice.size() && i < library.size(); ++i)
    per_slice[i] = library[i].vertices_per_slice();
  check_scene_size(scene, container, per_slice,
                   library.empty() ? scene.params.element.slices : library.front().slice_count, true);

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
    append_instance(topo, world.state, container, e, p, static_cast<int>(i));
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

  link_curves(topo);

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

ArtShape load_element_art(const SceneSpec& scene, std::size_t index) {
  const LibraryElementSpec& spec = scene.elements.at(index);
  SvgOptions options;
  options.flatten_tolerance = scene.params.art.flatten_tolerance;
  options.exclude = spec.exclude;
  try {
    return load_art(spec.art, options);
  } catch (const ExcludeError& e) {
    // The scene's entry is what the designer edits: name it, and the element and art it applies to.
    throw InputError(scene.file.string() + ": elements[" + std::to_string(index) + "].exclude[" +
                     std::to_string(e.index) + "]: \"" + e.selector + "\" in " + spec.art.string() + " (element `" +
                     spec.name + "`): " + e.problem);
  }
}

World make_world(const SceneSpec& scene) {
  Container container =
      make_container(load_art(scene.container.art, {scene.params.art.flatten_tolerance}), scene.container);
  if (scene.mirror) container = mirror_container(container, *scene.mirror, scene.file.string());
  animate_container(container, scene);
  // Before any element is meshed (docs/cli.md, "Limits"): per slice, the interior samples the art's box
  // grown by the offset holds at interior_spacing (packed hexagonally, the most it can hold) and about
  // its perimeter over boundary_spacing on the boundary.
  const Params::Element& mesh = scene.params.element;
  const double side = 1.0 + 2.0 * mesh.offset;
  const double estimate =
      std::ceil(side * side / (0.5 * std::sqrt(3.0) * mesh.interior_spacing * mesh.interior_spacing)) +
      std::ceil(4.0 * side / mesh.boundary_spacing);
  check_scene_size(scene, container, std::vector<double>(scene.elements.size(), estimate), mesh.slices, false);
  std::vector<SpacetimeElement> library;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const LibraryElementSpec& spec = scene.elements[i];
    const ArtShape art = load_element_art(scene, i);
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
