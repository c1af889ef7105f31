#include "NlosPictures.h"

#include <algorithm>

#include "tofsim/imaging/Pictures.h"

namespace tofsim::pipeline {

std::size_t nlosPictureBinsPerRow(std::size_t bins) {
  return (bins + kNlosPictureRows - 1) / kNlosPictureRows;
}

std::vector<Image> nlosProjections(const NlosVolume& volume) {
  const std::vector<std::size_t>& s = volume.shape;
  const std::size_t bins = s.front(), sx = s[s.size() - 2], sy = s.back();
  const std::size_t points = volume.H.size() / bins;  // laser points x sx x sy
  const std::size_t group = nlosPictureBinsPerRow(bins);
  const std::size_t T = (bins + group - 1) / group;  // the pictures' rows
  Image steady(static_cast<int32_t>(sx), static_cast<int32_t>(sy), 1);
  Image xt(static_cast<int32_t>(sx), static_cast<int32_t>(T), 1);
  Image yt(static_cast<int32_t>(sy), static_cast<int32_t>(T), 1);
  // Sums in double: a 64 x 64 wall's 4096 points per bin.
  std::vector<double> wall(sx * sy, 0.0), x(T * sx, 0.0), y(T * sy, 0.0);
  for (std::size_t b = 0; b < bins; ++b) {
    const std::size_t t = b / group;
    for (std::size_t p = 0; p < points; ++p) {
      const double v = volume.H[b * points + p];
      const std::size_t ix = (p / sy) % sx, iy = p % sy;
      wall[ix * sy + iy] += v;
      x[t * sx + ix] += v;
      y[t * sy + iy] += v;
    }
  }
  for (std::size_t ix = 0; ix < sx; ++ix) {
    for (std::size_t iy = 0; iy < sy; ++iy) {
      steady.at(static_cast<int32_t>(sy - 1 - iy), static_cast<int32_t>(ix), 0) =
          static_cast<float>(wall[ix * sy + iy]);
    }
  }
  for (std::size_t i = 0; i < x.size(); ++i) xt.data[i] = static_cast<float>(x[i]);
  for (std::size_t i = 0; i < y.size(); ++i) yt.data[i] = static_cast<float>(y[i]);
  return {steady, xt, yt};
}

namespace {

// A projection over time is a few dozen points wide and hundreds of bins
// tall: its columns repeated until it is about half as wide as tall, so the
// wall's axis reads (whole columns, no smoothing).
Image widened(const Image& image) {
  const int32_t factor = std::max(1, image.height / (2 * std::max(1, image.width)));
  Image wide(image.width * factor, image.height, 1);
  for (int32_t y = 0; y < image.height; ++y) {
    for (int32_t x = 0; x < wide.width; ++x) wide.at(y, x, 0) = image.at(y, x / factor, 0);
  }
  return wide;
}

}  // namespace

std::vector<std::string> writeNlosPictures(const std::filesystem::path& directory,
                                           const NlosVolume& volume) {
  const std::vector<Image> p = nlosProjections(volume);
  imaging::ColorScale wall;
  wall.colormap = "inferno";
  imaging::writeColormappedPng(directory / "H_steady.png", p[0],
                               "H summed over time, wall x right, y up [W m^-2 sr^-1]", wall);
  imaging::ColorScale overTime = wall;
  const double rowStep_m =
      volume.axis.bin_width_m() * static_cast<double>(nlosPictureBinsPerRow(volume.shape.front()));
  overTime.rows = imaging::RowAxis{volume.axis.start_m(), rowStep_m, "optical path [m]"};
  imaging::writeColormappedPng(directory / "H_xt.png", widened(p[1]),
                               "H summed over the wall's y: x right [W m^-2 sr^-1]", overTime);
  imaging::writeColormappedPng(directory / "H_yt.png", widened(p[2]),
                               "H summed over the wall's x: y right [W m^-2 sr^-1]", overTime);
  return {"H_steady.png", "H_xt.png", "H_yt.png"};
}

}  // namespace tofsim::pipeline
