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

/* The collision grid (CollisionGrid, include/animpak/solver/grids.hpp, without its arrays), passed to every
 * grid kernel. */
typedef struct {
  ap_int n;         /* cells per axis */
  ap_float cell;    /* cell edge */
  ap_int triangles; /* envelope triangles */
  ap_int cells;     /* n * n * n */
  ap_int far_cells; /* 1: the far shell reads the cell aggregates (grid_runs); 0: every centroid */
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

/* Every Params constant of the step's arithmetic, converted once to float (static_cast<float>, products
 * formed in double first) by step_params (src/solver/step_params.cpp): the kernels get it by value, the
 * reference reads the same block. */
typedef struct {
  ap_float k_repulsion, repulsion_epsilon;
  ap_float k_wall;                      /* wall_repulsion * k_repulsion */
  ap_float k_spring[AP_SPRING_CLASSES]; /* by SpringClass */
  ap_float k_target, k_overlap, k_overlap_depth, k_boundary, k_torsion, k_temporal;
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
  ap_float pad_boost;          /* unused: keeps the size a multiple of 8 bytes */
} ForceParams;

/* Sizes of the world, passed to every kernel that walks more than one array. */
typedef struct {
  ap_int vertices, slices, elements, loops;
  ap_int segments;  /* container segments */
  ap_int breakdown; /* 1: the forces kernel also writes every force separately (equivalence tests) */
} WorldInfo;

/* Force components in the breakdown buffer, each 3 * vertices floats (x, then y, then t). */
#define AP_FORCE_REPULSION 0
#define AP_FORCE_SPRINGS 1
#define AP_FORCE_TARGET 2
#define AP_FORCE_BOUNDARY 3
#define AP_FORCE_OVERLAP 4
#define AP_FORCE_TORSION 5
#define AP_FORCE_TEMPORAL 6
#define AP_FORCE_COMPONENTS 7

#endif
