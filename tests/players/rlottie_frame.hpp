// Frames of a Lottie file as rlottie (Telegram's and Samsung's player, Debian's librlottie) draws them: the
// player the Lottie export is held to in tests/render/test_animation_formats.cpp. Test-only.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

struct PlayerFrame {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;  ///< straight 8-bit RGBA, row-major, top row first
  std::string error;                ///< why there is no picture (rlottie refused the file)
};

/// Frame `frame` of the Lottie file at its own size (the document's w and h), on a transparent background.
PlayerFrame rlottie_frame(const std::filesystem::path& file, std::size_t frame);

/// The number of frames rlottie reads from the file (op − ip), 0 when it refuses it.
std::size_t rlottie_frame_count(const std::filesystem::path& file);
