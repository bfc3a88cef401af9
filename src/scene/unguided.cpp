// Unguided elements (paper §4): blue-noise seeds, a library pick per seed, an orientation, and the
// checks that the shrunken elements neither overlap nor leave the container.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/param_table.hpp"
#include "placement.hpp"

namespace animpak::scene_detail {
namespace {

double orientation(const OrientationSpec& o, const Container& c, Vec2 p, Rng& rng) {
  constexpr double deg = std::numbers::pi / 180.0;
  if (o.mode == OrientationMode::random) return rng.uniform(0.0, 2.0 * std::numbers::pi);
  if (o.mode == OrientationMode::fixed || o.field == FieldKind::constant) return o.angle * deg;
  const Vec2 d = p - c.frame.to_unit(o.center);
  const double radial = std::atan2(d.y, d.x);
  return o.field == FieldKind::radial ? radial : radial + 0.5 * std::numbers::pi;
}

// Seeds at least `spacing` from every guided element's anchor path: the paper rejects seeds whose
// element would cross a guided element's volume, and `spacing` is the room each element gets.
// `clearance` (default: spacing) is the distance kept from the paths.
std::vector<Vec2> free_seeds(const Container& c, double spacing, double margin, const std::vector<Placement>& guided,
                             double clearance, Rng& rng) {
  std::vector<Vec2> seeds = poisson_disk(c, spacing, margin, rng);
  std::erase_if(seeds, [&](Vec2 p) {
    for (const Placement& g : guided)
      for (const Vec2 q : g.path)
        if (norm(p - q) < clearance) return true;
    return false;
  });
  return seeds;
}

std::vector<Vec2> free_seeds(const Container& c, double spacing, double margin, const std::vector<Placement>& guided,
                             Rng& rng) {
  return free_seeds(c, spacing, margin, guided, spacing, rng);
}

// The smallest distance between two of `points` (infinity for fewer than two).
double closest_pair(const std::vector<Vec2>& points) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) d = std::min(d, norm(points[i] - points[j]));
  return d;
}

// Lloyd iterations over the picked seeds (docs/parameters.md, "Seeds for a fixed count").
constexpr int seed_relaxation = 20;

template <class T>
void shuffle(std::vector<T>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.below(i)]);
}

// `seeds` in the order they spread: from the first seed, each next one the seed farthest from those
// before it (ties to the lower index). spread_seeds' selection without its wall term: counting the wall
// (as spread_seeds does to choose where seeds go) starts the order deep inside and mixed the kinds of
// fill scenes less (nearest neighbour of the same kind 0.21 and 0.18 against 0.20 and 0.10 without it,
// tests/scene/test_world.cpp).
std::vector<Vec2> in_spreading_order(const std::vector<Vec2>& seeds) {
  const std::size_t n = seeds.size();
  std::vector<Vec2> order;
  std::vector<double> room(n, std::numeric_limits<double>::infinity());
  std::vector<bool> taken(n, false);
  for (std::size_t next = 0; next < n;) {
    taken[next] = true;
    order.push_back(seeds[next]);
    std::size_t best = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (taken[i]) continue;
      room[i] = std::min(room[i], norm(seeds[i] - seeds[next]));
      if (best == n || room[i] > room[best]) best = i;
    }
    next = best;
  }
  return order;
}

// How far a seed must stay from the wall: the largest rest radius of any library element at
// initial_scale, with 5 % to spare, keeps a shrunken element inside whatever its orientation.
double seed_margin(const std::vector<SpacetimeElement>& library, double initial_scale) {
  double radius = 0.0;
  for (const SpacetimeElement& e : library) {
    const Vec2 c = rest_centroid(e);
    for (int s = 0; s < e.slice_count; ++s)
      for (int v = 0; v < e.slice.boundary_count; ++v) radius = std::max(radius, norm(e.position(s, v) - c));
  }
  return 1.05 * initial_scale * radius;
}

