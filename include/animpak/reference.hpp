// The scalar reference solver (paper §5): one stateless function per force, constraint and query,
// written to be read next to the paper. It is the specification the OpenCL kernels are tested against
// bit for bit, so every function does its float arithmetic in one fixed, documented order (no FMA,
// no double intermediates) and every force is GATHERED: a vertex's force is computed from one
// snapshot of all positions and written only to that vertex.
//
// Float constants: every function of the step reads them from the block step_params makes
// (include/animpak/step_params.hpp), each double of Params converted once, the same block the OpenCL host
// hands to the kernels; none converts Params itself. Only the collision grid's cell size and far-field
// switch, which shape the grid rather than enter the step's arithmetic, come from Params.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "animpak/closest_point.hpp"
#include "animpak/curve.hpp"
#include "animpak/params.hpp"
#include "animpak/simulation.hpp"
#include "animpak/spring_class.hpp"
#include "animpak/state.hpp"
#include "animpak/step_params.hpp"

namespace animpak::reference {

// ---- collision grid (§5.1), grid.cpp ----------------------------------------------------------------

/// Envelope-triangle centroids binned into cubic cells over the unit cube (x, y, t), sorted by cell
/// with a stable counting sort (count → exclusive scan → scatter), as cuNSearch does.
struct CollisionGrid {
  std::int32_t n = 0;                       ///< cells per axis
  float cell = 0.0f;                        ///< cell edge
  std::vector<float> cx, cy, ct;            ///< centroid of envelope triangle i
  std::vector<std::int32_t> triangle_cell;  ///< linear cell of envelope triangle i
  std::vector<std::int32_t>
      cell_start;  ///< n³ + 1 entries: cell c holds sorted_triangles[cell_start[c], cell_start[c+1])
  std::vector<std::int32_t> sorted_triangles;  ///< triangle ids, by cell, increasing id within a cell
  /// The element of each slot: env_element[sorted_triangles[k]], laid out in slot order (the kernels'
  /// slot_element), so the cell walks test ownership from one array instead of through two.
  std::vector<std::int32_t> slot_element;
  /// The far field's cell aggregates (docs/parameters.md, "Far field"): a run is the slots of one cell
  /// that belong to one element (consecutive, since ids are element-major). For a run's first slot k,
  /// run_next[k] is one past its last slot and run_cx/cy/ct[k] the mean of its centroids (summed in slot
  /// order, then divided by the count); other slots hold 0. Filled when far_cells is set.
  bool far_cells = false;
  std::vector<std::int32_t> run_next;
  std::vector<float> run_cx, run_cy, run_ct;
};

/// Cells per axis for a cell edge: the smallest n with n · cell ≥ 1 (25 for 0.04). Throws
/// std::invalid_argument unless 0 < cell_size ≤ 1.
std::int32_t grid_cells_per_axis(double cell_size);

/// Cell index of one coordinate: clamp(floor(c / cell), 0, n − 1); NaN goes to cell 0 (state.hpp).
using animpak::grid_axis_cell;

/// Centroid (a + b + c) / 3 of envelope triangle i, summed left to right.
Vec3f envelope_centroid(const Topology& topo, const SimState& state, std::int32_t i);

CollisionGrid build_collision_grid(const Topology& topo, const SimState& state, const Params& params);

/// Fills slot_element of a grid whose sorted_triangles are set; build_collision_grid calls it, and a
/// device backend's read-back grid too.
void fill_slot_elements(const Topology& topo, CollisionGrid& grid);

/// Fills the far-field runs of a built grid (run_next, run_cx/cy/ct; slot_element must be filled) and
/// sets far_cells; build_collision_grid calls it when params.forces.far_cells is 1, and a device backend's
/// read-back grid too.
void build_far_runs(CollisionGrid& grid);

/// Envelope triangles of elements other than `own_element` whose centroids lie in the 3×3×3 block of
/// cells around q's cell ("near"), or in the 98 cells of the outer shell of the 5×5×5 block ("far").
/// Cells outside the grid are skipped. Order: cells by dz, dy, dx ascending, then sorted order within
/// a cell. `out` is cleared first.
void near_triangles(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out);
void far_triangles(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out);

/// The near triangles as grid slots, in the same order (the triangle is sorted_triangles[k]): Eq. 1
/// adds each one's term to the partial sum of its slot mod 4 (repulsion_force). With `own_only`, the
/// slots of own_element's triangles instead (the wall's mirror image, wall_mirror_force).
void repulsion_near_slots(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out,
                          bool own_only = false);

/// What Eq. 1 visits in the outer shell, as grid slots in the same order: with grid.far_cells the first
/// slot of every run (one per cell and other element), otherwise the slot of every far triangle; with
/// `own_only`, those of own_element instead.
void repulsion_far_slots(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out,
                         bool own_only = false);

// ---- geometry helpers ---------------------------------------------------------------------------------

// closest_point_on_triangle(p, a, b, c): animpak/closest_point.hpp (inline).

/// Closest point (*qx, *qy) to (px, py) on segment ab in x, y: the projection onto the line, clamped to
/// the segment (a for a zero-length one); returns the squared distance. The container's wall and the
/// overlap test's way out both use it. closest_point.cpp.
float closest_point_on_segment(float px, float py, float ax, float ay, float bx, float by, float& qx, float& qy);

/// One step of the even–odd (ray crossing) point-in-polygon test: whether the ray from (px, py)
/// towards +x crosses segment (ax, ay)–(bx, by). Toggle "inside" on every true. segments.cpp.
bool ray_crosses_segment(float px, float py, float ax, float ay, float bx, float by);

/// Whether segments p → n and a → b cross properly: each one's ends strictly on opposite sides of the
/// other's line (touching or collinear does not count). segments.cpp.
bool segments_cross_properly(float px, float py, float nx, float ny, float ax, float ay, float bx, float by);

// ---- forces (§5); each returns the force on vertex v only ---------------------------------------------

struct RepulsionResult {
  Vec3f force;
  float closest = std::numeric_limits<float>::infinity();  ///< distance to the nearest other element
};

/// Eq. 1 on a boundary vertex: k_rpl Σ u/|u| · 1/(ε + |u|²), u = x − x_i over exact closest points on
/// the triangles of the `near` slots (repulsion_near_slots), summed in four partials by slot mod 4 and joined as
/// (p0 + p1) + (p2 + p3), then one by one over the `far` slots (repulsion_far_slots): a triangle's centroid, or
/// with grid.far_cells a run's mean centroid counted once per triangle of the run. The force is zero when
/// `overlapping` (Eq. 3 takes over) or v is not a boundary vertex; `closest` is computed for every
/// boundary vertex.
/// repulsion.cpp.
RepulsionResult repulsion_force(const Topology& topo, const SimState& state, const ForceParams& params,
                                const CollisionGrid& grid, std::int32_t v, const std::vector<std::int32_t>& near,
                                const std::vector<std::int32_t>& far, bool overlapping);

/// Per global slice, the box of its boundary polygon (x0 ≤ x ≤ x1, y0 ≤ y ≤ y1) and its t (its first
/// vertex's), from one snapshot of positions. On the spline (`tangents` with mode curve_spline) the box
/// also holds each boundary vertex's Bézier handles towards its element's neighbouring slices
/// (curve_handle), so that the union of two slices' boxes holds the curve between them. overlap.cpp.
struct SliceBoxes {
  std::vector<float> x0, y0, x1, y1, t;
};
void slice_boxes(const Topology& topo, const SimState& state, const CurveTangents& tangents, SliceBoxes& out);

/// The overlap test's broadphase (docs/architecture.md, "The overlap test"): a uniform (x, y, t) cell
/// grid over every slice pair's box (the union of its two slices' boxes, from t of one slice to t of
/// the other), listing per cell the elements owning a pair whose box meets the cell, in increasing
/// element order, each once. A grid without cells (nx = 0: a box or slice t is not finite) sends every query
/// to every element.
struct OverlapGrid {
  std::int32_t nx = 0, ny = 0, nt = 0;    ///< cells per axis
  float x0 = 0.0f, y0 = 0.0f, t0 = 0.0f;  ///< the grid's low corner
  float cell = 1.0f, cell_t = 1.0f;       ///< cell edge in x and y, in t
  std::vector<std::int32_t>
      cell_start;  ///< nx · ny · nt + 1 entries: cell c lists elements[cell_start[c], cell_start[c+1])
  std::vector<std::int32_t> elements;  ///< element ids, by cell, increasing within a cell
};

/// Builds the broadphase from this step's slice boxes: the pairs in increasing slice order, each in
/// every cell its box meets, then the stable counting sort (src/solver/counting_sort.cpp). The OpenCL
/// backend runs it on the boxes read back when it builds its grids on the host; on the device,
/// kernels/overlap_grid.cl builds a grid of its own rule, which gives the same forces. overlap.cpp.
void build_overlap_grid(const Topology& topo, const SliceBoxes& boxes, OverlapGrid& grid);

/// The elements, in increasing order and each once, whose slice-pair boxes may meet the query box
/// x ∈ [ex0, ex1], y ∈ [ey0, ey1] at time pt: the merged lists of the (at most four) cells the box
/// meets, or all `elements` when the box meets more cells or has a NaN. Every element whose pair
/// around pt passes the overlap test's box test is among them. overlap.cpp.
void overlap_candidates(const OverlapGrid& grid, std::int32_t elements, float ex0, float ex1, float ey0, float ey1,
                        float pt, std::vector<std::int32_t>& out);

/// What the overlap test found for one boundary vertex (docs/parameters.md, "Overlaps").
struct OverlapResult {
  bool overlap = false;              ///< v or a point between slices next to it lies inside another element, or
                                     ///< its edge crosses one
  bool inside = false;               ///< v or a point between slices next to it lies inside another element
  float out_x = 0.0f, out_y = 0.0f;  ///< when inside: from the deepest such point to its nearest way out
  bool yield = false;                ///< one of the elements it overlaps is, there, no larger than v's slice (g),
                                     ///< or is primary while v's element is secondary
  bool block = false;                ///< one of the elements it overlaps does not give way to v's element: any,
                                     ///< except a secondary one when v's element is primary
};

/// Every vertex's tangent at its slice (include/animpak/curve.hpp), across the loop seam by `links`, from
/// one snapshot: the C2 spline's (`mode` curve_spline), Steffen's (curve_monotone), or Steffen's weighed by
/// nothing (curve_linear: straight lines). curve.cpp.
void curve_tangents(const Topology& topo, const CurveLinks& links, const SimState& state, int mode, CurveTangents& out);

/// The overlap test of Eq. 3, at any depth: boundary vertex v (and its boundary edge to the next boundary
/// vertex of its slice) against every other element's boundary polygon on its curve at v's t (`tangents`),
/// skipping elements whose slice boxes miss the edge (only the broadphase's candidates, `grid`, are
/// tried, in increasing element order); then the same between slices, where the paper's discrete test
/// cannot see (§6, §8): each slice interval holds `interval_points` evenly spaced times, at fractions
/// j / (interval_points + 1), and v tests those of the two intervals next to it that lie in the half
/// nearer to v (v and its edge on their curves towards the neighbouring slice, at that time; the middle
/// is tested from both ends). Interior vertices and elements with fewer than two slices never overlap.
/// overlap.cpp.
OverlapResult overlap_test(const Topology& topo, const SimState& state, const SliceBoxes& boxes,
                           const OverlapGrid& grid, const CurveTangents& tangents, std::int32_t v,
                           std::int32_t interval_points);

/// Eq. 3, k_ovr Σ (p_i − x) over centroids p_i of v's incident slice triangles, plus, when v (or a point
/// between slices next to it) is inside another element, k_ovr_depth · (out_x, out_y), its way out, so
/// the push grows with depth (docs/parameters.md). overlap.cpp.
Vec3f overlap_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v,
                    const OverlapResult& overlap);

