#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "animpak/error.hpp"
#include "animpak/render.hpp"
#include "temp_dir.hpp"

using namespace animpak;

namespace {

ArtShape square_art(Paint fill, Paint stroke, double stroke_width, PaintOrder order) {
  ArtPath path;
  path.id = "square";
  path.polylines.push_back({{{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}}, true});
  path.fill = fill;
  path.stroke = stroke;
  path.stroke_width = stroke_width;
  path.paint_order = order;
  ArtShape art;
  art.paths.push_back(path);
  return art;
}

std::array<int, 4> pixel(const std::vector<unsigned char>& rgba, int width, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

Box unit_box() {
  Box b;
  b.add({0, 0});
  b.add({1, 1});
  return b;
}

}  // namespace

TEST_CASE("Picture: a filled square covers its pixels and leaves the background elsewhere") {
  const ArtShape art = square_art({true, {1, 0, 0, 1}}, {}, 0, PaintOrder::fill_then_stroke);
  Picture pic(100, 100, unit_box(), {1, 1, 1, 1}, 0.0);
  pic.draw_art(art, own_points(art));
  const auto rgba = pic.rgba8();
  CHECK(pixel(rgba, 100, 50, 50) == std::array<int, 4>{255, 0, 0, 255});
  CHECK(pixel(rgba, 100, 5, 5) == std::array<int, 4>{255, 255, 255, 255});
  CHECK(pixel(rgba, 100, 95, 50) == std::array<int, 4>{255, 255, 255, 255});
  // The square spans pixels 25..75: the edge pixel just inside is filled, the one outside is not.
  CHECK(pixel(rgba, 100, 26, 50)[1] == 0);
  CHECK(pixel(rgba, 100, 23, 50)[1] == 255);
}

TEST_CASE("Picture: translucent paint on a transparent background comes out as straight alpha") {
  const ArtShape art = square_art({true, {1, 0, 0, 0.5}}, {}, 0, PaintOrder::fill_then_stroke);
  Picture pic(40, 40, unit_box(), {0, 0, 0, 0}, 0.0);
  pic.draw_art(art, own_points(art));
  const auto p = pixel(pic.rgba8(), 40, 20, 20);
  CHECK(p[0] == 255);  // premultiplied storage would give about 128 here
  CHECK(p[1] == 0);
  CHECK(std::abs(p[3] - 128) <= 1);
}

TEST_CASE("Picture: paint order decides whether the stroke's inner half shows") {
  const Paint fill{true, {0, 0, 1, 1}}, stroke{true, {0, 0, 0, 1}};
  // A stroke of width 0.1 straddles the edge at x = 0.25: pixels 25..29 are its inner half.
  auto inner_band = [&](PaintOrder order) {
    const ArtShape art = square_art(fill, stroke, 0.1, order);
    Picture pic(100, 100, unit_box(), {1, 1, 1, 1}, 0.0);
    pic.draw_art(art, own_points(art));
    return pixel(pic.rgba8(), 100, 27, 50);
  };
  CHECK(inner_band(PaintOrder::fill_then_stroke) == std::array<int, 4>{0, 0, 0, 255});
  CHECK(inner_band(PaintOrder::stroke_then_fill) == std::array<int, 4>{0, 0, 255, 255});
}

TEST_CASE("Picture: write produces a PNG that reads back pixel for pixel") {
  const ArtShape art = square_art({true, {0.2, 0.6, 0.4, 1}}, {true, {0, 0, 0, 1}}, 0.02, PaintOrder::fill_then_stroke);
  Picture pic(64, 48, unit_box());
  pic.draw_art(art, own_points(art));
  const test::TempDir temp("animpak-picture-");
  const auto file = temp / "picture.png";
  pic.write(file);
  auto in = OIIO::ImageInput::open(file.string());
  REQUIRE(in);
  const OIIO::ImageSpec& spec = in->spec();
  REQUIRE(spec.width == 64);
  REQUIRE(spec.height == 48);
  REQUIRE(spec.nchannels == 4);
  std::vector<unsigned char> back(64 * 48 * 4);
  REQUIRE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, back.data()));
  in->close();
  CHECK(back == pic.rgba8());
}

TEST_CASE("Picture: bad sizes and unwritable files are input errors naming the problem") {
  CHECK_THROWS_AS(Picture(0, 10, unit_box()), InputError);
  CHECK_THROWS_WITH(Picture(20000, 10, unit_box()), Catch::Contains("out of range"));
  Picture pic(8, 8, unit_box());
  CHECK_THROWS_WITH(pic.write("/nonexistent-folder/x.png"), Catch::Contains("/nonexistent-folder/x.png"));
  const test::TempDir temp("animpak-picture-");
  CHECK_THROWS_WITH(pic.write(temp / "x.unknownformat"), Catch::Contains("cannot write this image format"));
}

TEST_CASE("Picture: the world box is fitted with its aspect ratio kept and centred") {
  Box wide;
  wide.add({0, 0});
  wide.add({2, 1});
  Picture pic(100, 100, wide, {1, 1, 1, 1}, 0.0);
  CHECK(pic.to_pixel({0, 0}).x == Approx(0));
  CHECK(pic.to_pixel({2, 1}).x == Approx(100));
  CHECK(pic.to_pixel({0, 0}).y == Approx(25));
  CHECK(pic.to_pixel({2, 1}).y == Approx(75));
}
