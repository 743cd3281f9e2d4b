// cvtmesh stats IN [MORE...]: the quality table of one or several meshes (one column each), and
// their quality histograms overlaid as an SVG or PNG picture (--histogram).
#include <iostream>
#include <memory>

#include "convert/cli_common.h"
#include "convert/json_report.h"
#include "core/io/histogram_svg.h"
#include "core/quality/quality_histogram.h"

namespace cvtmesh::cli {

void register_stats(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto more = std::make_shared<std::vector<std::string>>();
  auto format = std::make_shared<std::string>("text");
  auto labels = std::make_shared<std::vector<std::string>>();
  auto histogram = std::make_shared<std::string>();
  auto bins = std::make_shared<int>(20);
  auto fe = std::make_shared<FeOptions>();
  CLI::App* c = app.add_subcommand(
      "stats", "print the quality table (the paper's Table 6/7 rows in 3D, Tables 1-5 in 2D)");
  add_input(c, *in);
  c->add_option("more", *more, "further meshes: one more column each (and one more histogram)");
  c->add_option("--format", *format, "text, markdown or json")
      ->check(CLI::IsMember({"text", "markdown", "json"}));
  c->add_option("--label", *labels,
                "column labels, one per mesh in order (repeatable; default: the file names)");
  c->add_option("--histogram", *histogram,
                "write the meshes' quality histograms, overlaid, to this .svg or .png (the paper's "
                "bins 0.3, 0.5, 0.7 marked; PNG through rsvg-convert, Debian's librsvg2-bin)");
  c->add_option("--bins", *bins, "number of histogram bins over [0, 1] (default 20)")
      ->check(CLI::Range(1, 1000));
  add_fe_options(c, *fe);
  commands().push_back(
      {c, [in, more, format, labels, histogram, bins, fe] {
         std::vector<std::string> paths = {in->path};
         paths.insert(paths.end(), more->begin(), more->end());
         if (!histogram->empty()) check_histogram_path(*histogram);
         QualityTable t;
         std::vector<QualityHistogram> hs;
         for (std::size_t i = 0; i < paths.size(); ++i) {
           InputOpts o = *in;
           o.path = paths[i];
           const MeshData d = read_mesh(o.path, o.to_read_options());
           const std::string l = i < labels->size() ? (*labels)[i] : o.path;
           t.columns.push_back(d.dim == 3 ? quality_stats(d.tet, l) : quality_stats(d.tri, l));
           add_fe_measures(t.columns.back(), d, *fe);
           if (!histogram->empty())
             hs.push_back(quality_histogram(d.dim == 3 ? element_qualities(d.tet, Measure::kQ)
                                                       : element_qualities(d.tri, Measure::kQ),
                                            *bins, l));
         }
         // One mesh: its object alone; several: the compare schema (docs/cli.md, JSON).
         if (*format == "json")
           std::cout
               << (t.columns.size() == 1 ? mesh_json(t.columns.front()) : table_json(t)).dump(2)
               << "\n";
         else
           std::cout << render(t, *format);
         if (!histogram->empty()) {
           OutputPolicy p;
           p.force = true;
           write_histogram(hs, *histogram, p);
         }
         return 0;
       }});
}

}  // namespace cvtmesh::cli