// `wanted` seeds for a fixed count, spread over the container (no closer than the first blue-noise set
// that holds enough, or than two shrunken elements' reach), or every seed at seed_spacing when the
// scene fills; `spacing` is the blue-noise spacing used.
std::vector<Vec2> unguided_seeds(const SceneSpec& scene, const Container& container,
                                 const std::vector<Placement>& guided, bool fill, int wanted, double margin, Rng& rng,
                                 double& spacing) {
  const std::string file = scene.file.string();
  std::vector<Vec2> seeds;
  spacing = scene.params.placement.seed_spacing;
  if (fill) return in_spreading_order(free_seeds(container, spacing, margin, guided, rng));
  if (wanted <= 0) return seeds;
  // Start looser than `wanted` discs can fill and tighten in small steps, so the first spacing that
  // fits gives only a few extra seeds: dropping many random extras would leave holes.
  spacing = std::sqrt(1.6 * container.area() / wanted);
  for (int attempt = 0; attempt < 120; ++attempt, spacing *= 0.97) {
    Rng trial = rng.split();
    seeds = free_seeds(container, spacing, margin, guided, trial);
    if (static_cast<int>(seeds.size()) >= wanted) break;
  }
  if (static_cast<int>(seeds.size()) < wanted)
    throw InputError(file + ": count: only " + std::to_string(seeds.size()) + " of " + std::to_string(wanted) +
                     " elements fit in the container at initial_scale " +
                     std::to_string(scene.params.placement.initial_scale) + "; lower count or params.initial_scale");
  // A random subset of those left regions empty (the clip-art example's heart started with its lower
  // third bare, and elements do not travel that far). Farthest-point selection among candidates four
  // times denser, from a random first pick, spreads the seeds over the whole container, the wall
  // counting as a mirror image, and Lloyd relaxation then evens them out, keeping the margin and the
  // guided paths' clearance. Where that brings two seeds so close that their shrunken elements could
  // touch (a crowded scene), the random subset stays: its spacing is the largest that holds them all.
  const std::vector<Vec2> dense = scene.params.placement.seed_spread != 0
                                      ? free_seeds(container, 0.25 * spacing, margin, guided, spacing, rng)
                                      : std::vector<Vec2>{};
  if (!dense.empty()) {
    std::vector<Vec2> occupied;
    for (const Placement& g : guided) occupied.insert(occupied.end(), g.path.begin(), g.path.end());
    std::vector<Vec2> picks = spread_seeds(container, dense, wanted, occupied, rng.below(dense.size()));
    if (static_cast<int>(picks.size()) == wanted && closest_pair(picks) >= 2.0 * margin) {
      std::vector<Vec2> relaxed = relax_seeds(container, picks, occupied, margin, spacing, seed_relaxation);
      return closest_pair(relaxed) >= 2.0 * margin ? relaxed : picks;
    }
  }
  shuffle(seeds, rng);
  seeds.resize(wanted);
  return in_spreading_order(seeds);
}

// The library element of each of `seeds` seeds, which come in their spreading order: every fixed count,
// then the rest by weight, each kind taking the next block of that order. The first block spreads over
// the whole container, and each later one fills the gaps the blocks before it left, so an element's
// nearest neighbours are mostly of other kinds: kinds mix in space.
std::vector<int> library_picks(const SceneSpec& scene, const std::vector<int>& weighted, std::size_t seeds, Rng& rng) {
  std::vector<int> picks;
  for (std::size_t i = 0; i < scene.elements.size(); ++i)
    for (int k = 0; k < scene.elements[i].count.value_or(0); ++k) picks.push_back(static_cast<int>(i));
  double total_weight = 0.0;
  for (int i : weighted) total_weight += scene.elements[i].weight;
  while (picks.size() < seeds) {
    double u = rng.uniform() * total_weight;
    int pick = weighted.back();
    for (int i : weighted)
      if ((u -= scene.elements[i].weight) < 0) {
        pick = i;
        break;
      }
    picks.push_back(pick);
  }
  return picks;
}

// The unguided elements a scene asks for: the per-element counts, the elements drawn by weight, and
// whether it fills the container (no `count` and an element with a weight) or asks for `wanted` elements.
struct Request {
  int fixed = 0;
  std::vector<int> weighted;
  bool fill = false;
  int wanted = 0;
};