/// Stiffness of one spring class (Eq. 2's k_edg per class): params.k_spring[c], 0 for an unknown class (as
/// kernels/springs.cl reads it).
float spring_stiffness(const ForceParams& params, SpringClass c);

/// Eq. 2 summed over v's CSR slots in slot order. springs.cpp.
Vec3f spring_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);

/// The fold guard (docs/parameters.md, "Folds"): for every slice triangle of v whose signed area (oriented
/// as its rest copy's) is below fold_area · g² · its rest copy's, k_fold · the height it misses, along the
/// normal of the edge opposite v; summed in v's incident-triangle order. Zero with k_fold 0. springs.cpp.
Vec3f fold_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);

/// Eq. 2 for the target-point spring of an anchor vertex (rest length 0, class target); zero for
/// vertices without a target. target.cpp.
Vec3f target_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);

/// Where a point lies against the container (x, y only: the container is the same at every t).
struct ContainerQuery {
  bool inside = true;  ///< inside the outline and outside every hole (even–odd over all rings)
  float distance2 = std::numeric_limits<float>::infinity();  ///< squared distance to the nearest segment
  float qx = 0.0f, qy = 0.0f;  ///< that nearest point (the first segment reaching the minimum wins)
};

/// The even–odd test always; the nearest boundary point only when `nearest` or the point is outside.
/// A world without a container has every point inside. boundary.cpp.
ContainerQuery container_query(const ContainerGeometry& box, float px, float py, bool nearest);

