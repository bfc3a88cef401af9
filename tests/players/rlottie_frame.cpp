#include "rlottie_frame.hpp"

#include <rlottie.h>

#include <algorithm>
#include <cstdint>
#include <memory>

PlayerFrame rlottie_frame(const std::filesystem::path& file, std::size_t frame) {
  PlayerFrame out;
  // No cache: a test rewrites files under the same name.
  const std::unique_ptr<rlottie::Animation> animation = rlottie::Animation::loadFromFile(file.string(), false);
  if (!animation) {
    out.error = file.string() + ": rlottie cannot read it";
    return out;
  }
  std::size_t width = 0, height = 0;
  animation->size(width, height);
  std::vector<std::uint32_t> pixels(width * height, 0u);
  animation->renderSync(frame, rlottie::Surface(pixels.data(), width, height, width * 4));
  out.width = static_cast<int>(width);
  out.height = static_cast<int>(height);
  out.rgba.resize(width * height * 4);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    // Premultiplied ARGB32 in native-endian words, as Cairo's.
    const std::uint32_t px = pixels[i];
    const unsigned a = px >> 24;
    for (int c = 0; c < 3; ++c) {
      const unsigned premul = (px >> (16 - 8 * c)) & 0xffu;
      out.rgba[4 * i + c] = static_cast<unsigned char>(a == 0 ? 0 : std::min(255u, (premul * 255u + a / 2) / a));
    }
    out.rgba[4 * i + 3] = static_cast<unsigned char>(a);
  }
  return out;
}

std::size_t rlottie_frame_count(const std::filesystem::path& file) {
  const std::unique_ptr<rlottie::Animation> animation = rlottie::Animation::loadFromFile(file.string(), false);
  return animation ? animation->totalFrame() : 0;
}