Request request_of(const SceneSpec& scene) {
  Request r;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    if (scene.elements[i].count)
      r.fixed += *scene.elements[i].count;
    else if (scene.elements[i].weight > 0)
      r.weighted.push_back(static_cast<int>(i));
  }
  r.fill = !scene.count && !r.weighted.empty();
  r.wanted = scene.count ? *scene.count : r.fixed;
  return r;
}

// The shrunken boundary ring of every slice of one instance, and their box.
struct PlacedRings {
  std::vector<std::vector<Vec2>> rings;  // [slice] → boundary ring
  Box box;
};

PlacedRings placed_rings(const Placement& p, const SpacetimeElement& e) {
  PlacedRings out;
  for (int s = 0; s < e.slice_count; ++s) {
    std::vector<Vec2> ring;
    for (int v = 0; v < e.slice.boundary_count; ++v) {
      ring.push_back(placed(p, e, s, v));
      out.box.add(ring.back());
    }
    out.rings.push_back(std::move(ring));
  }
  return out;
}

std::vector<Placement> unguided_placements(const SceneSpec& scene, const Container& container,
                                           const std::vector<SpacetimeElement>& library,
                                           const std::vector<Placement>& guided, Rng& rng, double& spacing) {
  const std::string file = scene.file.string();
  const Request request = request_of(scene);
  const int fixed = request.fixed, wanted = request.wanted;
  const bool fill = request.fill;
  if (scene.count && wanted < fixed)
    throw InputError(file + ": count: " + std::to_string(wanted) + " is less than the elements' own counts (" +
                     std::to_string(fixed) + "); raise count or lower the per-element counts");
  if (scene.count && wanted > fixed && request.weighted.empty())
    throw InputError(file + ": count: " + std::to_string(wanted) + " differs from the sum of the elements' counts (" +
                     std::to_string(fixed) + ") and no element has a weight to fill the rest");

  const double margin = seed_margin(library, scene.params.placement.initial_scale);
  // Making way, seeds cover the whole container, the guided paths included: the elements on a path step
  // aside while its traveller passes (make_way.cpp). Otherwise they keep off every point of every path.
  const bool making_way = scene.params.placement.make_way > 0 && !guided.empty();
  const std::vector<Vec2> seeds = unguided_seeds(scene, container, making_way ? std::vector<Placement>{} : guided, fill,
                                                 wanted, margin, rng, spacing);
  if (static_cast<int>(seeds.size()) < fixed)
    throw InputError(file + ": the elements' counts ask for " + std::to_string(fixed) + " elements but only " +
                     std::to_string(seeds.size()) + " seeds fit at params.seed_spacing " + std::to_string(spacing) +
                     "; lower the counts or the spacing");
  const std::vector<int> picks = library_picks(scene, request.weighted, seeds.size(), rng);

  std::vector<Placement> out;
  std::vector<int> per_library(library.size(), 0);
  // Phases come from their own stream, so that a phase leaves the seeds and orientations as they were.
  Rng phases(scene.seed ^ 0x70686173652d7267ull);
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const SpacetimeElement& e = library[picks[k]];
    Placement p;
    p.library = picks[k];
    p.name = e.name + "#" + std::to_string(++per_library[picks[k]]);
    p.pivot = rest_centroid(e);
    const double angle = orientation(scene.orientation, container, seeds[k], rng);
    p.offset.assign(e.slice_count, seeds[k]);
    p.seed = seeds[k];
    p.scale.assign(e.slice_count, scene.params.placement.initial_scale);
    p.angle.assign(e.slice_count, angle);
    const LibraryElementSpec& spec = scene.elements[picks[k]];
    p.secondary = spec.secondary;
    const int period = e.slice_count - 1;
    if (spec.random_phase)
      p.phase = static_cast<int>(phases.below(static_cast<std::uint64_t>(period)));
    else
      p.phase = static_cast<int>(std::lround(spec.phase * period)) % period;
    out.push_back(std::move(p));
  }
  if (!making_way) return out;
  make_way(scene, container, library, guided, out, margin);
  // A seed is refused only where its element, on its path, still meets a guided element's shrunken slice
  // at the same time (a seed pinned between a wall and a traveller); a fixed count keeps it, and the
  // placement check names the pair.
  if (fill) {
    std::vector<PlacedRings> travellers;
    for (const Placement& g : guided) travellers.push_back(placed_rings(g, library[g.library]));
    std::erase_if(out, [&](const Placement& p) {
      const PlacedRings mine = placed_rings(p, library[p.library]);
      for (const PlacedRings& t : travellers)
        for (std::size_t s = 0; s < mine.rings.size(); ++s)
          if (rings_overlap(mine.rings[s], t.rings[s])) return true;
      return false;
    });
  }
  return out;
}

