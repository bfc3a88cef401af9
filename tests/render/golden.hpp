// Golden-image comparison in the manner of OpenImageIO's idiff: layered thresholds (a per-channel
// difference that makes a pixel "differing", a share of differing pixels that is still a pass, and a
// hard cap no pixel may exceed), a report that names the worst pixel, and on failure the expected,
// actual and diff pictures written beside the test binary. ANIMPAK_UPDATE_GOLDEN=1 rewrites the
// references instead of comparing.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "animpak/render.hpp"

struct GoldenThresholds {
  int pixel = 16;            ///< a channel off by more than this (0–255) makes its pixel differ
  double max_share = 0.005;  ///< share of differing pixels still accepted
  int hard = 230;            ///< no channel of any pixel may be off by more than this
};

struct GoldenResult {
  bool pass = false;
  bool updated = false;  ///< the reference was (re)written
  std::string report;    ///< one paragraph: counts, worst pixel, files written on failure
};

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
};

/// Two rasterisers place an edge a little apart (each flattens curves its own way, cairo to 0.1 px by
/// default, and antialiases on its own grid), so a pixel on a thin line's edge may be 0.55 opaque in one
/// picture and 0.45 in the other. Such a pixel says nothing about the drawing: alpha_iou counts it against
/// the match only when its two alphas are also more than this (0.1 of opaque) apart.
inline constexpr int kEdgeNoise = 26;

/// Intersection over union of two same-size pictures' alpha masks: alpha ≥ 0.5 in both (or in one, the
/// other within kEdgeNoise of it), over alpha ≥ 0.5 in either; 1 when both are empty.
double alpha_iou(const Image& a, const Image& b);

/// Reads a PNG (RGBA or RGB) as 8-bit RGBA; an empty image when the file is missing or unreadable.
Image read_rgba(const std::filesystem::path& file);

/// ANIMPAK_UPDATE_GOLDEN=1 is set: references are written, not compared.
bool golden_update_requested();

/// Compares `actual` with tests/golden/<case_name>/ref/<image>.png.
GoldenResult compare_golden(const animpak::Picture& actual, const std::string& case_name, const std::string& image,
                            const GoldenThresholds& thresholds = {});
