// The §3 pipeline for one library element, in the paper's order: normalize to the unit square, offset
// the outline by Δs, sample and triangulate one slice, bind the art to it, animate every slice (§3.2),
// extrude along time. Every stage is deterministic, and only build_slice draws random numbers.
#include "animpak/animation.hpp"
#include "animpak/error.hpp"

namespace animpak {

SpacetimeElement build_element(const std::string& name, const ArtShape& art, const AnimationSpec& spec,
                               const Params& params, std::uint64_t seed) {
  NormalizedArt normalized = normalize_art(art);
  Outline outline = element_outline(normalized, params.element.offset);
  SliceMesh slice = build_slice(outline, params, seed);
  ArtBinding binding = bind_art(normalized.art, slice);
  std::vector<std::vector<Vec2>> per_slice;
  try {
    per_slice = animate_slices(slice, outline, normalized.frame, spec, params.element.slices);
  } catch (const InputError& e) {
    // The animation's messages name the field; the element and its art file say which scene entry.
    throw InputError("element '" + name + "' (" + art.source.string() + "): " + e.what());
  }
  const SliceAdvice advice =
      slice_advice(slice, outline, normalized.frame, spec, params.element.slices, params.forces.motion_curve);
  SpacetimeElement element = extrude(name, std::move(normalized), std::move(binding), std::move(slice), per_slice);
  element.notes = std::move(outline.notes);
  element.outline_pieces = std::move(outline.pieces);
  element.bridge_radius = outline.bridge_radius;
  element.slices_needed = advice.slices;
  element.motion_error = advice.error;
  return element;
}

}  // namespace animpak
