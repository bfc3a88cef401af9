// The scalar reference solver (paper §5): one stateless function per force, constraint and query,
// written to be read next to the paper. It is the specification the OpenCL kernels are tested against
// bit for bit, so every function does its float arithmetic in one fixed, documented order (no FMA,
// no double intermediates) and every force is GATHERED: a vertex's force is computed from one
// snapshot of all positions and written only to that vertex.
//
// Float constants: every function of the step reads them from the block step_params makes
// (include/animpak/step_params.hpp), each double of Params converted once, the same block the OpenCL host
// hands to the kernels; none converts Params itself. Only the collision grid's cell size and far-field
// switch, which shape the grid rather than enter the step's arithmetic, come from Params.
//
// One header per phase of the step (docs/architecture.md, "One step"), each with the equations it
// implements; this one includes them all, for the backend and the tests that walk every phase. The data both backends hold (the grids, the forces, growth's flags) is in
// include/animpak/solver/.
#pragma once

#include "animpak/reference/boundary.hpp"      // Eq. 4, the wall, containment
#include "animpak/reference/grid.hpp"          // §5.1, the collision grid
#include "animpak/reference/growth.hpp"        // §5.3, growth and the stop test's statistics
#include "animpak/reference/local_forces.hpp"  // Eq. 2 (springs, target, fold guard), Eq. 5, Eq. 6
#include "animpak/reference/overlap.hpp"       // Eq. 3, the curve's tangents, slice boxes, broadphase
#include "animpak/reference/repulsion.hpp"     // Eq. 1
#include "animpak/reference/segments.hpp"      // segment tests of the container and the overlap test
#include "animpak/reference/step.hpp"          // Eq. 7, integration, the constraints of §5.2
