// crosses_itself (animpak/element.hpp), which `animpak check` warns with: a figure eight crosses, a square and
// a star drawn round its outline do not, neighbouring segments never count, and an open path's implied
// closing segment is not one of its segments.
#include <catch2/catch.hpp>

#include "animpak/element.hpp"

TEST_CASE("crosses_itself: a bow tie crosses, a square does not, an open path has no closing segment") {
  using animpak::crosses_itself;
  using animpak::Polyline;
  CHECK_FALSE(crosses_itself(Polyline{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, true}));
  CHECK(crosses_itself(Polyline{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}, true}));
  // The same points open: the segments (0,0)-(1,1) and (1,0)-(0,1) still cross.
  CHECK(crosses_itself(Polyline{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}, false}));
  // A U open at the top: closed, its closing segment would meet nothing but its neighbours either.
  CHECK_FALSE(crosses_itself(Polyline{{{0, 1}, {0, 0}, {1, 0}, {1, 1}}, false}));
  // A zigzag whose last segment comes back across its first, open.
  CHECK(crosses_itself(Polyline{{{0, 0}, {2, 0}, {2, 1}, {1, -1}}, false}));
  CHECK_FALSE(crosses_itself(Polyline{{{0, 0}, {1, 0}, {1, 1}}, true}));  // fewer than four points
}
