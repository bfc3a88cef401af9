// Every constant of the paper, in one value passed down explicitly (never a global). Defaults are the
// paper's values where they are unit-free; the force constants are the paper's (and the authors'
// code's) values converted from the authors' 500-unit artboard to the unit container, because taken
// literally in unit space they give a repulsion that no longer falls off with distance. The
// conversion and every other difference are in docs/parameters.md. Grouped by the stage that reads them;
// a scene file may override any of them by its flat name in param_table() ("params": {"k_time": 2};
// include/animpak/param_table.hpp).
#pragma once

#include "shared_types.h"

namespace animpak {

struct Params {
  /// Reading the art (src/io).
  struct ArtImport {
    double flatten_tolerance = 0.1;  ///< largest curve-to-polyline distance when flattening, art units
  };

  /// §3 spacetime elements (src/element).
  struct Element {
    double offset = 0.04;               ///< Δs, channel of negative space around each element (unit square)
    double boundary_spacing = 0.15;     ///< longest boundary edge, between samples of the offset outline
    double boundary_tolerance = 0.008;  ///< largest distance between the boundary polygon and the outline
    double interior_spacing = 0.15;     ///< minimum distance between interior (Poisson-disk) samples
    int slices = 100;                   ///< n_s, slices along the time axis
    /// The packing starts with about one slice per coarse_step of these and refines to them once that
    /// coarse level stops (docs/parameters.md, "Coarse to fine"; levels.hpp); 1: the scene's slices throughout.
    int coarse_step = 4;
  };

  /// §4 initial configuration (src/scene).
  struct Placement {
    double initial_scale = 0.07;  ///< elements start at 5–10 % of their size
    double seed_spacing = 0.2;    ///< blue-noise distance between unguided seeds when the scene fills
    int seed_spread = 1;  ///< a fixed count's seeds: 1 spread (farthest points, Lloyd), 0 a random blue-noise subset
    int guide_curve = 1;  ///< a guided element's initial path: 1 a smooth curve through its targets, 0 straight lines
    /// Unguided elements make way for guided ones (docs/parameters.md, "Making way"): the share of the
    /// container their stand-in discs cover while the crowd is relaxed round each traveller, slice by
    /// slice; 0 (the default) keeps the paper's seeds off the guided paths and straight starts.
    double make_way = 0.0;
    /// Making way, an unguided element's script is scaled down by up to this where a traveller passes it
    /// (docs/parameters.md, "Making way"); 1: no dip.
    double make_way_dip = 1.3;
  };

  /// §5 forces, integration and the spatial queries (src/solver).
  struct Forces {
    double k_repulsion = 8e-8;        ///< Eq. 1
    double repulsion_epsilon = 4e-6;  ///< ε of Eq. 1
    double wall_repulsion =
        0.0;                   ///< the wall repels a boundary vertex like this many Eq. 1 terms from its nearest point
    double wall_range = 0.08;  ///< both wall forces act within this distance of the wall (the repulsion shell's reach)
    double wall_mirror = 1.0;  ///< the wall repels as the element's mirror image, weighted (0: off)
    double k_edge = 5000.0;    ///< Eq. 2, slice edge springs
    double k_shear = 5000.0;   ///< Eq. 2, shear springs
    double k_negative_space = 50.0;  ///< Eq. 2, negative-space springs
    double k_time = 5.0;             ///< Eq. 2, time springs
    double k_target = 500.0;         ///< Eq. 2, target-point springs of guided elements (target slices only)
    double k_fold = 200.0;           ///< a slice triangle squeezed below fold_area of its rest area is pushed back
    double fold_area = 0.2;          ///< (docs/parameters.md, "Folds"): the share of its rest area where that starts
    double k_overlap = 5.0;          ///< Eq. 3
    double k_overlap_depth = 5.0;    ///< Eq. 3 extended: pull of an inside vertex towards the other element's outline
    double k_boundary = 5.0;         ///< Eq. 4
    double k_torsion = 2e-4;         ///< Eq. 5
    double k_target_angle = 2e-3;    ///< Eq. 5 on a guided element's slices whose targets give an angle
    // clang-format off
    /// The stiffness of each force of AP_LOCAL_FORCES (kernels/shared_types.h), with its default: Eq. 6's k_tmp.
#define AP_PARAMS_MEMBER(name, stiffness, default_value, ...) double stiffness = default_value;
    AP_LOCAL_FORCES(AP_PARAMS_MEMBER)
#undef AP_PARAMS_MEMBER
    double dt = 0.05;                ///< Δt_sim, symplectic Euler step
    double velocity_cap = 0.02;      ///< speeds are capped at velocity_cap · Δt_sim
    double cell_size = 0.04;         ///< collision grid cell edge (25³ cells over the unit cube)
    int grid_rebuild_interval = 1;   ///< rebuild the collision grid every k steps
    int far_cells = 1;               ///< 1: Eq. 1's far shell sums one mean centroid per cell and element
                                     ///< (weighted by its triangles); 0: every triangle's centroid (§5.1)
    int interval_points = 7;         ///< the overlap test also checks this many evenly spaced times inside
                                     ///< every slice interval (1: the middle only; docs/parameters.md)
    int motion_curve = 2;            ///< between slices every vertex follows 2: the C2 spline through its
                                     ///< slices, 1: a monotone C1 cubic, 0: straight lines (§6);
                                     ///< include/animpak/curve.hpp
    // clang-format on
  };

  /// §5.3 growth (src/solver).
  struct Growth {
    double growth_rate = 0.01;  ///< g grows by growth_rate · Δt_sim per step on a free slice
    double shrink_rate = 0.01;  ///< g shrinks by shrink_rate · Δt_sim per step while a slice overlaps or spills
    double growth_ratio = 1.1;  ///< an element's largest g is at most growth_ratio × its smallest
    double neighbour_growth_ratio = 1.03;  ///< a slice's g is at most this × either time neighbour's
    double settle_shrink_rate = 0.04;      ///< while settling, overlapping and spilling slices shrink this fast
    double max_growth = 15.0;              ///< cap on g (the authors' code: 15, i.e. 0.07 · 15 ≈ full size)
    double growth_boost = 1.0;  ///< a free slice grows growth_rate × clamp(gap / boost_gap, 1, growth_boost)
    double boost_gap = 0.01;    ///< the slice gap (nearest other element or wall) at which the boost starts
    double boost_speed = 0.5;   ///< the boost moves no outline vertex faster than this share of the velocity cap
  };

  /// §5.3 stopping, and how often the run checks (src/solver).
  struct Stop {
    double stop_gap = 0.006;       ///< stop when the largest per-slice closest distance is below this
    double stop_growth = 0.0;      ///< also stop when every slice's g exceeds this (0: off)
    int max_iterations = 100000;   ///< hard cap on steps
    int settle_iterations = 3000;  ///< after the gap test passes, steps without growth to clear overlaps
    int stall_window = 400;        ///< the stall test compares the mean g this many steps apart (0: off)
    double stall_growth = 0.004;   ///< growth has stalled when the mean g rose by less than this share in a window
    int stall_tests = 4;           ///< the stall test runs this many times per window (1 to 4)
    int check_interval = 10;       ///< NaN/Inf check and statistics every k steps
  };

  ArtImport art;
  Element element;
  Placement placement;
  Forces forces;
  Growth growth;
  Stop stop;
};

}  // namespace animpak
