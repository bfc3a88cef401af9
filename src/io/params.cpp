#include "animpak/params.hpp"

#include <array>
#include <limits>

namespace animpak {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// Ranges reject values that make the simulation meaningless (a negative stiffness, a zero time step);
// they do not judge taste.
const std::array<ParamInfo, 42> table{{
    {"offset", &Params::offset, 0.0, 0.5,
     "Δs: negative-space channel around each element (§3.1)", "Δs = 0.04 (§3.1)"},
    {"boundary_spacing", &Params::boundary_spacing, 0.005, 1.0,
     "longest edge between boundary samples", "not stated (evenly spaced)"},
    {"boundary_tolerance", &Params::boundary_tolerance, 1e-4, 0.5,
     "largest distance between the boundary polygon and the offset outline", "not stated (evenly spaced)"},
    {"interior_spacing", &Params::interior_spacing, 0.005, 1.0,
     "minimum distance between interior samples", "not stated"},
    {"slices", &Params::slices, 2, 1000, "n_s: slices along the time axis (§3.1)", "n_s = 100 (§3.1)"},
    {"initial_scale", &Params::initial_scale, 0.001, 1.0,
     "size of every element at the start (§4)", "5–10 % of full size (§4)"},
    {"seed_spacing", &Params::seed_spacing, 0.01, 1.0,
     "distance between unguided seeds when filling (§4)", "not stated (blue noise, §4)"},
    {"k_repulsion", &Params::k_repulsion, 0.0, inf,
     "k_rpl, repulsion strength (Eq. 1)", "k_rpl = 10 (Eq. 1)"},
    {"repulsion_epsilon", &Params::repulsion_epsilon, 1e-12, inf, "ε, softening of Eq. 1", "ε = 1 (Eq. 1)"},
    {"wall_repulsion", &Params::wall_repulsion, 0.0, inf,
     "Eq. 1 terms the container's wall counts as", "not in the paper"},
    {"wall_range", &Params::wall_range, 0.0, 1.0,
     "distance within which the wall repels", "not in the paper"},
    {"k_edge", &Params::k_edge, 0.0, inf, "k_edg of slice edge springs (Eq. 2)", "10 (Eq. 2)"},
    {"k_shear", &Params::k_shear, 0.0, inf, "k_edg of shear springs (Eq. 2)", "10 (Eq. 2)"},
    {"k_negative_space", &Params::k_negative_space, 0.0, inf,
     "k_edg of negative-space springs (Eq. 2)", "0.1 (Eq. 2)"},
    {"k_time", &Params::k_time, 0.0, inf, "k_edg of time springs (Eq. 2)", "0.01 (Eq. 2)"},
    {"k_target", &Params::k_target, 0.0, inf, "k_edg of target-point springs (Eq. 2, §4)", "10 (Eq. 2)"},
    {"k_overlap", &Params::k_overlap, 0.0, inf, "k_ovr, overlap strength (Eq. 3)", "k_ovr = 5 (Eq. 3)"},
    {"k_overlap_depth", &Params::k_overlap_depth, 0.0, inf,
     "pull of an inside vertex out of the other element", "not in the paper"},
    {"k_boundary", &Params::k_boundary, 0.0, inf, "k_bdr, container strength (Eq. 4)", "k_bdr = 5 (Eq. 4)"},
    {"k_torsion", &Params::k_torsion, 0.0, inf, "k_tor, torsion strength (Eq. 5)", "k_tor = 0.1 (Eq. 5)"},
    {"k_target_angle", &Params::k_target_angle, 0.0, inf,
     "k_tor on the slices of guided elements whose targets give an angle (Eq. 5, §4)",
     "not stated (§4: an optional orientation at targets)"},
    {"k_temporal", &Params::k_temporal, 0.0, inf, "k_tmp, temporal strength (Eq. 6)", "k_tmp = 1 (Eq. 6)"},
    {"dt", &Params::dt, 1e-6, 1.0, "Δt_sim, symplectic Euler step (§5)", "Δt_sim = 0.01 (§5)"},
    {"velocity_cap", &Params::velocity_cap, 0.0, inf,
     "speeds are capped at velocity_cap · Δt_sim (§5)", "10 Δt_sim (§5)"},
    {"cell_size", &Params::cell_size, 0.005, 1.0,
     "collision grid cell edge (§5.1)", "0.04, a 25³ grid (§5.1)"},
    {"grid_rebuild_interval", &Params::grid_rebuild_interval, 1, 1000,
     "rebuild the grid every k steps", "every step (implied)"},
    {"far_cells", &Params::far_cells, 0, 1,
     "1: far shell of Eq. 1 by cell aggregates; 0: by every centroid (§5.1)",
     "per-triangle centroids (§5.1)"},
    {"interval_points", &Params::interval_points, 1, 15,
     "times the overlap test checks inside each slice interval, evenly spaced (paper §8)",
     "none: slices only (§8: future work)"},
    {"growth_rate", &Params::growth_rate, 0.0, inf,
     "g += growth_rate · Δt_sim per free step (§5.3)", "g += 0.001 Δt_sim per free step (§5.3)"},
    {"shrink_rate", &Params::shrink_rate, 0.0, inf,
     "g -= shrink_rate · Δt_sim per step while overlapping", "not in the paper (growth pauses)"},
    {"growth_ratio", &Params::growth_ratio, 1.0, inf,
     "largest g of an element ≤ growth_ratio × its smallest", "not in the paper (slices grow independently)"},
    {"neighbour_growth_ratio", &Params::neighbour_growth_ratio, 1.0, inf,
     "g ≤ this × either time neighbour's g", "not in the paper"},
    {"stop_gap", &Params::stop_gap, 0.0, 1.0,
     "stop when the largest per-slice gap is below this (§5.3)", "0.006 (§5.3)"},
    {"stop_growth", &Params::stop_growth, 0.0, inf,
     "stop when every g exceeds this; 0 turns it off (§5.3)", "not in the paper"},
    {"max_iterations", &Params::max_iterations, 1, 100000000, "hard cap on simulation steps", "none"},
    {"settle_iterations", &Params::settle_iterations, 0, 100000000,
     "steps without growth to clear overlaps at the end", "not in the paper"},
    {"settle_shrink_rate", &Params::settle_shrink_rate, 0.0, inf,
     "g -= settle_shrink_rate · Δt_sim per settling step while overlapping", "not in the paper"},
    {"stall_window", &Params::stall_window, 0, 100000000,
     "steps between the stall test's comparisons; 0 turns it off", "not in the paper"},
    {"stall_growth", &Params::stall_growth, 0.0, inf,
     "mean g must rise by this share per window, or growth has stalled", "not in the paper"},
    {"check_interval", &Params::check_interval, 1, 100000, "NaN check and statistics every k steps", "none"},
    // The two below are not the paper's but shape every result, so they are overridable too.
    {"max_growth", &Params::max_growth, 1.0, inf, "cap on a slice's growth factor g", "not in the paper"},
    {"flatten_tolerance", &Params::flatten_tolerance, 1e-4, 10.0,
     "curve flattening tolerance, art units", "not in the paper (art import)"},
}};

}  // namespace

std::span<const ParamInfo> param_table() { return table; }

double param_value(const Params& params, const ParamInfo& info) {
  return std::visit([&](auto member) { return static_cast<double>(params.*member); }, info.member);
}

bool param_is_integer(const ParamInfo& info) { return std::holds_alternative<int Params::*>(info.member); }

}  // namespace animpak