/// Whether the boundary edge p → n properly crosses a segment of the container's boundary (touching does
/// not count). Both ends may be inside: a reflex corner of the container, such as the heart's notch,
/// then pokes into the element between them (docs/parameters.md, "Containment"). boundary.cpp.
bool edge_crosses_container(const ContainerGeometry& box, float px, float py, float nx, float ny);

/// The container's force on a point, from its query: outside, Eq. 4, k_bdr (p_b − x) in x, y; inside, for
/// a boundary vertex (`boundary`), the wall repels like a neighbour, wall_repulsion · k_rpl · u/|u| ·
/// 1/(ε + |u|²) with u = x − p_b (Eq. 1's form; docs/parameters.md, "Containment"). boundary.cpp.
Vec3f boundary_force(const ForceParams& params, const ContainerQuery& q, float px, float py, bool boundary);

/// The container's force on vertex v. boundary.cpp.
Vec3f boundary_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);

/// The wall as the mirror image of the element (docs/parameters.md, "Containment"): for a boundary vertex
/// inside the container within wall_range of its nearest wall point q (`wall`, its query with the nearest
/// point), Eq. 1 at the reflection x' = 2q − x from the element's own triangles, summed as
/// repulsion_force sums (near slots of x' in four partials, then far slots, own_only), reflected back
/// across the wall's tangent at q (s − 2 (s·n) n in x, y with n = (x − q)/|x − q|; t unchanged) and
/// weighted wall_mirror · k_rpl. The reflected element is a neighbour at twice the wall distance, so the
/// wall presses as a neighbour would. Zero otherwise, and when wall_mirror is 0. repulsion.cpp.
Vec3f wall_mirror_force(const Topology& topo, const SimState& state, const ForceParams& params,
                        const CollisionGrid& grid, std::int32_t v, const ContainerQuery& wall);

