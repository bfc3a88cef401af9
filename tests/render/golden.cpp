#include "golden.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>

Image read_rgba(const std::filesystem::path& file) {
  Image img;
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return img;
  const OIIO::ImageSpec& spec = in->spec();
  // Opaque pictures may come without alpha (rsvg-convert writes RGB then): alpha is 255.
  if (spec.nchannels != 4 && spec.nchannels != 3) return img;
  const int channels = spec.nchannels;
  img.width = spec.width;
  img.height = spec.height;
  const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
  std::vector<unsigned char> read(pixels * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, read.data())) return img;
  in->close();
  img.rgba.assign(pixels * 4, 255);
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < channels; ++c) img.rgba[i * 4 + c] = read[i * channels + c];
  return img;
}

double alpha_iou(const Image& a, const Image& b) {
  std::size_t both = 0, either = 0;
  for (std::size_t i = 3; i < a.rgba.size() && i < b.rgba.size(); i += 4) {
    const bool x = a.rgba[i] >= 128, y = b.rgba[i] >= 128;
    both += (x && y) || ((x || y) && std::abs(a.rgba[i] - b.rgba[i]) <= kEdgeNoise);
    either += x || y;
  }
  return either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
}

namespace {

void write_rgba(const std::filesystem::path& file, int width, int height, const std::vector<unsigned char>& rgba) {
  auto out = OIIO::ImageOutput::create(file.string());
  const OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
  if (out && out->open(file.string(), spec)) {
    out->write_image(OIIO::TypeDesc::UINT8, rgba.data());
    out->close();
  }
}

}  // namespace

bool golden_update_requested() {
  const char* v = std::getenv("ANIMPAK_UPDATE_GOLDEN");
  return v && std::string(v) == "1";
}

GoldenResult compare_golden(const animpak::Picture& actual, const std::string& case_name, const std::string& image,
                            const GoldenThresholds& thresholds) {
  const auto ref_file =
      std::filesystem::path(ANIMPAK_SOURCE_DIR) / "tests" / "golden" / case_name / "ref" / (image + ".png");
  GoldenResult result;
  if (golden_update_requested()) {
    std::filesystem::create_directories(ref_file.parent_path());
    actual.write(ref_file);
    result.pass = result.updated = true;
    result.report = "updated " + ref_file.string();
    return result;
  }
  const Image expected = read_rgba(ref_file);
  const std::vector<unsigned char> got = actual.rgba8();
  std::ostringstream report;
  report << case_name << "/" << image << ": ";
  if (expected.rgba.empty() || expected.width != actual.width() || expected.height != actual.height()) {
    report << "reference " << ref_file.string() << " is missing, unreadable or not " << actual.width() << "x"
           << actual.height() << "; run with ANIMPAK_UPDATE_GOLDEN=1 to create it";
    result.report = report.str();
    return result;
  }

  // Differing pixels in red on a faded copy of the actual picture, like resvg's diff panel.
  std::vector<unsigned char> diff(got.size());
  std::size_t differing = 0;
  int worst = 0, worst_x = 0, worst_y = 0;
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * expected.width + x) * 4;
      int off = 0;
      for (int c = 0; c < 4; ++c) off = std::max(off, std::abs(int(got[i + c]) - int(expected.rgba[i + c])));
      if (off > worst) worst = off, worst_x = x, worst_y = y;
      const bool differs = off > thresholds.pixel;
      differing += differs;
      for (int c = 0; c < 3; ++c)
        diff[i + c] = differs ? (c == 0 ? 255 : 0) : static_cast<unsigned char>(191 + got[i + c] / 4);
      diff[i + 3] = 255;
    }
  const double share = double(differing) / (double(expected.width) * expected.height);
  result.pass = share <= thresholds.max_share && worst <= thresholds.hard;
  report << differing << " pixels differ by more than " << thresholds.pixel << " (" << 100.0 * share << " %, allowed "
         << 100.0 * thresholds.max_share << " %); max difference " << worst << " at (" << worst_x << ", " << worst_y
         << "), allowed " << thresholds.hard << ": " << (result.pass ? "PASS" : "FAILURE");
  if (!result.pass) {
    const auto dir = std::filesystem::absolute("golden-failures") / case_name;
    std::filesystem::create_directories(dir);
    write_rgba(dir / (image + "-expected.png"), expected.width, expected.height, expected.rgba);
    actual.write(dir / (image + "-actual.png"));
    write_rgba(dir / (image + "-diff.png"), expected.width, expected.height, diff);
    report << "\n  expected " << (dir / (image + "-expected.png")).string() << "\n  actual   "
           << (dir / (image + "-actual.png")).string() << "\n  diff     " << (dir / (image + "-diff.png")).string();
  }
  result.report = report.str();
  return result;
}
