// Unguided elements make way for guided ones (docs/parameters.md, "Making way"). The paper (§4) keeps
// every unguided seed off a guided element's whole volume, which for a straight tube is every point the
// traveller ever crosses: the route stays an empty band in every frame. Here seeds cover the whole
// container, and each unguided element starts on a path that steps aside while a traveller passes and
// comes back after: per slice, the crowd is relaxed as discs of the elements' expected full sizes, each
// tied to its seed, pushed out of every traveller's footprint at that time, apart from each other and off
// the wall, warm-started from the slice before and run round the loop until it closes. The crowd moves
// as a whole, as a 2D granular packing or a foam flows round an intruder.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "placement.hpp"

namespace animpak::scene_detail {
namespace {

// Relaxation rounds per slice, and the share of the way back to its seed a disc moves each round: with
// contacts projected fully, a tie of 0.15 lets a push die out within about two or three discs, as the
// disturbance round an intruder does in a 2D granular packing.
constexpr double tie = 0.15;
// A slice interval is crossed in `substeps` steps of `rounds_per_substep` rounds; the first slice settles
// from the seeds in `settle_rounds`.
constexpr int substeps = 6;
constexpr int rounds_per_substep = 30;
constexpr int settle_rounds = 200;
// Projections of the hard limits after every round.
constexpr int hard_sweeps = 3;
constexpr double wall_spare = 1.3;
// The share of a traveller's push that would carry a disc ahead of it which goes sideways instead.
constexpr double sideways = 0.7;
// An element's script dips fully where its disc touches a traveller's footprint, and not at all from
// `dip_reach` disc radii away.
constexpr double dip_reach = 2.0;
// Smoothing passes of the finished paths along t ([1/4, 1/2, 1/4]), so that a disc that slips from one
// side of its neighbour to the other does not jerk the element's start.
constexpr int smoothing_passes = 3;

struct Nearest {
  Vec2 point;
  double distance = std::numeric_limits<double>::infinity();
};

Nearest nearest_on_ring(const std::vector<Vec2>& ring, Vec2 p, Nearest best = {}) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    const Vec2 ab = b - a;
    const double len2 = dot(ab, ab);
    const double u = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const Vec2 q = a + u * ab;
    if (const double d = norm(p - q); d < best.distance) best = {q, d};
  }
  return best;
}

Nearest nearest_on_wall(const Container& c, Vec2 p) {
  Nearest best = nearest_on_ring(c.outline, p);
  for (const auto& hole : c.holes) best = nearest_on_ring(hole, p, best);
  return best;
}

// Moves `p` out of `ring` (a traveller's footprint) to at least `clearance` from its outline.
Vec2 out_of(const std::vector<Vec2>& ring, Vec2 p, double clearance) {
  const bool inside = ring_contains(ring, p);
  const Nearest n = nearest_on_ring(ring, p);
  if (!inside && n.distance >= clearance) return p;
  if (!(n.distance > 0)) return p;  // on the outline itself: no direction; the next round moves it
  const Vec2 away = (inside ? -1.0 : 1.0) / n.distance * (p - n.point);
  return n.point + clearance * away;
}

// `p` moved to at least `room` from the wall and inside the container, along the wall's normal; `p`
// itself when it is there already, nothing when the wall's normal does not lead there (a concave corner).
std::optional<Vec2> with_room(const Container& c, Vec2 p, double room) {
  const bool inside = c.contains(p);
  const Nearest n = nearest_on_wall(c, p);
  if (inside && n.distance >= room) return p;
  if (!(n.distance > 0)) return std::nullopt;
  const Vec2 q = n.point + room * ((inside ? 1.0 : -1.0) / n.distance * (p - n.point));
  if (c.contains(q) && c.distance_to_boundary(q) >= 0.999 * room) return q;
  return std::nullopt;
}

double ring_area(const SpacetimeElement& e) {
  std::vector<Vec2> ring(e.slice.vertices.begin(), e.slice.vertices.begin() + e.slice.boundary_count);
  return std::abs(signed_area(ring));
}

}  // namespace

