// Scene set-up (paper §4): the container normalized into the unit square and extruded over t, the
// element instances placed in it, and the initial simulation state.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "animpak/container_motion.hpp"
#include "animpak/curve.hpp"
#include "animpak/element.hpp"
#include "animpak/io.hpp"
#include "animpak/random.hpp"
#include "animpak/scene_spec.hpp"
#include "animpak/state.hpp"

namespace animpak {

/// The line a mirrored scene is reflected across (docs/scene-format.md, "Mirror"), in unit coordinates.
struct MirrorLine {
  bool vertical = true;  ///< x = at (true) or y = at
  double at = 0.0;
  Vec2 reflect(Vec2 p) const { return vertical ? Vec2{2.0 * at - p.x, p.y} : Vec2{p.x, 2.0 * at - p.y}; }
};

/// The container in unit coordinates: its outline and holes, each a simple ring without repeats.
struct Container {
  std::vector<Vec2> outline;
  std::vector<std::vector<Vec2>> holes;
  ArtFrame frame;               ///< container art coordinates → unit square (targets, field centres use it)
  ArtShape art;                 ///< the container's art in unit coordinates (stroke widths too), for drawing it
  int outline_path = -1;        ///< source index of the art path the outline was taken from
  std::vector<int> hole_paths;  ///< source index of each hole's path, in `holes` order
  /// Mirror symmetry: `outline` and `holes` are the side that is simulated, the line is a wall of it, and
  /// the frames show that side and its reflection, whose outline and holes are `whole_outline` and
  /// `whole_holes` (mirror_container).
  std::optional<MirrorLine> mirror;
  std::vector<Vec2> whole_outline;
  std::vector<std::vector<Vec2>> whole_holes;
  /// Its motion as a whole (docs/scene-format.md, "A container that moves"): at time t the container is
  /// motion.at(t) applied to `outline` and `holes`, which are its shape at rest. It does not move unless
  /// the scene animates it (animate_container).
  ContainerMotion motion;
  /// The elements take the motion's change of scale into their scripts (ContainerSpec::inherit_scale).
  bool inherit_scale = true;

