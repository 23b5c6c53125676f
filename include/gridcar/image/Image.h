#pragma once
/// @file Image.h
/// @brief 8-bit raster images: decoding (PNG via stb_image, PNM P2/P3/P5/P6) and PNG writing.

#include "gridcar/core/Errors.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace gridcar
{
/// Interleaved 8-bit image, row 0 at the top. channels: 1 gray, 2 gray+alpha, 3 RGB, 4 RGBA.
struct Image
{
    int width{0};
    int height{0};
    int channels{0};
    std::vector<std::uint8_t> data;

    std::uint8_t *px(int x, int y) { return data.data() + (std::size_t(y) * width + x) * channels; }
    const std::uint8_t *px(int x, int y) const { return data.data() + (std::size_t(y) * width + x) * channels; }
};

/// Reads a PNG (gray, gray+alpha, RGB, RGBA; decoded by stb_image) or a Netpbm image
/// (P2/P5 gray, P3/P6 colour; 16-bit samples scaled to 8 bit). The format is detected from
/// the file's first bytes. Throws MapLoadError naming the file and the reason.
Image readImage(const std::string &path);

/// Writes an image as PNG (stb_image_write). Throws std::runtime_error on failure.
void writePng(const std::string &path, const Image &img);

/// Writes a gray image as binary PGM (P5). Throws std::runtime_error on failure.
void writePgm(const std::string &path, const Image &img);

}  // namespace gridcar