// The first slice at which an instance has a vertex outside the container, or -1. A guided element's
// slices between targets lie on the straight path between them, which may cross a hole or leave a
// concave container: place_guided warns, and the boundary force (Eq. 4) pushes them in. Only the slices
// of its targets must start inside.
int slice_outside(const Container& container, const Placement& p, const PlacedRings& placed) {
  std::vector<bool> must_fit(placed.rings.size(), !p.guided);
  for (const Placement::Key& key : p.keys) must_fit[key.slice] = true;
  for (std::size_t s = 0; s < placed.rings.size(); ++s)
    if (must_fit[s] &&
        !std::all_of(placed.rings[s].begin(), placed.rings[s].end(), [&](Vec2 q) { return container.contains(q); }))
      return static_cast<int>(s);
  return -1;
}

struct Overlap {
  std::size_t a = 0, b = 0;  // a < b
  int slice = 0;
};

// The first pair of instances (a, b), b >= `from`, whose shrunken boundaries overlap on a slice.
std::optional<Overlap> first_overlap(const std::vector<PlacedRings>& placed, std::size_t from) {
  for (std::size_t j = from; j < placed.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const Box &bi = placed[i].box, &bj = placed[j].box;
      if (bi.max.x < bj.min.x || bj.max.x < bi.min.x || bi.max.y < bj.min.y || bj.max.y < bi.min.y) continue;
      for (std::size_t s = 0; s < placed[i].rings.size(); ++s)
        if (rings_overlap(placed[i].rings[s], placed[j].rings[s])) return Overlap{i, j, static_cast<int>(s)};
    }
  return std::nullopt;
}

std::vector<PlacedRings> rings_of(const std::vector<SpacetimeElement>& library,
                                  const std::vector<Placement>& placements) {
  std::vector<PlacedRings> out;
  for (const Placement& p : placements) out.push_back(placed_rings(p, library[p.library]));
  return out;
}

// The scene with `k` unguided elements: `count` k where it has one, and the elements' counts scaled to add
// up to k (largest remainders first) where they ask for more than k.
SceneSpec with_count(const SceneSpec& scene, const Request& request, int k) {
  SceneSpec trial = scene;
  if (scene.count) trial.count = k;
  if (request.fixed <= k) return trial;
  std::vector<std::pair<double, std::size_t>> remainders;
  int given = 0;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    if (!scene.elements[i].count) continue;
    const double share = static_cast<double>(*scene.elements[i].count) * k / request.fixed;
    trial.elements[i].count = static_cast<int>(std::floor(share));
    given += *trial.elements[i].count;
    remainders.emplace_back(share - std::floor(share), i);
  }
  std::stable_sort(remainders.begin(), remainders.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  for (std::size_t r = 0; given < k && r < remainders.size(); ++r, ++given)
    ++*trial.elements[remainders[r].second].count;
  return trial;
}

// What goes wrong in the placement build_world makes for `trial` from `rng`: an unguided element outside
// the container or overlapping another; nothing when every unguided element fits.
std::optional<std::string> unguided_misfit(const SceneSpec& trial, const Container& container,
                                           const std::vector<SpacetimeElement>& library, Rng rng) {
  std::vector<std::string> notes;
  std::vector<Placement> all = place_guided(trial, container, library, notes);
  const std::size_t guided = all.size();
  try {
    double spacing = 0.0;
    for (Placement& p : unguided_placements(trial, container, library, all, rng, spacing)) all.push_back(std::move(p));
  } catch (const InputError&) {
    return std::string("the seeds do not fit");
  }
  const std::vector<PlacedRings> placed = rings_of(library, all);
  for (std::size_t i = guided; i < all.size(); ++i)
    if (const int s = slice_outside(container, all[i], placed[i]); s >= 0)
      return "element " + all[i].name + " lies outside the container at slice " + std::to_string(s);
  if (const std::optional<Overlap> o = first_overlap(placed, guided))
    return "elements " + all[o->a].name + " and " + all[o->b].name + " overlap at slice " + std::to_string(o->slice);
  return std::nullopt;
}

