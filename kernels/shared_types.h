/* Structs and constants shared by the OpenCL kernels and the C++ host (docs/architecture.md, "Layout shared by host and kernels"). The
 * kernels see this file first in every program; the host includes it from src/solver/opencl, and the
 * solver stage for ForceParams (include/animpak/step_params.hpp), the block both backends read. Only
 * 4-byte scalars, so both compilers lay the structs out alike; the host static_asserts the sizes and
 * offsets (src/solver/opencl/layout.cpp) and that the constants match VertexFlag and SpringClass. */
#ifndef ANIMPAK_KERNELS_SHARED_TYPES_H
#define ANIMPAK_KERNELS_SHARED_TYPES_H

#ifdef __OPENCL_VERSION__
typedef int ap_int;
typedef float ap_float;
/* A helper the repulsion and overlap kernels call many times per work-item (per grid row, per lane
 * group, per candidate element): on a CPU device (built with AP_NEAR_LANES, program.cpp) inlined, so
 * it does not pay a call, spilled vector registers and results through memory at each
 * (docs/architecture.md, "Inlined helpers"). Inlining changes no float operation, so no bit. Left to
 * the compiler elsewhere: a GPU compiler inlines on its own, and Oclgrind crashes on the inlined
 * repulsion kernel. */
#ifdef AP_NEAR_LANES
#define AP_INLINE __attribute__((always_inline))
#else
#define AP_INLINE
#endif
#else
#include <cstdint>
typedef std::int32_t ap_int;
typedef float ap_float;
#endif

/* VertexFlag bits (state.hpp). */
#define AP_VERTEX_BOUNDARY 1
#define AP_VERTEX_ANCHOR 2
#define AP_VERTEX_HOLD_ANGLE 16

/* ContactBit values (state.hpp): what the overlap and container tests found at a vertex. */
#define AP_CONTACT_OVERLAP 1
#define AP_CONTACT_OUTSIDE 2
#define AP_CONTACT_WALL 4
#define AP_CONTACT_INSIDE 8
#define AP_CONTACT_YIELD 16
#define AP_CONTACT_BLOCK 32

/* GrowthChange values (include/animpak/solver/step.hpp): what grow_slices did to a slice's g. */
#define AP_GROWTH_GREW 1
#define AP_GROWTH_SHRANK 2
#define AP_GROWTH_HELD 4

/* How far inside the container the containment projection puts a vertex (containment_margin,
 * include/animpak/solver/step.hpp). */
#define AP_CONTAINMENT_MARGIN 1e-5f

/* SpringClass values (include/animpak/spring_class.hpp); AP_SPRING_CLASSES is the size of ForceParams.k_spring. */
#define AP_SPRING_CLASSES 5

/* ForceParams.motion_curve: the curve between slices (include/animpak/curve.hpp, CurveMode). */
#define AP_CURVE_LINEAR 0
#define AP_CURVE_MONOTONE 1
#define AP_CURVE_SPLINE 2

/* Work-group size of every kernel: PoCL compiles one kernel per local size, so it never varies. */
#define AP_LOCAL_SIZE 64

/* Cells per block of the device-side grid scan (grid.cl). */
#define AP_SCAN_BLOCK 64

/* The planes of the slot_vertices buffer (grid.cl, slot_positions): plane p of slot k is at p * triangles + k. */
#define AP_SLOT_AX 0
#define AP_SLOT_AY 1
#define AP_SLOT_AT 2
#define AP_SLOT_BX 3
#define AP_SLOT_BY 4
#define AP_SLOT_BT 5
#define AP_SLOT_CX 6
#define AP_SLOT_CY 7
#define AP_SLOT_CT 8

/* Grouped buffers: one buffer holds the planes of a group, all of one type, plane k from element
 * k * stride on, the group's stride (WorldInfo, GridInfo) padded to the device's base-address alignment
 * so that every plane starts as aligned as a buffer of its own (src/solver/opencl/plane_buffer.hpp;
 * docs/architecture.md, "Layout shared by host and kernels"). Every kernel that reads or writes a plane
 * takes the whole group and names its planes once at its top, `x = positions + AP_X * world.vertex_stride`,
 * so its arithmetic reads one array per quantity; the host never binds a plane on its own. The planes of
 * each group, by index: */
/* positions, velocities, forces (float, vertex_stride): x, y, t. */
#define AP_X 0
#define AP_Y 1
#define AP_T 2
/* vertex_topology (int, vertex_stride): per vertex its element, slice, VertexFlag bits and target point
 * (or -1). */
