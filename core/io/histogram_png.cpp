#include "core/io/histogram_png.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/io/histogram_svg.h"
#include "core/io/run_program.h"
#include "core/util/error.h"

namespace cvtmesh {

namespace {

// A temporary file that is removed when it goes out of scope.
struct TempFile {
  std::string path;
  explicit TempFile(const std::string& suffix) {
    std::string t = (std::filesystem::temp_directory_path() / "cvtmesh-XXXXXX").string() + suffix;
    const int fd = mkstemps(t.data(), static_cast<int>(suffix.size()));
    if (fd < 0) throw OutputError("cannot create a temporary file in " + t);
    close(fd);
    path = t;
  }
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
};

bool starts_as_png(const std::string& path) {
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::ifstream f(path, std::ios::binary);
  char b[8] = {};
  if (!f.read(b, 8)) return false;
  for (int i = 0; i < 8; ++i)
    if (static_cast<unsigned char>(b[i]) != sig[i]) return false;
  return true;
}

std::string first_line(const std::string& s) {
  const auto end = s.find('\n');
  return end == std::string::npos ? s : s.substr(0, end);
}

}  // namespace

std::string histogram_png_rasterizer() {
  if (const char* e = std::getenv("CVTMESH_RSVG_CONVERT")) return find_program(e);
  return find_program("rsvg-convert");
}

void check_histogram_png(const std::string& path) {
  if (histogram_png_rasterizer().empty())
    throw OutputError("cannot write '" + path +
                      "': a PNG histogram needs rsvg-convert (Debian package librsvg2-bin), "
                      "which was not found; install it or write the histogram as .svg");
}

void write_histogram_png(const std::vector<QualityHistogram>& series, const std::string& path,
                         const OutputPolicy& policy) {
  check_output_allowed(path, policy);
  const std::string rsvg = histogram_png_rasterizer();
  if (rsvg.empty()) check_histogram_png(path);
  TempFile svg(".svg");
  {
    std::ofstream o(svg.path);
    o << histogram_svg(series);
    if (!o) throw OutputError("cannot write the temporary file '" + svg.path + "'");
  }
  AtomicFile f(path);
  const ProgramRun r = run_program({rsvg, "--format", "png", "--background-color", "white",
                                    "--output", f.temp_path(), svg.path});
  if (r.exit_code != 0 || !starts_as_png(f.temp_path())) {
    std::string why = first_line(r.error_output);
    if (why.empty())
      why = r.exit_code < 0 ? "it did not run to its end"
                            : "exit " + std::to_string(r.exit_code) + ", no PNG written";
    throw OutputError("cannot write '" + path + "': " + rsvg + " failed: " + why);
  }
  f.commit();
}

}  // namespace cvtmesh
