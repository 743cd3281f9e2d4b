#include "core/io/svg_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/util/error.h"

namespace cvtmesh {
namespace {

// A perceptually ordered ramp: dark red (worst) -> orange -> yellow -> light green -> blue-green
// (best).
std::string colour(double s) {
  static const double stops[5][3] = {
      {165, 0, 38}, {244, 109, 67}, {254, 224, 139}, {166, 217, 106}, {26, 152, 80}};
  s = std::clamp(s, 0.0, 1.0) * 4;
  const int i = std::min(3, static_cast<int>(s));
  const double f = s - i;
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x",
                static_cast<int>(std::lround(stops[i][0] + f * (stops[i + 1][0] - stops[i][0]))),
                static_cast<int>(std::lround(stops[i][1] + f * (stops[i + 1][1] - stops[i][1]))),
                static_cast<int>(std::lround(stops[i][2] + f * (stops[i + 1][2] - stops[i][2]))));
  return buf;
}

std::string esc(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '<')
      r += "&lt;";
    else if (c == '>')
      r += "&gt;";
    else if (c == '&')
      r += "&amp;";
    else
      r += c;
  }
  return r;
}

}  // namespace

void write_svg(const TriMesh2& mesh, const std::string& path, const SvgOptions& o) {
  check_output_allowed(path, o.policy);
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (int v = 0; v < mesh.nb_vertices(); ++v)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], mesh.point(v)[k]);
      hi[k] = std::max(hi[k], mesh.point(v)[k]);
    }
  if (mesh.nb_vertices() == 0) lo[0] = lo[1] = 0, hi[0] = hi[1] = 1;
  const double w = std::max(hi[0] - lo[0], 1e-300), h = std::max(hi[1] - lo[1], 1e-300);
  const double margin = 10, scale = (o.width - 2 * margin) / w;
  const double top = o.title.empty() ? margin : margin + 24;
  const double bar = o.colour_bar ? 44 : 0;
  const double height = top + h * scale + margin + bar;
  auto X = [&](const double* p) { return margin + (p[0] - lo[0]) * scale; };
  auto Y = [&](const double* p) { return top + (hi[1] - p[1]) * scale; };  // y up
  const double stroke =
      std::clamp(0.6 * std::sqrt(w * h / std::max(1, mesh.nb_tris())) * scale / 12, 0.15, 1.0);

  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(1);  // 0.1 px is plenty for a picture, and keeps the files small
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.width << "\" height=\"" << height
    << "\" viewBox=\"0 0 " << o.width << " " << height << "\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!o.title.empty())
    s << "<text x=\"" << margin << "\" y=\"" << margin + 14
      << "\" font-family=\"sans-serif\" font-size=\"15\">" << esc(o.title) << "</text>\n";
  char sw[2][32];
  std::snprintf(sw[0], sizeof sw[0], "%.3f", stroke);
  std::snprintf(sw[1], sizeof sw[1], "%.3f", 2.5 * stroke);
  s << "<g stroke=\"#202020\" stroke-width=\"" << sw[0] << "\" stroke-linejoin=\"round\">\n";
  for (int t = 0; t < mesh.nb_tris(); ++t) {
    const int* tv = &mesh.tris[3 * t];
    if (tv[0] < 0) continue;
    const double q =
        tri_quality(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]), 2, o.measure);
    const double f = (q - o.q_low) / (o.q_high - o.q_low);
    s << "<polygon points=\"";
    for (int k = 0; k < 3; ++k)
      s << (k ? " " : "") << X(mesh.point(tv[k])) << "," << Y(mesh.point(tv[k]));
    s << "\" fill=\"" << colour(f) << "\"/>\n";
  }
  s << "</g>\n<g stroke=\"black\" stroke-width=\"" << sw[1] << "\" stroke-linecap=\"round\">\n";
  for (int e = 0; e < mesh.nb_edges(); ++e) {
    const double* a = mesh.point(mesh.edges[2 * e]);
    const double* b = mesh.point(mesh.edges[2 * e + 1]);
    s << "<line x1=\"" << X(a) << "\" y1=\"" << Y(a) << "\" x2=\"" << X(b) << "\" y2=\"" << Y(b)
      << "\"/>\n";
  }
  s << "</g>\n";
  if (o.colour_bar) {
    const double y0 = top + h * scale + margin + 6, bw = std::min(300.0, o.width - 2 * margin);
    const int steps = 30;
    for (int i = 0; i < steps; ++i)
      s << "<rect x=\"" << margin + bw * i / steps << "\" y=\"" << y0 << "\" width=\""
        << bw / steps + 0.5 << "\" height=\"12\" fill=\"" << colour((i + 0.5) / steps) << "\"/>\n";
    char lo_s[32], hi_s[32];
    std::snprintf(lo_s, sizeof lo_s, "%g", o.q_low);
    std::snprintf(hi_s, sizeof hi_s, "%g", o.q_high);
    s << "<text x=\"" << margin << "\" y=\"" << y0 + 28
      << "\" font-family=\"sans-serif\" font-size=\"12\">" << measure_name(o.measure) << " &#8804; "
      << lo_s << "</text>\n"
      << "<text x=\"" << margin + bw << "\" y=\"" << y0 + 28
      << "\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"end\">" << hi_s
      << "</text>\n";
  }
  s << "</svg>\n";

  AtomicFile f(path);
  {
    std::ofstream out(f.temp_path(), std::ios::binary);
    out << s.str();
    out.flush();
    if (!out) throw OutputError("cannot write '" + path + "'");
  }
  f.commit();
}

}  // namespace cvtmesh
