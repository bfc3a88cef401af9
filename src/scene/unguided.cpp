// Unguided elements (paper §4): blue-noise seeds, a library pick per seed, an orientation, and the
// checks that the shrunken elements neither overlap nor leave the container.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "animpak/error.hpp"
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
std::vector<Vec2> free_seeds(const Container& c, double spacing, double margin, const std::vector<Placement>& guided,
                             Rng& rng) {
  std::vector<Vec2> seeds = poisson_disk(c, spacing, margin, rng);
  std::erase_if(seeds, [&](Vec2 p) {
    for (const Placement& g : guided)
      for (const Vec2 q : g.path)
        if (norm(p - q) < spacing) return true;
    return false;
  });
  return seeds;
}

template <class T>
void shuffle(std::vector<T>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.below(i)]);
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

// `wanted` seeds for a fixed count (a random subset of the first blue-noise set that holds enough), or
// every seed at seed_spacing when the scene fills; `spacing` is the spacing used.
std::vector<Vec2> unguided_seeds(const SceneSpec& scene, const Container& container,
                                 const std::vector<Placement>& guided, bool fill, int wanted, double margin, Rng& rng,
                                 double& spacing) {
  const std::string file = scene.file.string();
  std::vector<Vec2> seeds;
  spacing = scene.params.placement.seed_spacing;
  if (fill) return free_seeds(container, spacing, margin, guided, rng);
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
  shuffle(seeds, rng);
  seeds.resize(wanted);
  return seeds;
}

// The library element of each of `seeds` seeds: every fixed count, then the rest by weight; shuffled so
// kinds mix in space.
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
  shuffle(picks, rng);
  return picks;
}

}  // namespace

std::vector<Placement> place_unguided(const SceneSpec& scene, const Container& container,
                                      const std::vector<SpacetimeElement>& library,
                                      const std::vector<Placement>& guided, Rng& rng, std::vector<std::string>& notes) {
  const std::string file = scene.file.string();
  int fixed = 0;
  std::vector<int> weighted;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    if (scene.elements[i].count)
      fixed += *scene.elements[i].count;
    else if (scene.elements[i].weight > 0)
      weighted.push_back(static_cast<int>(i));
  }
  const bool fill = !scene.count && !weighted.empty();
  const int wanted = scene.count ? *scene.count : fixed;
  if (scene.count && wanted < fixed)
    throw InputError(file + ": count: " + std::to_string(wanted) + " is less than the elements' own counts (" +
                     std::to_string(fixed) + "); raise count or lower the per-element counts");
  if (scene.count && wanted > fixed && weighted.empty())
    throw InputError(file + ": count: " + std::to_string(wanted) + " differs from the sum of the elements' counts (" +
                     std::to_string(fixed) + ") and no element has a weight to fill the rest");

  double spacing = 0.0;
  const double margin = seed_margin(library, scene.params.placement.initial_scale);
  const std::vector<Vec2> seeds = unguided_seeds(scene, container, guided, fill, wanted, margin, rng, spacing);
  if (static_cast<int>(seeds.size()) < fixed)
    throw InputError(file + ": the elements' counts ask for " + std::to_string(fixed) + " elements but only " +
                     std::to_string(seeds.size()) + " seeds fit at params.seed_spacing " + std::to_string(spacing) +
                     "; lower the counts or the spacing");
  const std::vector<int> picks = library_picks(scene, weighted, seeds.size(), rng);

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
  notes.push_back("seeded " + std::to_string(out.size()) + " unguided element(s) at spacing " +
                  std::to_string(spacing) + (fill ? " (fill)" : ""));
  return out;
}

void check_placements(const Container& container, const std::vector<SpacetimeElement>& library,
                      const std::vector<Placement>& placements) {
  const std::size_t n = placements.size();
  std::vector<std::vector<std::vector<Vec2>>> rings(n);  // [instance][slice] → boundary ring
  std::vector<Box> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    const SpacetimeElement& e = library[placements[i].library];
    // A guided element's slices between targets lie on the straight path between them, which may
    // cross a hole or leave a concave container: place_guided warns, and the boundary force (Eq. 4)
    // pushes them in. Only the slices of its targets must start inside.
    std::vector<bool> must_fit(e.slice_count, !placements[i].guided);
    for (const Placement::Key& key : placements[i].keys) must_fit[key.slice] = true;
    for (int s = 0; s < e.slice_count; ++s) {
      std::vector<Vec2> ring;
      for (int v = 0; v < e.slice.boundary_count; ++v) {
        const Vec2 p = placed(placements[i], e, s, v);
        if (must_fit[s] && !container.contains(p))
          throw InputError("element " + placements[i].name + " lies outside the container at slice " +
                           std::to_string(s) + " after shrinking; move its seed or targets inward");
        ring.push_back(p);
        boxes[i].add(p);
      }
      rings[i].push_back(std::move(ring));
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (boxes[i].max.x < boxes[j].min.x || boxes[j].max.x < boxes[i].min.x || boxes[i].max.y < boxes[j].min.y ||
          boxes[j].max.y < boxes[i].min.y)
        continue;
      for (std::size_t s = 0; s < rings[i].size(); ++s)
        if (rings_overlap(rings[i][s], rings[j][s]))
          throw InputError("elements " + placements[i].name + " and " + placements[j].name + " overlap at slice " +
                           std::to_string(s) +
                           " after shrinking; lower params.initial_scale or move their seeds or targets apart");
    }
}

}  // namespace animpak::scene_detail
