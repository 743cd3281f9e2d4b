#include "core/io/histogram_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/histogram_png.h"
#include "core/util/error.h"

namespace cvtmesh {

namespace {

constexpr double kW = 760, kH = 440;                        // picture
constexpr double kX0 = 70, kX1 = 730, kY0 = 50, kY1 = 380;  // plot area (y grows down)
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += c;
    }
  return o;
}

std::string num(double v, const char* fmt = "%.2f") {
  char b[32];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}

// A round upper bound for the y axis (in %): 1, 2, 5 times a power of ten.
double nice_ceiling(double v) {
  if (v <= 0) return 1;
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0})
    if (m * p >= v) return m * p;
  return 10 * p;
}

}  // namespace

std::string histogram_svg(const std::vector<QualityHistogram>& series) {
  double top = 0;
  for (const auto& h : series)
    for (double f : h.fraction) top = std::max(top, 100 * f);
  const double ymax = nice_ceiling(top * 1.05);
  auto X = [](double q) { return kX0 + q * (kX1 - kX0); };
  auto Y = [ymax](double pct) { return kY1 - pct / ymax * (kY1 - kY0); };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kW << "\" height=\"" << kH
    << "\" viewBox=\"0 0 " << kW << " " << kH << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << kW / 2 << "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">"
    << "Element quality Q = 72&#8730;3 V / (&#931; L&#178;)^1.5 (1 = regular element)</text>\n";
  // The paper's bins: Q <= 0.3 bad, 0.3-0.5, 0.5-0.7, 0.7-1 good.
  for (double e : {0.3, 0.5, 0.7})
    s << "<line x1=\"" << X(e) << "\" y1=\"" << kY0 << "\" x2=\"" << X(e) << "\" y2=\"" << kY1
      << "\" stroke=\"#999\" stroke-dasharray=\"5,4\"/>\n";
  s << "<text x=\"" << X(0.15) << "\" y=\"" << kY0 - 6
    << "\" text-anchor=\"middle\" fill=\"#666\">bad (Q &#8804; 0.3)</text>\n"
    << "<text x=\"" << X(0.85) << "\" y=\"" << kY0 - 6
    << "\" text-anchor=\"middle\" fill=\"#666\">good (Q &gt; 0.7)</text>\n";
  // Axes, ticks and labels.
  s << "<line x1=\"" << kX0 << "\" y1=\"" << kY1 << "\" x2=\"" << kX1 << "\" y2=\"" << kY1
    << "\" stroke=\"black\"/>\n<line x1=\"" << kX0 << "\" y1=\"" << kY0 << "\" x2=\"" << kX0
    << "\" y2=\"" << kY1 << "\" stroke=\"black\"/>\n";
  for (int i = 0; i <= 10; ++i) {
    const double q = i / 10.0;
    s << "<line x1=\"" << X(q) << "\" y1=\"" << kY1 << "\" x2=\"" << X(q) << "\" y2=\"" << kY1 + 5
      << "\" stroke=\"black\"/><text x=\"" << X(q) << "\" y=\"" << kY1 + 19
      << "\" text-anchor=\"middle\">" << num(q, "%.1f") << "</text>\n";
  }
  for (int i = 0; i <= 5; ++i) {
    const double p = ymax * i / 5;
    s << "<line x1=\"" << kX0 - 5 << "\" y1=\"" << Y(p) << "\" x2=\"" << kX0 << "\" y2=\"" << Y(p)
      << "\" stroke=\"black\"/><text x=\"" << kX0 - 8 << "\" y=\"" << Y(p) + 4
      << "\" text-anchor=\"end\">" << num(p, ymax < 10 ? "%.1f" : "%.0f") << "</text>\n";
  }
  s << "<text x=\"" << (kX0 + kX1) / 2 << "\" y=\"" << kY1 + 40
    << "\" text-anchor=\"middle\">Q</text>\n"
    << "<text transform=\"translate(18," << (kY0 + kY1) / 2
    << ") rotate(-90)\" text-anchor=\"middle\">"
    << "elements (%)</text>\n";
  // One step outline per mesh (lightly filled when there are at most two).
  for (std::size_t k = 0; k < series.size(); ++k) {
    const auto& h = series[k];
    const char* colour = kColours[k % (sizeof kColours / sizeof *kColours)];
    const int n = static_cast<int>(h.fraction.size());
    std::ostringstream pts;
    pts << X(0) << "," << Y(0);
    for (int b = 0; b < n; ++b) {
      const double y = Y(100 * h.fraction[b]);
      pts << " " << X(static_cast<double>(b) / n) << "," << y << " "
          << X(static_cast<double>(b + 1) / n) << "," << y;
    }
    pts << " " << X(1) << "," << Y(0);
    s << "<polygon points=\"" << pts.str() << "\" fill=\"" << colour << "\" fill-opacity=\""
      << (series.size() <= 2 ? 0.12 : 0.0) << "\" stroke=\"" << colour
      << "\" stroke-width=\"2\"/>\n";
    const double ly = kY0 + 16 + 18 * static_cast<double>(k);
    s << "<rect x=\"" << kX0 + 12 << "\" y=\"" << ly - 10 << "\" width=\"14\" height=\"10\" fill=\""
      << colour << "\"/><text x=\"" << kX0 + 32 << "\" y=\"" << ly << "\">" << escape(h.label)
      << " — " << h.nb_elements << " elements, Q_min " << num(h.q_min, "%.3f") << ", average "
      << num(h.q_avg, "%.3f");
    if (h.nb_inverted > 0) s << ", " << h.nb_inverted << " inverted";
    s << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

void check_histogram_path(const std::string& path) {
  const std::filesystem::path p(path);
  if (p.extension() != ".svg" && p.extension() != ".png")
    throw OutputError("'" + path + "': a histogram is written as .svg or .png");
  const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : ".";
  if (!std::filesystem::is_directory(dir))
    throw OutputError("'" + path + "': the directory '" + dir.string() + "' does not exist");
  if (p.extension() == ".png") check_histogram_png(path);
}

void write_histogram_svg(const std::vector<QualityHistogram>& series, const std::string& path,
                         const OutputPolicy& policy) {
  if (std::filesystem::path(path).extension() != ".svg")
    throw OutputError("'" + path + "': write_histogram_svg writes .svg only");
  check_histogram_path(path);
  if (!policy.force && std::filesystem::exists(path))
    throw OutputError("'" + path + "' exists (use --force to replace it)");
  AtomicFile f(path);
  {
    std::ofstream o(f.temp_path());
    o << histogram_svg(series);
    if (!o) throw OutputError("cannot write '" + path + "'");
  }
  f.commit();
}

void write_histogram(const std::vector<QualityHistogram>& series, const std::string& path,
                     const OutputPolicy& policy) {
  check_histogram_path(path);
  if (std::filesystem::path(path).extension() == ".png")
    write_histogram_png(series, path, policy);
  else
    write_histogram_svg(series, path, policy);
}

}  // namespace cvtmesh
