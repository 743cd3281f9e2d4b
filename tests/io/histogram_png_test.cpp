// The PNG histogram (core/io/histogram_png.h): a valid PNG of the SVG's size, with the series'
// colours and text drawn in it; a missing or failing rasterizer is an OutputError that names the
// file and leaves no file behind. Through the CLI too (stats --histogram H.png).
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/histogram_png.h"
#include "core/io/histogram_svg.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint32_t be32(const std::string& s, std::size_t at) {
  return (std::uint32_t(std::uint8_t(s[at])) << 24) |
         (std::uint32_t(std::uint8_t(s[at + 1])) << 16) |
         (std::uint32_t(std::uint8_t(s[at + 2])) << 8) | std::uint32_t(std::uint8_t(s[at + 3]));
}

// A decoded 8-bit RGB or RGBA, non-interlaced PNG (what rsvg-convert writes): pixels as 0xRRGGBB.
struct Png {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint32_t> rgb;
};

Png decode_png(const std::string& path) {
  const std::string s = slurp(path);
  Png p;
  if (s.size() < 33 || s.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) {
    ADD_FAILURE() << path << " has no PNG signature";
    return p;
  }
  if (s.compare(12, 4, "IHDR") != 0) {
    ADD_FAILURE() << path << ": the first chunk is not IHDR";
    return p;
  }
  p.width = be32(s, 16);
  p.height = be32(s, 20);
  const int depth = std::uint8_t(s[24]), colour = std::uint8_t(s[25]),
            interlace = std::uint8_t(s[28]);
  EXPECT_EQ(depth, 8);
  EXPECT_TRUE(colour == 2 || colour == 6) << "colour type " << colour;
  EXPECT_EQ(interlace, 0);
  const int bpp = colour == 6 ? 4 : 3;
  std::string idat;
  bool iend = false;
  for (std::size_t at = 8; at + 12 <= s.size();) {
    const std::uint32_t len = be32(s, at);
    const std::string type = s.substr(at + 4, 4);
    if (at + 12 + len > s.size()) break;
    if (type == "IDAT") idat += s.substr(at + 8, len);
    if (type == "IEND") iend = true;
    at += 12 + len;
  }
  EXPECT_TRUE(iend) << path << " is truncated (no IEND)";
  const std::size_t stride = std::size_t(p.width) * bpp;
  std::vector<unsigned char> raw((stride + 1) * p.height);
  uLongf n = raw.size();
  if (uncompress(raw.data(), &n, reinterpret_cast<const Bytef*>(idat.data()), idat.size()) !=
          Z_OK ||
      n != raw.size()) {
    ADD_FAILURE() << path << ": the image data does not inflate to " << raw.size() << " bytes";
    return p;
  }
  std::vector<unsigned char> img(stride * p.height), prev(stride, 0);
  for (std::uint32_t y = 0; y < p.height; ++y) {
    const unsigned char f = raw[y * (stride + 1)];
    const unsigned char* in = &raw[y * (stride + 1) + 1];
    unsigned char* out = &img[y * stride];
    for (std::size_t i = 0; i < stride; ++i) {
      const int a = i >= std::size_t(bpp) ? out[i - bpp] : 0, b = prev[i],
                c = i >= std::size_t(bpp) ? prev[i - bpp] : 0;
      int pred = 0;
      if (f == 1) pred = a;
      if (f == 2) pred = b;
      if (f == 3) pred = (a + b) / 2;
      if (f == 4) {
        const int pp = a + b - c, pa = std::abs(pp - a), pb = std::abs(pp - b),
                  pc = std::abs(pp - c);
        pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      }
      out[i] = static_cast<unsigned char>(in[i] + pred);
    }
    std::copy(out, out + stride, prev.begin());
  }
  for (std::size_t k = 0; k < std::size_t(p.width) * p.height; ++k)
    p.rgb.push_back((std::uint32_t(img[k * bpp]) << 16) | (std::uint32_t(img[k * bpp + 1]) << 8) |
                    img[k * bpp + 2]);
  return p;
}

class HistogramPng : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cvtmesh-histpng-" + std::to_string(getpid()));
    fs::create_directories(dir_);
    if (const char* e = std::getenv("CVTMESH_RSVG_CONVERT")) saved_ = e;
  }
  void TearDown() override {
    if (saved_)
      setenv("CVTMESH_RSVG_CONVERT", saved_->c_str(), 1);
    else
      unsetenv("CVTMESH_RSVG_CONVERT");
    fs::remove_all(dir_);
  }
  std::size_t files_in_dir() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {}));
  }
  fs::path dir_;
  std::optional<std::string> saved_;
};

std::vector<QualityHistogram> two_series() {
  std::vector<double> a, b;
  for (int i = 0; i < 400; ++i) a.push_back(0.2 + 0.7 * (i % 37) / 37.0);
  for (int i = 0; i < 300; ++i) b.push_back(0.6 + 0.39 * (i % 11) / 11.0);
  return {quality_histogram(a, 20, "before"), quality_histogram(b, 20, "after")};
}

