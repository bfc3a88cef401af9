#include <catch2/catch.hpp>

#include "animpak/render.hpp"

// LeakSanitizer reads this hook when it is linked in (sanitizer builds) and ignores it otherwise:
// fontconfig, loaded once by Cairo's toy text API, keeps its configuration for the process lifetime.
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }

using namespace animpak;

namespace {

// Picture whose world is its own pixel grid, so positions below are pixels.
Picture pixel_picture(int w, int h) {
  Box b;
  b.add({0, 0});
  b.add({double(w), double(h)});
  return Picture(w, h, b, {1, 1, 1, 1}, 0.0);
}

int green(const std::vector<unsigned char>& rgba, int width, int x, int y) {
  return rgba[(static_cast<std::size_t>(y) * width + x) * 4 + 1];
}

}  // namespace

TEST_CASE("Picture::draw_polyline: an open line paints its segments and does not close") {
  Picture pic = pixel_picture(60, 60);
  pic.draw_polyline({{10, 10}, {50, 10}, {50, 50}}, {0, 0, 0, 1}, 3.0);
  const auto rgba = pic.rgba8();
  CHECK(green(rgba, 60, 30, 10) < 64);
  CHECK(green(rgba, 60, 50, 30) < 64);
  CHECK(green(rgba, 60, 30, 30) == 255);  // the closing diagonal (50,50)→(10,10) is not drawn
}

TEST_CASE("Picture::draw_text: ink lands on the side of the anchor that the alignment asks for") {
  Picture left = pixel_picture(200, 40), right = pixel_picture(200, 40);
  left.draw_text({100, 20}, "Wide text", 16, {0, 0, 0, 1}, {0.0, 0.5});
  right.draw_text({100, 20}, "Wide text", 16, {0, 0, 0, 1}, {1.0, 0.5});
  auto ink = [](const Picture& p, int x0, int x1) {
    const auto rgba = p.rgba8();
    int n = 0;
    for (int y = 0; y < p.height(); ++y)
      for (int x = x0; x < x1; ++x) n += green(rgba, p.width(), x, y) < 128;
    return n;
  };
  CHECK(ink(left, 100, 200) > 20);
  CHECK(ink(left, 0, 98) == 0);
  CHECK(ink(right, 0, 100) > 20);
  CHECK(ink(right, 102, 200) == 0);
}