#define AP_TOPO_ELEMENT 0
#define AP_TOPO_SLICE 1
#define AP_TOPO_FLAGS 2
#define AP_TOPO_TARGET 3
#define AP_TOPO_PLANES 4
/* vertex_rest (float, vertex_stride): the rest state per vertex, its t and direction from the slice
 * centroid (Eq. 4, 5), and the rest copy (§5.3). */
#define AP_REST_T 0
#define AP_REST_DIR_X 1
#define AP_REST_DIR_Y 2
#define AP_REST_COPY_X 3
#define AP_REST_COPY_Y 4
#define AP_REST_COPY_T 5
#define AP_REST_PLANES 6
/* springs (int, spring_stride): the CSR rows, vertices + 1, and per slot the other end and the
 * SpringClass. */
#define AP_SPRINGS_BEGIN 0
#define AP_SPRINGS_OTHER 1
#define AP_SPRINGS_CLASS 2
#define AP_SPRINGS_PLANES 3
/* triangles (int, triangle_stride): the slice triangles' corners, the incident-triangle rows (vertices
 * + 1) and their list. */
#define AP_TRIS_A 0
#define AP_TRIS_B 1
#define AP_TRIS_C 2
#define AP_TRIS_BEGIN 3
#define AP_TRIS_LIST 4
#define AP_TRIS_PLANES 5
/* slice_topology (int, slice_stride): slice_begin (slices + 1), slice_boundary, slice_element,
 * element_slice_begin (elements + 1) and element_secondary (per element, 1 if secondary). */
#define AP_SLICES_BEGIN 0
#define AP_SLICES_BOUNDARY 1
#define AP_SLICES_ELEMENT 2
#define AP_SLICES_ELEMENT_BEGIN 3
#define AP_SLICES_SECONDARY 4
#define AP_SLICES_PLANES 5
/* slice_geometry (float, slice_stride): the centroids (slice_centroids) and boxes with their t
 * (slice_boxes). */
#define AP_GEOM_CX 0
#define AP_GEOM_CY 1
#define AP_GEOM_X0 2
#define AP_GEOM_Y0 3
#define AP_GEOM_X1 4
#define AP_GEOM_Y1 5
#define AP_GEOM_T 6
#define AP_GEOM_PLANES 7
/* curve (float, vertex_stride): the tangents (curve_tangents) and the Bézier handles of the boundary
 * vertices towards the next slice (P) and the one before (Q) (slice_boxes). */
#define AP_CURVE_TANGENT_X 0
#define AP_CURVE_TANGENT_Y 1
#define AP_CURVE_HANDLE_PX 2
#define AP_CURVE_HANDLE_PY 3
#define AP_CURVE_HANDLE_QX 4
#define AP_CURVE_HANDLE_QY 5
#define AP_CURVE_PLANES 6
/* repulsion (float, vertex_stride): what repulsion_force hands on per boundary vertex: Eq. 1, the
 * nearest other element's distance and the overlap test's way out. Its contact bits are a uchar buffer
 * of their own. */
#define AP_RPL_X 0
#define AP_RPL_Y 1
#define AP_RPL_T 2
#define AP_RPL_CLOSEST 3
#define AP_RPL_DEPTH_X 4
#define AP_RPL_DEPTH_Y 5
#define AP_RPL_PLANES 6
/* wall (float, vertex_stride): the wall's mirror image (wall_mirror_force) and the container query's
 * squared distance and nearest point, written by wall_mirror_force or step_forces, whichever makes the
 * query; whether the vertex is inside is a uchar buffer of its own. */
#define AP_WALL_MIRROR_X 0
#define AP_WALL_MIRROR_Y 1
#define AP_WALL_MIRROR_T 2
#define AP_WALL_D2 3
#define AP_WALL_QX 4
#define AP_WALL_QY 5
#define AP_WALL_PLANES 6
/* targets (float, target_stride): the target points' x, y, t (AP_X, AP_Y, AP_T). */
/* segments (float, segment_stride): the container's segments at rest, a to b, and its motion table
 * (ContainerGeometry::motion_*, world.motion_entries entries; none when it does not move). */