TEST_F(HistogramPng, IsAPngOfTheSvgSizeWithTheSeriesDrawn) {
  if (histogram_png_rasterizer().empty()) GTEST_SKIP() << "rsvg-convert not installed";
  const std::string out = (dir_ / "h.png").string();
  write_histogram(two_series(), out);
  const Png p = decode_png(out);
  // The SVG's own size (histogram_svg: width="760" height="440").
  const std::string svg = histogram_svg(two_series());
  EXPECT_NE(svg.find("width=\"760\" height=\"440\""), std::string::npos);
  EXPECT_EQ(p.width, 760u);
  EXPECT_EQ(p.height, 440u);
  ASSERT_EQ(p.rgb.size(), std::size_t(760) * 440);
  // White background, black axes and text, the two series' colours (#1f77b4, #d62728), and the
  // antialiased shades between them: many colours, most pixels white, a fair number not.
  std::set<std::uint32_t> colours(p.rgb.begin(), p.rgb.end());
  std::size_t white = 0, dark = 0, blue = 0, red = 0;
  for (std::uint32_t c : p.rgb) {
    white += c == 0xffffff;
    dark +=
        (c >> 16) < 0x80 && ((c >> 8) & 0xff) < 0x80 && (c & 0xff) < 0x80;  // black, antialiased
    blue += c == 0x1f77b4;
    red += c == 0xd62728;
  }
  EXPECT_EQ(p.rgb.front(), 0xffffffu);  // a corner: the background
  EXPECT_GT(colours.size(), 20u);
  EXPECT_GT(white, p.rgb.size() / 2);
  EXPECT_GT(dark, 500u);  // axes (2 x ~330 px) and glyphs
  EXPECT_GT(blue, 100u);
  EXPECT_GT(red, 100u);
  EXPECT_EQ(files_in_dir(), 1u);  // no temporary left beside it
}

TEST_F(HistogramPng, AMissingRasterizerIsRefusedBeforeAnyWork) {
  setenv("CVTMESH_RSVG_CONVERT", (dir_ / "no-such-program").c_str(), 1);
  const std::string out = (dir_ / "h.png").string();
  try {
    check_histogram_path(out);
    ADD_FAILURE() << "no error";
  } catch (const OutputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(out), std::string::npos) << m;
    EXPECT_NE(m.find("rsvg-convert"), std::string::npos) << m;
    EXPECT_NE(m.find("librsvg2-bin"), std::string::npos) << m;
  }
  EXPECT_THROW(write_histogram(two_series(), out), OutputError);
  EXPECT_EQ(files_in_dir(), 0u);
  // The SVG does not need it.
  write_histogram(two_series(), (dir_ / "h.svg").string());
  EXPECT_TRUE(fs::exists(dir_ / "h.svg"));
  EXPECT_THROW(check_histogram_path((dir_ / "h.bmp").string()), OutputError);
}

TEST_F(HistogramPng, AFailingRasterizerLeavesNoFile) {
  // A rasterizer that fails after writing half a file: /bin/sh script that writes junk and exits 1.
  const fs::path fake = dir_ / "fake-rsvg";
  std::ofstream(fake)
      << "#!/bin/sh\n"
         "while [ $# -gt 0 ]; do [ \"$1\" = --output ] && echo junk > \"$2\"; shift; done\n"
         "echo 'fake-rsvg: broken' >&2\nexit 1\n";
  fs::permissions(fake, fs::perms::owner_all);
  setenv("CVTMESH_RSVG_CONVERT", fake.c_str(), 1);
  const std::string out = (dir_ / "h.png").string();
  try {
    write_histogram(two_series(), out);
    ADD_FAILURE() << "no error";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("fake-rsvg: broken"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(out), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(files_in_dir(), 1u);  // the fake program only
}

TEST_F(HistogramPng, StatsWritesAPngHistogram) {
  if (histogram_png_rasterizer().empty()) GTEST_SKIP() << "rsvg-convert not installed";
  const std::string out = (dir_ / "stats.png").string();
  std::string log;
  ASSERT_EQ(testing::run(testing::cli_path() + " -q stats '" + testing::geo_path("quad.geo") +
                             "' --histogram '" + out + "'",
                         &log),
            0)
      << log;
  const Png p = decode_png(out);
  EXPECT_EQ(p.width, 760u);
  EXPECT_EQ(p.height, 440u);
  // Refused up front, with exit 3 (cannot write) and no file, when the rasterizer is missing.
  const std::string out2 = (dir_ / "stats2.png").string();
  const int code =
      testing::run("CVTMESH_RSVG_CONVERT=/no/such " + testing::cli_path() + " stats '" +
                       testing::geo_path("quad.geo") + "' --histogram '" + out2 + "'",
                   &log);
  EXPECT_EQ(code, 3) << log;
  EXPECT_NE(log.find("librsvg2-bin"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(out2));
}

}  // namespace
}  // namespace cvtmesh
