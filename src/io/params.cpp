#include "animpak/param_table.hpp"

#include <array>
#include <limits>

namespace animpak {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// Member M of group G of a Params, as a function whose address the table can hold.
template <auto G, auto M>
auto& member_of(Params& params) {
  return (params.*G).*M;
}

template <auto G, auto M>
constexpr auto field() {
  return &member_of<G, M>;
}

// Ranges reject values that make the simulation meaningless (a negative stiffness, a zero time step);
// they do not judge taste.
const std::array<ParamInfo, 54 + AP_LOCAL_FORCE_COUNT> table{{
    {"flatten_tolerance", "art", field<&Params::art, &Params::ArtImport::flatten_tolerance>(), 1e-4, 10.0,
     "curve flattening tolerance, art units", "not in the paper (art import)"},
    {"offset", "element", field<&Params::element, &Params::Element::offset>(), 0.0, 0.5,
     "Δs: negative-space channel around each element (§3.1)", "Δs = 0.04 (§3.1)"},
    {"boundary_spacing", "element", field<&Params::element, &Params::Element::boundary_spacing>(), 0.005, 1.0,
     "longest edge between boundary samples", "not stated (evenly spaced)"},
    {"boundary_tolerance", "element", field<&Params::element, &Params::Element::boundary_tolerance>(), 1e-4, 0.5,
     "largest distance between the boundary polygon and the offset outline", "not stated (evenly spaced)"},
    {"interior_spacing", "element", field<&Params::element, &Params::Element::interior_spacing>(), 0.005, 1.0,
     "minimum distance between interior samples", "not stated"},
    {"slices", "element", field<&Params::element, &Params::Element::slices>(), 2, 1000,
     "n_s: slices along the time axis (§3.1)", "n_s = 100 (§3.1)"},
    {"coarse_step", "element", field<&Params::element, &Params::Element::coarse_step>(), 1, 100,
     "the packing starts with one slice per coarse_step of n_s, refined to n_s at its stop (1: n_s throughout)",
     "n_s throughout (§8: future work)"},
    {"initial_scale", "placement", field<&Params::placement, &Params::Placement::initial_scale>(), 0.001, 1.0,
     "size of every element at the start (§4)", "5–10 % of full size (§4)"},
    {"seed_spacing", "placement", field<&Params::placement, &Params::Placement::seed_spacing>(), 0.01, 1.0,
     "distance between unguided seeds when filling (§4)", "not stated (blue noise, §4)"},
    {"seed_spread", "placement", field<&Params::placement, &Params::Placement::seed_spread>(), 0, 1,
     "a fixed count's seeds: 1 spread over the container (farthest points, then Lloyd); 0 a random subset of "
     "blue noise (0.4.0)",
     "blue noise (§4)"},
    {"guide_curve", "placement", field<&Params::placement, &Params::Placement::guide_curve>(), 0, 1,
     "a guided element's initial path through its targets: 1 a smooth curve in t (periodic through loop "
     "partners); 0 straight lines between targets (0.6.0)",
     "a polygonal extrusion (§4)"},
    {"make_way", "placement", field<&Params::placement, &Params::Placement::make_way>(), 0.0, 0.9,
     "unguided elements start on paths that step aside while a guided element passes: the share of the "
     "container their stand-in discs cover while making way (0: seeds kept off the guided paths, straight starts)",
     "seeds rejected where they meet a guided volume, straight extrusions (§4)"},
    {"make_way_dip", "placement", field<&Params::placement, &Params::Placement::make_way_dip>(), 1.0, 2.0,
     "while a guided element passes, an unguided element's script is scaled down by up to this factor (a size "
     "that gives way; 1: none)",
     "not in the paper"},
    {"k_repulsion", "forces", field<&Params::forces, &Params::Forces::k_repulsion>(), 0.0, inf,
     "k_rpl, repulsion strength (Eq. 1)", "k_rpl = 10 (Eq. 1)"},
    {"repulsion_epsilon", "forces", field<&Params::forces, &Params::Forces::repulsion_epsilon>(), 1e-12, inf,
     "ε, softening of Eq. 1", "ε = 1 (Eq. 1)"},
    {"wall_repulsion", "forces", field<&Params::forces, &Params::Forces::wall_repulsion>(), 0.0, inf,
     "Eq. 1 terms the container's wall counts as from its nearest point (0.5.0: 10)", "not in the paper"},
    {"wall_range", "forces", field<&Params::forces, &Params::Forces::wall_range>(), 0.0, 1.0,
     "distance within which the wall repels", "not in the paper"},
    {"wall_mirror", "forces", field<&Params::forces, &Params::Forces::wall_mirror>(), 0.0, inf,
     "weight of the wall's mirror image: Eq. 1 from the element reflected in the wall (0: off)", "not in the paper"},
    {"k_edge", "forces", field<&Params::forces, &Params::Forces::k_edge>(), 0.0, inf,
     "k_edg of slice edge springs (Eq. 2)", "10 (Eq. 2)"},
    {"k_shear", "forces", field<&Params::forces, &Params::Forces::k_shear>(), 0.0, inf,
     "k_edg of shear springs (Eq. 2)", "10 (Eq. 2)"},
    {"k_negative_space", "forces", field<&Params::forces, &Params::Forces::k_negative_space>(), 0.0, inf,
     "k_edg of negative-space springs (Eq. 2)", "0.1 (Eq. 2)"},
    {"k_time", "forces", field<&Params::forces, &Params::Forces::k_time>(), 0.0, inf, "k_edg of time springs (Eq. 2)",
     "0.01 (Eq. 2)"},
    {"k_target", "forces", field<&Params::forces, &Params::Forces::k_target>(), 0.0, inf,
     "k_edg of target-point springs (Eq. 2, §4)", "10 (Eq. 2)"},
    {"k_fold", "forces", field<&Params::forces, &Params::Forces::k_fold>(), 0.0, 800.0,
     "pushes a slice triangle squeezed below fold_area of its rest area back open, so that it never folds over "
     "and its art stays inside the element's outline (0: off)",
     "not in the paper"},
    {"fold_area", "forces", field<&Params::forces, &Params::Forces::fold_area>(), 0.0, 1.0,
     "share of a slice triangle's rest area (times g squared) below which k_fold pushes it back", "not in the paper"},
    {"k_overlap", "forces", field<&Params::forces, &Params::Forces::k_overlap>(), 0.0, inf,
     "k_ovr, overlap strength (Eq. 3)", "k_ovr = 5 (Eq. 3)"},
    {"k_overlap_depth", "forces", field<&Params::forces, &Params::Forces::k_overlap_depth>(), 0.0, inf,
     "pull of an inside vertex out of the other element", "not in the paper"},
    {"k_boundary", "forces", field<&Params::forces, &Params::Forces::k_boundary>(), 0.0, inf,
     "k_bdr, container strength (Eq. 4)", "k_bdr = 5 (Eq. 4)"},
    {"k_torsion", "forces", field<&Params::forces, &Params::Forces::k_torsion>(), 0.0, inf,
     "k_tor, torsion strength (Eq. 5)", "k_tor = 0.1 (Eq. 5)"},
    {"k_target_angle", "forces", field<&Params::forces, &Params::Forces::k_target_angle>(), 0.0, inf,
     "k_tor on the slices of guided elements whose targets give an angle (Eq. 5, §4)",
     "not stated (§4: an optional orientation at targets)"},
// clang-format off
// The rows of AP_LOCAL_FORCES (kernels/shared_types.h), where their members are in Params::Forces.
#define AP_LOCAL_FORCE_ROW(name, stiffness, default_value, max, meaning, paper) \
  {#stiffness, "forces", field<&Params::forces, &Params::Forces::stiffness>(), 0.0, max, meaning, paper},
    AP_LOCAL_FORCES(AP_LOCAL_FORCE_ROW)
#undef AP_LOCAL_FORCE_ROW
    // clang-format on
    {"dt", "forces", field<&Params::forces, &Params::Forces::dt>(), 1e-6, 1.0, "Δt_sim, symplectic Euler step (§5)",
     "Δt_sim = 0.01 (§5)"},
    {"velocity_cap", "forces", field<&Params::forces, &Params::Forces::velocity_cap>(), 0.0, inf,
     "speeds are capped at velocity_cap · Δt_sim (§5)", "10 Δt_sim (§5)"},
    {"cell_size", "forces", field<&Params::forces, &Params::Forces::cell_size>(), 0.005, 1.0,
     "collision grid cell edge (§5.1)", "0.04, a 25³ grid (§5.1)"},
    {"grid_rebuild_interval", "forces", field<&Params::forces, &Params::Forces::grid_rebuild_interval>(), 1, 1000,
     "rebuild the grid every k steps", "every step (implied)"},
    {"far_cells", "forces", field<&Params::forces, &Params::Forces::far_cells>(), 0, 1,
     "1: far shell of Eq. 1 by cell aggregates; 0: by every centroid (§5.1)", "per-triangle centroids (§5.1)"},
    {"interval_points", "forces", field<&Params::forces, &Params::Forces::interval_points>(), 1, 15,
     "times the overlap test checks inside each slice interval, evenly spaced (paper §8)",
     "none: slices only (§8: future work)"},
    {"motion_curve", "forces", field<&Params::forces, &Params::Forces::motion_curve>(), 0, 2,
     "between slices every vertex follows 2: the C2 cubic spline through its slices (no jump of speed or "
     "acceleration at a slice); 1: a monotone cubic (C1, 0.4.0 to 0.7.0); 0: straight lines. The frames, the "
     "animated files' keys, the quality measures and the overlap test all use it",
     "straight lines (§6)"},
    {"growth_rate", "growth", field<&Params::growth, &Params::Growth::growth_rate>(), 0.0, inf,
     "g += growth_rate · Δt_sim per free step (§5.3)", "g += 0.001 Δt_sim per free step (§5.3)"},
    {"growth_boost", "growth", field<&Params::growth, &Params::Growth::growth_boost>(), 1.0, 100.0,
     "a free slice grows growth_rate × clamp(gap / boost_gap, 1, growth_boost) per step: faster while "
     "nothing is near it (1: off, the paper's one rate)",
     "one rate for every free slice (§5.3)"},
    {"boost_gap", "growth", field<&Params::growth, &Params::Growth::boost_gap>(), 1e-4, 1.0,
     "the slice gap (nearest other element or the wall) above which a free slice grows faster than "
     "growth_rate, in proportion to the gap",
     "not in the paper"},
    {"boost_speed", "growth", field<&Params::growth, &Params::Growth::boost_speed>(), 0.0, 1.0,
     "the room's boost never moves a slice's outline outwards faster than this share of velocity_cap "
     "(the farthest vertex from its centroid: its rest radius times the growth per step)",
     "not in the paper"},
    {"shrink_rate", "growth", field<&Params::growth, &Params::Growth::shrink_rate>(), 0.0, inf,
     "g -= shrink_rate · Δt_sim per step while overlapping", "not in the paper (growth pauses)"},
    {"growth_ratio", "growth", field<&Params::growth, &Params::Growth::growth_ratio>(), 1.0, inf,
     "largest g of an element ≤ growth_ratio × its smallest", "not in the paper (slices grow independently)"},
    {"neighbour_growth_ratio", "growth", field<&Params::growth, &Params::Growth::neighbour_growth_ratio>(), 1.0, inf,
     "g ≤ this × either time neighbour's g", "not in the paper"},
    {"settle_shrink_rate", "growth", field<&Params::growth, &Params::Growth::settle_shrink_rate>(), 0.0, inf,
     "g -= settle_shrink_rate · Δt_sim per settling step while overlapping", "not in the paper"},
    {"max_growth", "growth", field<&Params::growth, &Params::Growth::max_growth>(), 1.0, inf,
     "cap on a slice's growth factor g", "not in the paper"},
    {"stop_gap", "stop", field<&Params::stop, &Params::Stop::stop_gap>(), 0.0, 1.0,
     "stop when the largest per-slice gap is below this (§5.3)", "0.006 (§5.3)"},
    {"stop_growth", "stop", field<&Params::stop, &Params::Stop::stop_growth>(), 0.0, inf,
     "stop when every g exceeds this; 0 turns it off (§5.3)", "not in the paper"},
    {"max_iterations", "stop", field<&Params::stop, &Params::Stop::max_iterations>(), 1, 100000000,
     "hard cap on simulation steps", "none"},
    {"settle_iterations", "stop", field<&Params::stop, &Params::Stop::settle_iterations>(), 0, 100000000,
     "steps without growth to clear overlaps at the end", "not in the paper"},
    {"stall_window", "stop", field<&Params::stop, &Params::Stop::stall_window>(), 0, 100000000,
     "steps over which the stall test measures the rise of the mean g; 0 turns it off", "not in the paper"},
    {"stall_growth", "stop", field<&Params::stop, &Params::Stop::stall_growth>(), 0.0, inf,
     "mean g must rise by this share over a window, or growth has stalled", "not in the paper"},
    {"stall_tests", "stop", field<&Params::stop, &Params::Stop::stall_tests>(), 1, 4,
     "the stall test runs this many times per window, each over the last stall_window steps; 1: once per window",
     "not in the paper"},
    {"check_interval", "stop", field<&Params::stop, &Params::Stop::check_interval>(), 1, 100000,
     "NaN check and statistics every k steps (a settling run tests for a clean step after every step)", "none"},
}};

}  // namespace

std::span<const ParamInfo> param_table() { return table; }

double param_value(const Params& params, const ParamInfo& info) {
  Params copy = params;  // the accessors hand out a mutable reference
  return std::visit([&](auto field) { return static_cast<double>(field(copy)); }, info.field);
}

bool param_is_integer(const ParamInfo& info) { return std::holds_alternative<int& (*)(Params&)>(info.field); }

}  // namespace animpak