void make_way(const SceneSpec& scene, const Container& container, const std::vector<SpacetimeElement>& library,
              const std::vector<Placement>& guided, std::vector<Placement>& unguided, double margin) {
  const double share = scene.params.placement.make_way;
  if (!(share > 0) || guided.empty() || unguided.empty()) return;
  const int slices = static_cast<int>(unguided.front().offset.size());
  const double s0 = scene.params.placement.initial_scale;

  // The growth g at which the elements' outlines (channel included) would cover `share` of the container.
  double area = 0.0;
  for (const Placement& p : guided) area += ring_area(library[p.library]) * p.scale.front() * p.scale.front();
  for (const Placement& p : unguided) area += ring_area(library[p.library]) * s0 * s0;
  if (!(area > 0)) return;
  const double g = std::min(std::sqrt(share * container.area() / area), scene.params.growth.max_growth);

  const std::size_t n = unguided.size();
  const double max_step = 0.5 * margin;
  std::vector<Vec2> seed(n), x(n);
  std::vector<double> radius(n), room(n), wall(n);
  for (std::size_t i = 0; i < n; ++i) {
    seed[i] = x[i] = unguided[i].offset.front();
    radius[i] = s0 * g * std::sqrt(ring_area(library[unguided[i].library]) / std::numbers::pi);
    // A disc keeps its full radius from the wall, or its seed's distance where the seed sits nearer: a seed
    // is never pushed off the wall when no traveller is near.
    room[i] = std::max(margin, std::min(radius[i], container.distance_to_boundary(seed[i])));
    // The hard limit keeps a little more than the margin where the seed allows: the curve between slices
    // (docs/parameters.md, "Motion between slices") bulges slightly past a path that slides along the wall.
    wall[i] = std::max(margin, std::min(wall_spare * margin, container.distance_to_boundary(seed[i])));
  }

  // Each traveller's footprint at slice s: its placed outline grown by `grow` about its anchor's path point.
  const auto footprint = [&](const Placement& p, int s, double grow) {
    const SpacetimeElement& e = library[p.library];
    std::vector<Vec2> ring;
    for (int v = 0; v < e.slice.boundary_count; ++v)
      ring.push_back(p.path[s] + grow * (placed(p, e, s, v) - p.path[s]));
    return ring;
  };

  // The footprints at every slice, and between two slices each vertex on the straight line between them.
  // The shrunken elements (`margin` holds any of them round its centroid) are what must not meet: they
  // are kept hard, the discs of the expected sizes soft. Footprints are kept at both sizes.
  using Rings = std::vector<std::vector<Vec2>>;
  std::vector<Rings> at_slice(slices), shrunken(slices);
  for (int s = 0; s < slices; ++s)
    for (const Placement& p : guided) {
      at_slice[s].push_back(footprint(p, s, g));
      shrunken[s].push_back(footprint(p, s, 1.0));
    }
  const auto blend = [&](const std::vector<Rings>& rings, int s, double u) {
    if (u <= 0.0 || s + 1 >= slices) return rings[s];
    Rings out = rings[s];
    for (std::size_t k = 0; k < out.size(); ++k)
      for (std::size_t v = 0; v < out[k].size(); ++v) out[k][v] = out[k][v] + u * (rings[s + 1][k][v] - out[k][v]);
    return out;
  };

  // The hard limits, projected in turn: shrunken elements apart, out of the shrunken travellers, inside.
  const auto keep_apart = [&](const Rings& small) {
    for (int sweep = 0; sweep < hard_sweeps; ++sweep) {
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
          const Vec2 d = x[j] - x[i];
          const double dist = norm(d), overlap = 2.0 * margin - dist;
          if (!(overlap > 0) || !(dist > 0)) continue;
          const Vec2 push = (0.5 * overlap / dist) * d;
          x[i] = x[i] - push;
          x[j] = x[j] + push;
        }
      for (std::size_t i = 0; i < n; ++i) {
        Vec2 q = x[i];
        for (const std::vector<Vec2>& ring : small) q = out_of(ring, q, margin);
        if (const std::optional<Vec2> inside = with_room(container, q, wall[i])) x[i] = *inside;
      }
    }
  };

  // A traveller's heading over slice interval s (towards the next slice; the last one's for the last).
  const auto heading = [&](std::size_t k, int s) {
    const std::vector<Vec2>& path_k = guided[k].path;
    const int a = std::min(s, slices - 2), b = a + 1;
    const Vec2 d = path_k[b] - path_k[a];
    const double length = norm(d);
    return length > 0 ? (1.0 / length) * d : Vec2{0.0, 0.0};
  };

  const auto relax = [&](const Rings& travellers, const Rings& small, int s, int rounds) {
    std::vector<Vec2> before(n);
    for (int round = 0; round < rounds; ++round) {
      before = x;
      for (std::size_t i = 0; i < n; ++i) x[i] = x[i] + tie * (seed[i] - x[i]);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
          const Vec2 d = x[j] - x[i];
          const double dist = norm(d), overlap = radius[i] + radius[j] - dist;
          if (!(overlap > 0) || !(dist > 0)) continue;
          const Vec2 push = (0.5 * overlap / dist) * d;
          x[i] = x[i] - push;
          x[j] = x[j] + push;
        }
      // Out of every traveller's way, then the wall's room, then the hard limit: a centre at least
      // `margin` inside, so the shrunken element is. The wall is rigid and a traveller is not (it deforms
      // and shrinks like any element), so between the two a disc keeps its room from the wall and overlaps
      // the traveller's expected footprint instead; pushed against the wall, it keeps the push's share
      // along the wall and slides round the traveller.
      for (std::size_t i = 0; i < n; ++i) {
        Vec2 q = x[i];
        // No disc moves more than `max_step` a round, so none tunnels through a thin traveller or snaps
        // home through the crowd.
        if (const Vec2 step = q - before[i]; norm(step) > max_step) q = before[i] + (max_step / norm(step)) * step;
        for (std::size_t k = 0; k < travellers.size(); ++k) {
          // Out of the traveller's way, but what would push the disc ahead of it goes to the side the disc
          // is on instead: the crowd flows round an intruder rather than being carried along.
          Vec2 push = out_of(travellers[k], q, radius[i]) - q;
          const Vec2 v = heading(k, s), side{-v.y, v.x};
          if (const double ahead = dot(push, v); ahead > 0) {
            const Vec2 centre = guided[k].path[std::min(s, slices - 1)];
            const double sign = dot(q - centre, side) >= 0 ? 1.0 : -1.0;
            push = push - (sideways * ahead) * v + (sign * sideways * ahead) * side;
          }
          q = q + push;
        }
        q = with_room(container, q, room[i]).value_or(q);
        if (const std::optional<Vec2> inside = with_room(container, q, wall[i])) x[i] = *inside;
      }
      keep_apart(small);
    }
  };

  // From slice to slice in substeps, so that a traveller never jumps over a disc in its way: the disc is
  // pushed aside, and its start never crosses the traveller's between two slices. Round the loop twice,
  // the second time warm-started from the end of the first, so that the last slice leads into the first;
  // without a loop, once from the seeds.
  std::vector<std::vector<Vec2>> path(n, std::vector<Vec2>(slices));
  const int intervals = slices - 1;
  relax(at_slice[0], shrunken[0], 0, settle_rounds);
  for (int pass = scene.loop ? 0 : 1; pass < 2; ++pass) {
    for (std::size_t i = 0; i < n; ++i) path[i][0] = x[i];
    for (int s = 0; s < intervals; ++s) {
      for (int k = 1; k <= substeps; ++k)
        relax(blend(at_slice, s, double(k) / substeps), blend(shrunken, s, double(k) / substeps), s,
              rounds_per_substep);
      for (std::size_t i = 0; i < n; ++i) path[i][s + 1] = x[i];
    }
  }
  if (scene.loop)
    for (std::size_t i = 0; i < n; ++i) path[i][slices - 1] = path[i][0];

  // How deep a point lies in the footprints at slice s: the most by which it is nearer one than its radius.
  const auto depth = [&](Vec2 q, int s, double r) {
    double d = 0.0;
    for (const std::vector<Vec2>& ring : at_slice[s])
      d = std::max(d, ring_contains(ring, q) ? r + nearest_on_ring(ring, q).distance
                                             : r - nearest_on_ring(ring, q).distance);
    return d;
  };
  // A smoothed point must keep the element inside, apart from the others' shrunken elements and no
  // deeper in a traveller's way; elements are smoothed one after the other, each against the others' latest.
  const int period = scene.loop ? intervals : slices;
  for (int pass = 0; pass < smoothing_passes; ++pass)
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<Vec2>& p = path[i];
      std::vector<Vec2> smooth = p;
      for (int s = 0; s < period; ++s) {
        const int before = s > 0 ? s - 1 : (scene.loop ? period - 1 : 0);
        const int after = s + 1 < period ? s + 1 : (scene.loop ? 0 : s);
        const Vec2 q = 0.25 * p[before] + 0.5 * p[s] + 0.25 * p[after];
        bool apart = true;
        for (std::size_t j = 0; j < n && apart; ++j) apart = j == i || norm(q - path[j][s]) >= 2.0 * margin;
        for (const std::vector<Vec2>& ring : shrunken[s])
          apart = apart && !ring_contains(ring, q) && nearest_on_ring(ring, q).distance >= margin;
        if (apart && container.contains(q) && container.distance_to_boundary(q) >= margin &&
            depth(q, s, radius[i]) <= std::max(0.0, depth(p[s], s, radius[i])))
          smooth[s] = q;
      }
      if (scene.loop) smooth[slices - 1] = smooth[0];
      p = smooth;
    }
  // A size that gives way (params.make_way_dip): where a traveller's footprint comes within a disc of an
  // element's, the element's script is scaled down, by up to 1 / make_way_dip where they touch, so that
  // the slices it would be squeezed at no longer hold the whole loop small (growth_ratio holds every
  // slice's g to its smallest). The dip is smoothed along t, as the paths are.
  const double dip = scene.params.placement.make_way_dip;
  for (std::size_t i = 0; i < n; ++i) {
    unguided[i].offset = path[i];
    if (!(dip > 1.0)) continue;
    std::vector<double> closeness(slices, 0.0);
    for (int s = 0; s < slices; ++s) {
      double near = 0.0;
      for (const std::vector<Vec2>& ring : at_slice[s]) {
        const double d = ring_contains(ring, path[i][s]) ? 0.0 : nearest_on_ring(ring, path[i][s]).distance;
        near = std::max(near, std::clamp((dip_reach * radius[i] - d) / ((dip_reach - 1.0) * radius[i]), 0.0, 1.0));
      }
      closeness[s] = near;
    }
    const int period = scene.loop ? intervals : slices;
    for (int pass = 0; pass < smoothing_passes; ++pass) {
      std::vector<double> smooth = closeness;
      for (int s = 0; s < period; ++s) {
        const int before = s > 0 ? s - 1 : (scene.loop ? period - 1 : 0);
        const int after = s + 1 < period ? s + 1 : (scene.loop ? 0 : s);
        smooth[s] = std::max(closeness[s], 0.25 * closeness[before] + 0.5 * closeness[s] + 0.25 * closeness[after]);
      }
      if (scene.loop) smooth[slices - 1] = smooth[0];
      closeness = smooth;
    }
    for (int s = 0; s < slices; ++s) unguided[i].scale[s] = s0 / (1.0 + (dip - 1.0) * closeness[s]);
  }
}

}  // namespace animpak::scene_detail
