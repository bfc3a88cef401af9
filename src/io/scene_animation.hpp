// The `animation` object of a library element in the scene file (docs/scene-format.md).
#pragma once

#include "animpak/scene_spec.hpp"
#include "json_fields.hpp"

namespace animpak::io_detail {

/// Reads and checks one animation: preset parameters, transform keys and handle keys (t in [0, 1],
/// strictly increasing; when looping, a key at t = 1 equal to the key at t = 0).
AnimationSpec read_animation(const JsonField& field);

}  // namespace animpak::io_detail
