#include <catch2/catch.hpp>

#include "golden.hpp"
#include "tiny_world.hpp"

using namespace animpak;

// Drawing regressions show here first: art replay, stroke scaling, container outline, anti-aliasing.
TEST_CASE("draw_frame: the tiny star world at t = 0 and 0.5 matches its reference pictures") {
  const World world = tiny_star_world();
  FrameStyle style;
  style.size = 128;
  for (const auto& [t, image] : {std::pair{0.0, "t0.00"}, std::pair{0.5, "t0.50"}}) {
    const GoldenResult r = compare_golden(draw_frame(world, world.state, t, style), "tiny-stars", image);
    if (r.updated) WARN(r.report);
    INFO(r.report);
    CHECK(r.pass);
  }
}

TEST_CASE("compare_golden: a picture unlike its reference fails and writes expected, actual and diff") {
  const World world = tiny_star_world();
  FrameStyle style;
  style.size = 128;
  style.background = {0.1, 0.1, 0.1, 1};  // a dark background differs everywhere from the reference
  if (golden_update_requested()) return;  // this picture must never become the reference
  const GoldenResult r = compare_golden(draw_frame(world, world.state, 0.0, style), "tiny-stars", "t0.00");
  INFO(r.report);
  CHECK_FALSE(r.pass);
  CHECK(r.report.find("FAILURE") != std::string::npos);
  CHECK(std::filesystem::exists(std::filesystem::absolute("golden-failures") / "tiny-stars" / "t0.00-diff.png"));
}
