// The `animation` object of a library element or of the container in the scene file (docs/scene-format.md).
#pragma once

#include "animpak/scene_spec.hpp"
#include "json_fields.hpp"

namespace animpak::io_detail {

/// Reads and checks one animation: preset parameters, transform keys and handle keys (t in [0, 1],
/// strictly increasing; when looping, a key at t = 1 equal to the key at t = 0).
/// `loop` is what the field's own `loop` defaults to; the container's animation, which has none of its own,
/// passes the scene's.
AnimationSpec read_animation(const JsonField& field, bool loop = true);

}  // namespace animpak::io_detail