/// Current centroid of every slice (mean of its vertices in index order), for Eq. 5. torsion.cpp.
void slice_centroids(const Topology& topo, const SimState& state, std::vector<float>& cx, std::vector<float>& cy);

/// Eq. 5 with the slice centroid (cx, cy) of v's slice, at k_target_angle for a vertex_hold_angle vertex
/// and k_torsion otherwise. torsion.cpp.
Vec3f torsion_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v, float cx,
                    float cy);

/// Eq. 6: k_tmp (rest_t − t) along t. temporal.cpp.
Vec3f temporal_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);

/// What a step reads besides the forces for one vertex (growth, §5.3, and the statistics).
struct ContactGap {
  /// For a boundary vertex, the distance to the nearest other element or container wall (the slice gap
  /// of §5.3 counts the wall as a neighbour), 0 when it overlaps; +inf for interior vertices.
  float closest = std::numeric_limits<float>::infinity();
  std::uint8_t contact = 0;  ///< ContactBit flags
};

/// Vertex v's ContactGap from the step's queries: the overlap test, the nearest other element's
/// distance (`nearest`, RepulsionResult::closest) and the container query. contact.cpp.
ContactGap contact_gap(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v,
                       const OverlapResult& overlap, float nearest, const ContainerQuery& wall);

// ---- one step ------------------------------------------------------------------------------------------

/// Per-vertex force components, structure of arrays.
struct ForceField {
  std::vector<float> x, y, t;
  void assign(std::size_t n);  ///< n zero vectors
  void set(std::int32_t v, Vec3f f) {
    x[v] = f.x;
    y[v] = f.y;
    t[v] = f.t;
  }
  Vec3f at(std::int32_t v) const { return {x[v], y[v], t[v]}; }
};

/// Every force of Eq. 7 separately (the equivalence suite and `validate` compare them one by one).
struct ForceBreakdown {
  ForceField repulsion, springs, target, boundary, overlap, torsion, temporal;
};

struct StepForces {
  ForceField total;  ///< Eq. 7 per vertex
  /// Per boundary vertex, the distance to the nearest other element or container wall (the slice gap of
  /// §5.3 counts the wall as a neighbour), 0 when it overlaps; +inf for interior vertices.
  std::vector<float> closest;
  std::vector<std::uint8_t> contact;  ///< per vertex: ContactBit flags (growth pauses, shrinks, statistics)
};