std::string shown(double v) {
  std::ostringstream text;
  text << v;
  return text.str();
}

// What to lower to place `n` elements: the scene's `count`, the one element's count, or all of theirs.
std::string lower_count_to(const SceneSpec& scene, const Request& request, int n) {
  const SceneSpec trial = with_count(scene, request, n);
  std::vector<std::size_t> counted;
  for (std::size_t i = 0; i < scene.elements.size(); ++i)
    if (scene.elements[i].count && *scene.elements[i].count > 0) counted.push_back(i);
  std::string elements;
  for (std::size_t i : counted)
    elements += std::string(elements.empty() ? "" : ", ") + "\"" + scene.elements[i].name + "\" " +
                std::to_string(*trial.elements[i].count);
  if (scene.count && request.fixed <= n) return "`count` to " + std::to_string(n);
  if (scene.count) return "`count` to " + std::to_string(n) + " and the elements' counts to " + elements;
  if (counted.size() == 1)
    return "elements[" + std::to_string(counted.front()) + "] (\"" + scene.elements[counted.front()].name +
           "\") `count` to " + std::to_string(n);
  return "the elements' counts to add up to " + std::to_string(n) + " (" + elements + ")";
}

// The largest initial_scale at which all of the scene's unguided elements place, times `share`, rounded
// down to three significant digits and checked to place; empty when none in the parameter's range does.
// Searched on the placement itself between the parameter's range ends, so the value does not depend on the
// scale the scene started from (scaling the given one by the share that fits offered 0.0365 from 0.1 but
// 0.0571 from 0.07). Placing is not strictly monotone in the scale (the seeds' margin moves with it), so
// the bisection finds a boundary, and the rounded value is checked once more, stepping down until it places.
std::optional<double> largest_placing_scale(const SceneSpec& scene, const Container& container,
                                            const std::vector<SpacetimeElement>& library, const Rng& unguided_rng,
                                            double share) {
  double lowest = 0.0, highest = 1.0;
  for (const ParamInfo& info : param_table())
    if (info.name == "initial_scale") lowest = info.min, highest = info.max;
  const auto places = [&](double s) {
    SceneSpec trial = scene;
    trial.params.placement.initial_scale = s;
    return !unguided_misfit(trial, container, library, unguided_rng);
  };
  if (!places(lowest)) return std::nullopt;
  double fits_at = lowest, fails_at = highest;
  for (int step = 0; step < 16 && fails_at - fits_at > 1e-4 * fails_at; ++step) {
    const double mid = 0.5 * (fits_at + fails_at);
    (places(mid) ? fits_at : fails_at) = mid;
  }
  const double wanted = std::max(lowest, share * fits_at);
  const double digit = std::pow(10.0, std::floor(std::log10(wanted)) - 2);  // 3 significant digits, down
  double rounded = std::floor(wanted / digit) * digit;
  for (int step = 0; step < 10 && rounded >= lowest; ++step, rounded -= digit)
    if (places(rounded)) return rounded;
  return std::nullopt;
}

