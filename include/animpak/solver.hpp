// The simulation's data (design.md "The solver's data"): a flat structure-of-arrays state that moves,
// and a topology that does not. Both backends (the scalar reference, the OpenCL kernels) read and write
// exactly these arrays. Units: the normalized container, x, y in [0, 1] (y down), t in [0, 1].
// All simulation arithmetic is float, in an order both backends share (equivalence by construction).
#pragma once

#include <cstdint>
#include <vector>

#include "animpak/params.hpp"

namespace animpak {

struct Vec3f {
  float x = 0.0f, y = 0.0f, t = 0.0f;
};

enum VertexFlag : std::uint8_t {
  vertex_boundary = 1,   ///< on its slice's outer boundary (repulsion, overlap, envelope)
  vertex_anchor = 2,     ///< the guided element's anchor (has a target-point spring)
  vertex_first_slice = 4,
  vertex_last_slice = 8,
};

/// The container extruded over t: line segments of the outline and of every hole.
struct ContainerGeometry {
  std::vector<float> ax, ay, bx, by;  ///< segment i runs from (ax[i], ay[i]) to (bx[i], by[i])
  std::vector<std::int32_t> ring_begin;  ///< ring r is segments [ring_begin[r], ring_begin[r+1]); ring 0 the outline
};

/// Everything that does not move during a simulation. Vertex ids are global (all elements).
struct Topology {
  // per vertex
  std::vector<std::int32_t> element;      ///< element id
  std::vector<std::int32_t> slice;        ///< global slice id
  std::vector<std::uint8_t> flags;        ///< VertexFlag bits
  std::vector<float> rest_t;              ///< t of its slice at creation (temporal force, Eq. 6)
  std::vector<float> rest_dir_x, rest_dir_y;  ///< unit rest orientation about the slice centroid (Eq. 5)
  std::vector<std::int32_t> target;       ///< target-point index, or -1

  // springs as CSR: vertex v's springs are [spring_begin[v], spring_begin[v+1]); rest lengths live in
  // SimState::spring_rest because growth changes them
  std::vector<std::int32_t> spring_begin;
  std::vector<std::int32_t> spring_other;
  std::vector<std::uint8_t> spring_class;  ///< SpringClass

  // slice triangles (overlap force, Eq. 3): vertex v's incident triangles are
  // tri_list[tri_begin[v] .. tri_begin[v+1]), indices into tri_a/b/c
  std::vector<std::int32_t> tri_a, tri_b, tri_c;
  std::vector<std::int32_t> tri_begin, tri_list;

  // slices: global slice s holds vertices [slice_begin[s], slice_begin[s+1]); its boundary vertices
  // come first, slice_boundary[s] of them
  std::vector<std::int32_t> slice_begin;
  std::vector<std::int32_t> slice_boundary;
  std::vector<std::int32_t> slice_element;
  // elements: element e holds slices [element_slice_begin[e], element_slice_begin[e+1])
  std::vector<std::int32_t> element_slice_begin;

  // envelope triangles, index triples (design.md), with their element
  std::vector<std::int32_t> env_a, env_b, env_c, env_element;

  // target points of guided elements
  std::vector<float> target_x, target_y, target_t;

  // loop constraint: vertex loop_end[i] (on a t = 1 slice) coincides with loop_start[i] (t = 0 slice)
  std::vector<std::int32_t> loop_end, loop_start;

  ContainerGeometry container;

  std::int32_t vertex_count() const { return static_cast<std::int32_t>(element.size()); }
  std::int32_t slice_count() const { return static_cast<std::int32_t>(slice_boundary.size()); }
  std::int32_t element_count() const { return static_cast<std::int32_t>(element_slice_begin.size()) - 1; }
  std::int32_t envelope_count() const { return static_cast<std::int32_t>(env_a.size()); }
};

/// Everything that moves.
struct SimState {
  std::vector<float> x, y, t;     ///< positions, per vertex
  std::vector<float> vx, vy, vt;  ///< velocities, per vertex
  std::vector<float> spring_rest; ///< rest length per CSR slot (both ends of a spring hold the same value)
  std::vector<float> growth;      ///< g per global slice (§5.3)
  std::uint64_t iteration = 0;
};

}  // namespace animpak