#define AP_SEG_AX 0
#define AP_SEG_AY 1
#define AP_SEG_BX 2
#define AP_SEG_BY 3
#define AP_SEG_MOTION_A 4
#define AP_SEG_MOTION_B 5
#define AP_SEG_MOTION_EX 6
#define AP_SEG_MOTION_EY 7
#define AP_SEG_PLANES 8
/* grid_index (int, GridInfo.index_stride): the collision grid's cell ranges (cells + 1), each slot's
 * element (grid_gather; then AP_LANES spare slots), the far field's run ranges (cells + 1) and each
 * run's element (grid_runs). */
#define AP_INDEX_CELL_START 0
#define AP_INDEX_SLOT_ELEMENT 1
#define AP_INDEX_RUN_START 2
#define AP_INDEX_RUN_ELEMENT 3
#define AP_INDEX_PLANES 4
/* slot_centroids (float, GridInfo.slot_stride): each slot's triangle centroid (grid_gather), x, y, t
 * (AP_X, AP_Y, AP_T). */

/* The collision grid (CollisionGrid, include/animpak/solver/grids.hpp, without its arrays), passed to every
 * grid kernel. */
typedef struct {
  ap_int n;            /* cells per axis */
  ap_float cell;       /* cell edge */
  ap_int triangles;    /* envelope triangles */
  ap_int cells;        /* n * n * n */
  ap_int far_cells;    /* 1: the far shell reads the cell aggregates (grid_runs); 0: every centroid */
  ap_int index_stride; /* grid_index's planes */
  ap_int slot_stride;  /* slot_centroids' planes */
} GridInfo;

/* The overlap test's broadphase (OverlapGrid, include/animpak/solver/grids.hpp, without its arrays), built
 * each step on the host or on the device (overlap_grid.cl) into a one-element buffer the repulsion kernel reads. nx == 0: no grid, every query tries every element. */
typedef struct {
  ap_int nx, ny, nt;     /* cells per axis */
  ap_float x0, y0, t0;   /* low corner */
  ap_float cell, cell_t; /* cell edge in x and y, in t */
} OverlapGridInfo;

/* The container query's index (ContainerIndex in include/animpak/state.hpp without its list array, which
 * is passed as one int buffer: band_start at 0, the band lists from band_segments, cell_start from
 * cell_start, the cell lists from cell_segments). nx == 0: no index, every query tries every segment. */
typedef struct {
  ap_float x0, y0, cell;
  ap_int nx, ny;
  ap_int band_segments, cell_start, cell_segments;
} ContainerIndexInfo;

/* The forces of Eq. 7, one row each, in the order the sum adds them (docs/architecture.md, "How to add a
 * force"). Every list of the forces follows this one: the total's left-to-right sum in both step_forces
 * (kernels/forces.cl, src/solver/reference/forces.cpp), the fields of ForceBreakdown
 * (include/animpak/solver/step.hpp), the breakdown buffer's components and breakdown_forces
 * (src/solver/compare.cpp), which validate and the equivalence suite compare. X(name, ...): the first
 * six are computed in step_forces itself; AP_LOCAL_FORCES's rows follow them. */
#define AP_FORCE_TERMS(X) X(repulsion) X(springs) X(target) X(boundary) X(overlap) X(torsion) AP_LOCAL_FORCES(X)

/* Forces of one vertex's own state with one stiffness each, one row per force:
 *   X(name, stiffness, default, max, meaning, paper)
 * The row is the whole binding: the stiffness is a ForceParams field set by step_params with one
 * static_cast<float>, a Params::Forces member (a double with that default) and a row of the "forces" group
 * of param_table() (src/io/params.cpp; range 0 to max, meaning and the paper's value as the table prints
 * them). Its force is name_force: in the reference, Vec3f name_force(const Topology&, const SimState&,
 * const ForceParams&, std::int32_t v), declared from this list in include/animpak/reference/local_forces.hpp;
 * in the kernels, void name_force(const ForceParams p, const LocalForceInputs in, int v, float* fx,
 * float* fy, float* ft) in a kernel file of its own, which program_source places before forces.cl
 * (src/solver/opencl/program.cpp). Both step_forces call it for every vertex. The host reads every
 * column, the kernels the first two. */
/* clang-format off */
#define AP_LOCAL_FORCES(X) \
  X(temporal, k_temporal, 1.0, inf, "k_tmp, temporal strength (Eq. 6)", "k_tmp = 1 (Eq. 6)")
/* clang-format on */

/* How many rows a list has: 0 AP_LOCAL_FORCES(AP_COUNT_ROW). */
#define AP_COUNT_ROW(...) +1
enum { AP_LOCAL_FORCE_COUNT = 0 AP_LOCAL_FORCES(AP_COUNT_ROW) };
#define AP_FORCE_PARAMS_FIELD(name, stiffness, ...) ap_float stiffness;