// The error for unguided elements that overlap because the scene asks for more than fit: how many do fit,
// found by placing them as build_world does (the same seeds from the same generator) for fewer and fewer;
// the largest count that places without overlap is what the message offers, and the next one overlaps.
[[noreturn]] void too_many(const SceneSpec& scene, const Container& container,
                           const std::vector<SpacetimeElement>& library, const Rng& unguided_rng,
                           const std::string& overlap) {
  const Request request = request_of(scene);
  const double scale = scene.params.placement.initial_scale;
  int fits = 0, overlaps = request.wanted;  // 0 unguided elements always fit; the scene's count did not
  std::string misfit = overlap;             // what goes wrong with `overlaps` elements
  while (overlaps - fits > 1) {
    const int mid = fits + (overlaps - fits) / 2;
    if (std::optional<std::string> why =
            unguided_misfit(with_count(scene, request, mid), container, library, unguided_rng))
      overlaps = mid, misfit = *why;
    else
      fits = mid;
  }
  const std::optional<double> smaller = largest_placing_scale(scene, container, library, unguided_rng, 1.0);
  throw InputError(scene.file.string() + ": " + std::to_string(request.wanted) + " elements requested, at most about " +
                   std::to_string(fits) + " fit in the container at params.initial_scale " + shown(scale) +
                   " (placed as pack places them, " + std::to_string(fits) + " do not overlap; with " +
                   std::to_string(fits + 1) + ", " + misfit + "); lower " + lower_count_to(scene, request, fits) +
                   " or lower params.initial_scale" +
                   (smaller ? " (to " + shown(*smaller) + " all " + std::to_string(request.wanted) + " fit)" : ""));
}

}  // namespace

std::vector<Placement> place_unguided(const SceneSpec& scene, const Container& container,
                                      const std::vector<SpacetimeElement>& library,
                                      const std::vector<Placement>& guided, Rng& rng, std::vector<std::string>& notes) {
  double spacing = 0.0;
  std::vector<Placement> out = unguided_placements(scene, container, library, guided, rng, spacing);
  notes.push_back("seeded " + std::to_string(out.size()) + " unguided element(s) at spacing " +
                  std::to_string(spacing) + (request_of(scene).fill ? " (fill)" : ""));
  double detour = 0.0;
  std::size_t moved = 0;
  for (const Placement& p : out) {
    double largest = 0.0;
    for (const Vec2 q : p.offset) largest = std::max(largest, norm(q - p.seed));
    detour = std::max(detour, largest);
    if (largest > 0.0) ++moved;
  }
  if (moved > 0)
    notes.push_back("making way for " + std::to_string(guided.size()) + " guided element(s): " + std::to_string(moved) +
                    " unguided element(s) start on paths that step aside, at most " + shown(detour) +
                    " from their seeds (params.make_way 0: straight starts)");
  return out;
}

std::optional<double> picked_initial_scale(const SceneSpec& scene, const Container& container,
                                           const std::vector<SpacetimeElement>& library, const Rng& unguided_rng) {
  const Request request = request_of(scene);
  if (scene.initial_scale_given || request.fill || request.wanted == 0) return std::nullopt;
  if (!unguided_misfit(scene, container, library, unguided_rng)) return std::nullopt;
  // A start a little below the largest that places, so that the elements do not start touching.
  return largest_placing_scale(scene, container, library, unguided_rng, kPickedScaleShare);
}

void check_placements(const SceneSpec& scene, const Container& container, const std::vector<SpacetimeElement>& library,
                      const std::vector<Placement>& placements, const Rng& unguided_rng) {
  const std::string file = scene.file.string();
  const std::vector<PlacedRings> placed = rings_of(library, placements);
  for (std::size_t i = 0; i < placements.size(); ++i) {
    const int s = slice_outside(container, placements[i], placed[i]);
    if (s >= 0)
      throw InputError(file + ": element " + placements[i].name + " lies outside the container at slice " +
                       std::to_string(s) + " after shrinking; move its seed or targets inward");
  }
  const std::optional<Overlap> overlap = first_overlap(placed, 0);
  if (!overlap) return;
  const std::string pair = "elements " + placements[overlap->a].name + " and " + placements[overlap->b].name +
                           " overlap at slice " + std::to_string(overlap->slice);
  // Guided elements come first: a pair with an unguided element in a scene that asks for a number of them.
  const Request request = request_of(scene);
  if (!placements[overlap->b].guided && !request.fill && request.wanted > 0)
    too_many(scene, container, library, unguided_rng, pair);
  throw InputError(file + ": " + pair +
                   " after shrinking; lower params.initial_scale or move their seeds or targets apart");
}

}  // namespace animpak::scene_detail
