#include <cairo.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/render.hpp"

namespace animpak {

struct Picture::Impl {
  cairo_surface_t* surface = nullptr;
  cairo_t* cr = nullptr;
  double scale = 1.0;
  Vec2 offset;  // pixel = world * scale + offset

  ~Impl() {
    if (cr) cairo_destroy(cr);
    if (surface) cairo_surface_destroy(surface);
  }
};

Picture::Picture(int width, int height, Box world, Rgba background, double margin_px)
    : impl_(std::make_unique<Impl>()) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw InputError("picture size " + std::to_string(width) + "x" + std::to_string(height) +
                     " is out of range; use 1 to 16384 pixels per side");
  impl_->surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  if (cairo_surface_status(impl_->surface) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("cairo: cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                             " surface");
  impl_->cr = cairo_create(impl_->surface);
  cairo_set_antialias(impl_->cr, CAIRO_ANTIALIAS_BEST);
  cairo_set_source_rgba(impl_->cr, background.r, background.g, background.b, background.a);
  cairo_paint(impl_->cr);

  const PixelFit fit = fit_to_picture(width, height, world, margin_px);
  impl_->scale = fit.scale;
  impl_->offset = fit.offset;
}

PixelFit fit_to_picture(int width, int height, Box world, double margin_px) {
  if (world.empty()) world.add({0, 0}), world.add({1, 1});
  const double w = std::max(world.width(), 1e-12), h = std::max(world.height(), 1e-12);
  const double usable_w = std::max(1.0, width - 2 * margin_px), usable_h = std::max(1.0, height - 2 * margin_px);
  PixelFit fit;
  fit.scale = std::min(usable_w / w, usable_h / h);
  fit.offset = {0.5 * (width - fit.scale * (world.min.x + world.max.x)),
                0.5 * (height - fit.scale * (world.min.y + world.max.y))};
  return fit;
}

Picture::~Picture() = default;
Picture::Picture(Picture&&) noexcept = default;
Picture& Picture::operator=(Picture&&) noexcept = default;

int Picture::width() const { return cairo_image_surface_get_width(impl_->surface); }
int Picture::height() const { return cairo_image_surface_get_height(impl_->surface); }
Vec2 Picture::to_pixel(Vec2 p) const { return p * impl_->scale + impl_->offset; }

namespace {

void set_colour(cairo_t* cr, Rgba c, double opacity) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a * opacity); }

}  // namespace