  /// Inside the outline and outside every hole.
  bool contains(Vec2 p) const;
  /// Distance to the nearest point of the outline or of a hole.
  double distance_to_boundary(Vec2 p) const;
  /// Outline area minus hole areas.
  double area() const;
  /// Box of the outline (holes lie inside it).
  Box bounds() const;
  /// The outline and holes the frames draw and measure: the whole of a mirrored container, or these.
  const std::vector<Vec2>& shown_outline() const { return mirror ? whole_outline : outline; }
  const std::vector<std::vector<Vec2>>& shown_holes() const { return mirror ? whole_holes : holes; }
  /// Box of the shown outline: the frames' extent.
  Box shown_bounds() const;
};

/// Picks the outline and holes from the container art (spec.outline / spec.holes by source index;
/// defaults: holes are `.path` type-7 paths, the outline is the largest remaining closed polyline) and
/// normalizes them like element art (longer side 1, centred). InputError names the file and the path
/// index for a missing index, an outline with fewer than 3 points or no area, or a hole outside it.
Container make_container(const ArtShape& art, const ContainerSpec& spec);

/// Sets container.motion from the scene's `container.animation` (pivot in container art coordinates,
/// default the outline's area centroid; looping with the scene) and container.inherit_scale. InputError
/// naming the scene file for an animated mirrored scene or an animation the container cannot take.
/// container.cpp.
void animate_container(Container& container, const SceneSpec& scene);

/// The side of `whole` that `spec` keeps, for a mirrored scene (docs/scene-format.md, "Mirror"): the
/// container clipped to that side of the line (in the container art's coordinates, through whole.frame),
/// with `mirror` set and, as `whole_outline`/`whole_holes`, that side united with its reflection, which is
/// what the frames show. InputError when the line misses the container or leaves the kept side in more
/// than one piece, or an island inside a hole. mirror.cpp.
Container mirror_container(const Container& whole, const MirrorSpec& spec, const std::string& scene_name);

/// Builds box.index, the container query's segment index, for `cells` cells along the longer side of the
/// segments' bounding box (square cells; a container without segments gets none). container_index.cpp.
void index_container(ContainerGeometry& box, std::int32_t cells = 32);

/// Blue-noise (Poisson-disk, Bridson) points inside the container, at least `min_distance` apart and
/// at least `margin` from the boundary, in generation order. Deterministic for the generator's state.
std::vector<Vec2> poisson_disk(const Container& container, double min_distance, double margin, Rng& rng);

/// `wanted` of `candidates`, spread evenly by farthest-point selection: candidates[first] first (the
/// first candidate if `first` is past the end), then
/// each pick the candidate farthest from everything already there: the picks so far, the `occupied`
/// points (guided elements' paths) and the wall, where the wall counts at twice its distance (as the
/// mirror image of a seed there, so seeds settle half a spacing from it). The first maximum wins;
/// deterministic. Fewer than `wanted` candidates: all of them, in selection order.
std::vector<Vec2> spread_seeds(const Container& container, const std::vector<Vec2>& candidates, int wanted,
                               const std::vector<Vec2>& occupied, std::size_t first = 0);

/// Lloyd relaxation of `seeds` towards a centroidal Voronoi arrangement: `iterations` times, every seed
/// moves to the centroid of the container points nearer to it than to any other seed or `occupied`
/// point (a 128 × 128 grid over the container's box), unless that would bring it nearer than `margin`
/// to the wall or nearer than `clearance` to an occupied point. Deterministic.
std::vector<Vec2> relax_seeds(const Container& container, std::vector<Vec2> seeds, const std::vector<Vec2>& occupied,
                              double margin, double clearance, int iterations);

/// One element in the container: a library element, shrunk, oriented and placed.
struct ElementInstance {
  std::string name;  ///< "<library name>#<k>" for unguided elements, the guided name otherwise
  int library = 0;   ///< index into World::library
  bool guided = false;
  bool secondary = false;  ///< docs/parameters.md, "Secondary elements"
  int vertex_begin = 0;    ///< its first global vertex id
  int slice_begin = 0;     ///< its first global slice id
  Vec2 position;           ///< unit coordinates of its seed (unguided) or first target (guided)
  double angle = 0.0;      ///< radians, clockwise on screen
  /// Its smallest start scale over its largest: below 1 where its script dips while a traveller passes
  /// (params.make_way_dip, docs/parameters.md, "Making way"); 1 for an unguided element that never dips.
  double dip = 1.0;
};

/// Everything a simulation starts from.
struct World {
  Container container;
  std::vector<SpacetimeElement> library;  ///< built once per library entry, full size, animated
  std::vector<ElementInstance> elements;
  Topology topology;  ///< with its curve links and chains (link_curves)
  SimState state;     ///< the initial state: shrunken elements at rest, g = 1
  Params params;
  std::uint64_t seed = 1;
  bool loop = true;
  std::vector<std::string> notes;  ///< what set-up decided, one line each (seed spacing, rejections)
};

/// Places the elements of `scene` (paper §4): guided elements along their targets, unguided ones on
/// blue-noise seeds, each shrunk to params.placement.initial_scale; then checks that nothing overlaps and that
/// every element is inside the container. InputError names the elements (and slice) at fault.
World build_world(const SceneSpec& scene, Container container, std::vector<SpacetimeElement> library);

/// Slice vertex positions of element instance `element` at frame time tf (paper §6): on the curve between
/// the two consecutive slices whose current t values bracket tf (include/animpak/curve.hpp; the paper's
/// linear interpolation with `motion_curve` 0).
std::vector<Vec2> element_at(const World& world, const SimState& state, int element, double tf);
/// The interval of element instance `element` (of two slices or more) that element_at reads at time tf:
/// its first slice (of the element's), tf's share of the way to the next one (0 to 1), and its length in t.
struct SliceInterval {
  int slice = 0;
  double share = 0.0, length = 0.0;
};
SliceInterval slice_interval(const World& world, const SimState& state, int element, double tf);
/// The same with the element's tangents computed once (element_tangents), for many times of one state.
std::vector<Vec2> element_at(const World& world, const SimState& state, int element, double tf,
                             const std::vector<Vec2>& tangents);
/// The curve's tangent (dx/dt, dy/dt) at every vertex of every slice of element `element`, slice-major
/// (slice s, vertex v at s · vertices_per_slice + v), in double: the spline's from a solve along the chain
/// its slices lie on, Steffen's from their neighbours, or zeros for straight lines.
std::vector<Vec2> element_tangents(const World& world, const SimState& state, int element);

/// How many elements the frames draw and measure: every element, then under mirror symmetry the reflection of each
/// (drawn element N + i is element i reflected across Container::mirror; docs/scene-format.md, "Mirror").
int drawn_count(const World& world);
/// The element drawn as `drawn`: itself, or drawn − N for a reflection.
int drawn_source(const World& world, int drawn);
/// Its name: the element's, or the element's with " mirrored" after it.
std::string drawn_name(const World& world, int drawn);

/// The share of the container the elements' meshes fill at g = 1: each element's rest copy slice area
/// (its triangles, the mean over its slices) summed over the elements, over the container's area. The
/// meshes fill the container to about 0.6 at a packing's stop (docs/cli.md, "Progress and the time left").
double unit_mesh_density(const World& world);

/// The seed of library element `index`'s slice sampling: independent per element, so adding an
/// element does not change the others.
std::uint64_t element_seed(std::uint64_t scene_seed, std::size_t index);

/// The art of `scene.elements[index]` as pack builds it: read with the scene's flatten_tolerance and its
/// `exclude` left out. A selector that does not parse or matches nothing is an InputError naming the
/// scene's field (`scene.json: elements[3].exclude[0]: …`).
ArtShape load_element_art(const SceneSpec& scene, std::size_t index);

/// Loads the scene's art, builds the library elements and calls build_world.
World make_world(const SceneSpec& scene);

}  // namespace animpak