/// Eq. 7 for every vertex from one snapshot of positions. forces.cpp.
StepForces step_forces(const Topology& topo, const SimState& state, const ForceParams& params,
                       const CollisionGrid& grid, ForceBreakdown* out);

/// Symplectic Euler with the velocity cap (§5). integrate.cpp.
void integrate(const ForceField& force, const ForceParams& params, SimState& state);

// ---- constraints (§5.2), constraints.cpp ------------------------------------------------------------------

/// End-to-end: element e's first slice to t = 0, last slice to t = 1.
void apply_end_to_end(const Topology& topo, SimState& state, std::int32_t e);

/// Simultaneity: every inner slice of element e snapped to the mean t of its vertices.
void apply_simultaneity(const Topology& topo, SimState& state, std::int32_t e);

/// Loop: both vertices of every loop pair move to the average of their x, y; t untouched.
void apply_loop(const Topology& topo, SimState& state);

/// Containment: every vertex outside the container moves to the nearest point of the container's boundary,
/// a hair (containment_margin) inside, and stops in x, y. A hard constraint like those of §5.2, because
/// the linear Eq. 4 loses against the stiff springs of a grown element (docs/parameters.md). boundary.cpp,
/// beside the container query it uses (kernels/boundary.cl holds the kernel).
inline constexpr float containment_margin = 1e-5f;
void apply_containment(const Topology& topo, SimState& state);

// ---- growth (§5.3), growth.cpp -------------------------------------------------------------------------

/// Bits of the per-slice `changed` flags grow_slices writes: whether g grew or shrank, and whether the
/// element's growth_ratio or neighbour_growth_ratio limit held it below its own proposal or below one
/// growth step at growth_rate, whichever is less (such a slice is blocked by a contact elsewhere in its
/// element, so the stop test counts it as touching; one that the limits only slow from the room's boost
/// is not).
enum GrowthChange : std::uint8_t { growth_kept = 0, growth_grew = 1, growth_shrank = 2, growth_held = 4 };

/// How many times growth_rate a free slice grows (docs/parameters.md, "Growth that follows the room"): its gap (the least
/// `closest` over its vertices: the nearest other element or the wall) over boost_gap, clamped to
/// [1, boost], and to at most speed_limit (the multiplier at which the slice's outline moves outwards
/// boost_speed × the velocity cap per step) unless that is below 1. Not in the paper, which grows every
/// free slice at one rate.
float growth_multiplier(float gap, float boost_gap, float boost, float speed_limit);

/// Each slice's own next g from its contacts (docs/parameters.md, "Growth"), into `proposed`: a slice
/// with a vertex outside the container, or one that overlaps an element no larger there (contact_yield),
/// shrinks by shrink_rate · Δt_sim (not below 1); one that overlaps only larger elements, has a boundary
/// vertex nearer the wall than stop_gap, or is at max_growth keeps its g; any other grows by growth_rate ·
/// Δt_sim × growth_multiplier of its gap. Without `growing` (the settling phase) no slice grows, and every overlapping or spilling slice
/// shrinks by settle_shrink_rate · Δt_sim.
void propose_growth(const Topology& topo, const std::vector<std::uint8_t>& contact, const std::vector<float>& closest,
                    const ForceParams& params, bool growing, const SimState& state, std::vector<float>& proposed);

/// Every slice's new g: its proposal, limited to growth_ratio × the smallest proposal of its element and
/// to neighbour_growth_ratio × the proposal of each time neighbour. `changed` marks what moved; returns
/// how many slices grew.
std::int32_t grow_slices(const Topology& topo, const std::vector<float>& proposed, const ForceParams& params,
                         SimState& state, std::vector<std::uint8_t>& changed);

/// Recomputes the rest length of every spring with an end on a slice marked in `changed`.
void update_rest_lengths(const Topology& topo, const std::vector<std::uint8_t>& changed, SimState& state);

// ---- statistics for the stop test, stats.cpp -------------------------------------------------------------

/// Per slice, from the latest step's `closest` and `contact` (StepForces) and growth's `changed`: the
/// least gap (0 for a slice growth_held marks), the overlapping and outside vertices, and the first
/// vertex whose position or velocity is not finite.
void slice_statistics(const Topology& topo, const SimState& state, const std::vector<float>& closest,
                      const std::vector<std::uint8_t>& contact, const std::vector<std::uint8_t>& changed,
                      SliceStatistics& out);

}  // namespace animpak::reference