void Picture::draw_art(const ArtShape& art, const ArtPoints& points, double opacity, double stroke_scale,
                       double min_stroke_px) {
  cairo_t* cr = impl_->cr;
  for (std::size_t p = 0; p < art.paths.size() && p < points.size(); ++p) {
    const ArtPath& path = art.paths[p];
    cairo_new_path(cr);
    for (std::size_t q = 0; q < path.polylines.size() && q < points[p].size(); ++q) {
      const auto& pts = points[p][q];
      if (pts.empty()) continue;
      const Vec2 first = to_pixel(pts[0]);
      cairo_move_to(cr, first.x, first.y);
      for (std::size_t k = 1; k < pts.size(); ++k) {
        const Vec2 px = to_pixel(pts[k]);
        cairo_line_to(cr, px.x, px.y);
      }
      if (path.polylines[q].closed) cairo_close_path(cr);
    }
    cairo_set_fill_rule(cr, path.fill_rule == FillRule::evenodd ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    auto fill = [&] {
      if (!path.fill.enabled) return;
      set_colour(cr, path.fill.color, opacity);
      cairo_fill_preserve(cr);
    };
    auto stroke = [&] {
      if (!path.stroke.enabled || path.stroke_width <= 0) return;
      set_colour(cr, path.stroke.color, opacity);
      cairo_set_line_width(cr, std::max(min_stroke_px, path.stroke_width * stroke_scale * impl_->scale));
      cairo_stroke_preserve(cr);
    };
    if (path.paint_order == PaintOrder::fill_then_stroke)
      fill(), stroke();
    else
      stroke(), fill();
    cairo_new_path(cr);
  }
}

void Picture::draw_edges(const std::vector<Vec2>& positions, const std::vector<Edge>& edges, Rgba color,
                         double width_px, bool dashed) {
  cairo_t* cr = impl_->cr;
  const double dash[] = {3.0 * width_px, 2.5 * width_px};
  cairo_set_dash(cr, dash, dashed ? 2 : 0, 0.0);
  cairo_set_line_width(cr, width_px);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  set_colour(cr, color, 1.0);
  for (const Edge& e : edges) {
    const Vec2 a = to_pixel(positions.at(e[0])), b = to_pixel(positions.at(e[1]));
    cairo_move_to(cr, a.x, a.y);
    cairo_line_to(cr, b.x, b.y);
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

void Picture::draw_ring(const std::vector<Vec2>& ring, Rgba color, double width_px) {
  if (ring.empty()) return;
  cairo_t* cr = impl_->cr;
  cairo_new_path(cr);
  for (const Vec2& p : ring) {
    const Vec2 px = to_pixel(p);
    cairo_line_to(cr, px.x, px.y);
  }
  cairo_close_path(cr);
  cairo_set_line_width(cr, width_px);
  set_colour(cr, color, 1.0);
  cairo_stroke(cr);
}

void Picture::draw_dots(const std::vector<Vec2>& positions, Rgba color, double radius_px) {
  cairo_t* cr = impl_->cr;
  set_colour(cr, color, 1.0);
  for (const Vec2& p : positions) {
    const Vec2 px = to_pixel(p);
    cairo_new_sub_path(cr);
    cairo_arc(cr, px.x, px.y, radius_px, 0.0, 2.0 * M_PI);
  }
  cairo_fill(cr);
}

void Picture::draw_polyline(const std::vector<Vec2>& points, Rgba color, double width_px) {
  if (points.size() < 2) return;
  cairo_t* cr = impl_->cr;
  cairo_new_path(cr);
  for (const Vec2& p : points) {
    const Vec2 px = to_pixel(p);
    cairo_line_to(cr, px.x, px.y);
  }
  cairo_set_line_width(cr, width_px);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  set_colour(cr, color, 1.0);
  cairo_stroke(cr);
}

void Picture::draw_text(Vec2 anchor, const std::string& text, double size_px, Rgba color, Vec2 align) {
  cairo_t* cr = impl_->cr;
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size_px);
  cairo_text_extents_t box;
  cairo_text_extents(cr, text.c_str(), &box);
  const Vec2 px = to_pixel(anchor);
  // Extents are relative to the baseline origin; shift so that `align` of the ink box sits on px.
  cairo_move_to(cr, px.x - box.x_bearing - align.x * box.width, px.y - box.y_bearing - align.y * box.height);
  set_colour(cr, color, 1.0);
  cairo_show_text(cr, text.c_str());
  cairo_new_path(cr);
}

std::vector<unsigned char> Picture::rgba8() const {
  cairo_surface_flush(impl_->surface);
  const int w = width(), h = height(), stride = cairo_image_surface_get_stride(impl_->surface);
  const unsigned char* data = cairo_image_surface_get_data(impl_->surface);
  std::vector<unsigned char> out(static_cast<std::size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < w; ++x) {
      // Cairo stores premultiplied ARGB in native-endian 32-bit words; PNG wants straight RGBA.
      const std::uint32_t px = row[x];
      const unsigned a = px >> 24;
      unsigned char* o = &out[(static_cast<std::size_t>(y) * w + x) * 4];
      for (int c = 0; c < 3; ++c) {
        const unsigned premul = (px >> (16 - 8 * c)) & 0xffu;
        o[c] = static_cast<unsigned char>(a == 0 ? 0 : std::min(255u, (premul * 255u + a / 2) / a));
      }
      o[3] = static_cast<unsigned char>(a);
    }
  }
  return out;
}

void Picture::write(const std::filesystem::path& file) const {
  const std::vector<unsigned char> pixels = rgba8();
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out) throw InputError(file.string() + ": cannot write this image format (" + OIIO::geterror() + "); use .png");
  const OIIO::ImageSpec spec(width(), height(), 4, OIIO::TypeDesc::UINT8);
  // Encoded in memory and written by write_file_atomically: OpenImageIO's PNG writer does not report a
  // write that fails on a full disk, and left cut-off frames that looked written.
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  if (!out->supports("ioproxy") || !out->set_ioproxy(&memory))
    throw InputError(file.string() + ": cannot encode this image format in memory; use .png");
  if (!out->open(file.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !out->close())
    throw InputError(file.string() + ": cannot encode the image (" + out->geterror() + ")");
  write_file_atomically(file, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

}  // namespace animpak