/* Every Params constant of the step's arithmetic, converted once to float (static_cast<float>, products
 * formed in double first) by step_params (src/solver/step_params.cpp): the kernels get it by value, the
 * reference reads the same block. */
typedef struct {
  ap_float k_repulsion, repulsion_epsilon;
  ap_float k_wall;                      /* wall_repulsion * k_repulsion */
  ap_float k_spring[AP_SPRING_CLASSES]; /* by SpringClass */
  ap_float k_target, k_overlap, k_overlap_depth, k_boundary, k_torsion;
  AP_LOCAL_FORCES(AP_FORCE_PARAMS_FIELD) /* the stiffness of each force of AP_LOCAL_FORCES */
  ap_float dt;
  ap_float velocity_cap; /* velocity_cap * dt */
  ap_float growth_step;  /* growth_rate * dt */
  ap_float shrink_step;  /* shrink_rate * dt */
  ap_float growth_ratio;
  ap_float neighbour_growth_ratio;
  ap_float max_growth;
  ap_float stop_gap;
  ap_float k_target_angle;     /* Eq. 5 on vertices with AP_VERTEX_HOLD_ANGLE */
  ap_float wall_range2;        /* wall_range * wall_range */
  ap_float settle_shrink_step; /* settle_shrink_rate * dt */
  ap_int interval_points;      /* times the overlap test checks inside each slice interval */
  ap_int motion_curve;         /* AP_CURVE_SPLINE (2): the C2 spline between slices (kernels/curve.cl); 1: the
                                * monotone cubic; 0: straight lines */
  ap_float k_mirror;           /* wall_mirror * k_repulsion: the wall as the element's mirror image; 0 off */
  ap_float k_fold;             /* the fold guard's stiffness (kernels/springs.cl, fold_force); 0 off */
  ap_float fold_area;          /* the share of a slice triangle's rest area where the fold guard starts */
  ap_float growth_boost;       /* a free slice's growth step is at most growth_boost × growth_step */
  ap_float boost_gap;          /* ... and growth_step × slice gap / boost_gap below that */
  ap_float boost_step;         /* boost_speed * velocity_cap * dt * dt: the outline's largest boosted step */
  ap_float pad[2 - AP_LOCAL_FORCE_COUNT % 2]; /* unused, 0: with the 32 fields besides AP_LOCAL_FORCES, keeps
                                               * the size a multiple of 8 bytes (src/solver/opencl/layout.cpp) */
} ForceParams;

/* Sizes of the world and the strides of its grouped buffers, passed to every kernel that walks more
 * than one array. */
typedef struct {
  ap_int vertices, slices, elements, loops;
  ap_int segments;        /* container segments */
  ap_int breakdown;       /* 1: the forces kernel also writes every force separately (equivalence tests) */
  ap_int boundaries;      /* boundary vertices: the repulsion and wall-image kernels' work-items */
  ap_int vertex_stride;   /* positions, velocities, forces, vertex_topology, vertex_rest, curve, repulsion, wall */
  ap_int slice_stride;    /* slice_topology, slice_geometry */
  ap_int spring_stride;   /* springs */
  ap_int triangle_stride; /* triangles */
  ap_int target_stride;   /* targets */
  ap_int segment_stride;  /* segments */
  ap_int motion_entries;  /* the container's motion table in segments; 0: the container does not move */
} WorldInfo;

/* Force components in the breakdown buffer, each 3 * vertices floats (x, then y, then t): AP_FORCE_<name>
 * for every row of AP_FORCE_TERMS, in its order. */
#define AP_FORCE_TERM_INDEX(name, ...) AP_FORCE_##name,
enum { AP_FORCE_TERMS(AP_FORCE_TERM_INDEX) AP_FORCE_COMPONENTS };

#ifdef __OPENCL_VERSION__
/* What a force of AP_LOCAL_FORCES reads of vertex v, the planes step_forces names at its top: the
 * positions and the per-vertex topology and rest state (the kernels' twin of the reference's Topology and
 * SimState). */
typedef struct {
  __global const float *x, *y, *t;
  __global const int *element, *slice, *flags, *target;
  __global const float *rest_t, *rest_dir_x, *rest_dir_y, *rest_copy_x, *rest_copy_y, *rest_copy_t;
} LocalForceInputs;
#endif

#endif
