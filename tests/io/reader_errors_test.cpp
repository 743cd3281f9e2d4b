// Bad input for our own readers: every problem is an InputError that names the file (and the line
// for text formats); never a crash, never another exception. Ends with a small mutation fuzz.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>

#include "core/io/medit_io.h"
#include "core/io/read_mesh.h"
#include "core/io/surface_io.h"
#include "core/io/tetgen_io.h"
#include "core/io/vtk_io.h"
#include "core/io/write_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
void spit(const std::string& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}
std::string replace_once(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << "test setup: '" << from << "' not found";
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

MeshData cube() {
  MeshData d;
  d.dim = 3;
  d.tet = testing::cube6();
  return d;
}
MeshData square() {
  MeshData d;
  d.dim = 2;
  d.tri = testing::square2();
  return d;
}

// Valid files of each format, as text, written by our writers.
struct Samples {
  std::string dir = testing::temp_dir();
  std::string node, ele, face, medit, medit2, vtk, vtu, node2, ele2;
  Samples() {
    write_mesh(cube(), dir + "/c.node");
    write_mesh(cube(), dir + "/c.mesh");
    write_mesh(cube(), dir + "/c.vtk");
    write_mesh(cube(), dir + "/c.vtu");
    write_mesh(square(), dir + "/s.mesh");
    write_mesh(square(), dir + "/s.node");
    node = slurp(dir + "/c.node");
    ele = slurp(dir + "/c.ele");
    face = slurp(dir + "/c.face");
    medit = slurp(dir + "/c.mesh");
    medit2 = slurp(dir + "/s.mesh");
    vtk = slurp(dir + "/c.vtk");
    vtu = slurp(dir + "/c.vtu");
    node2 = slurp(dir + "/s.node");
    ele2 = slurp(dir + "/s.ele");
  }
};
const Samples& samples() {
  static const Samples s;
  return s;
}

// Runs the reader on `path`, expects an InputError naming the file and containing `what`.
void expect_input_error(const std::function<void()>& read, const std::string& path,
                        const std::string& what, bool with_line = true) {
  try {
    read();
    ADD_FAILURE() << "no error for " << path << " (expected: " << what << ")";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path), std::string::npos) << "message does not name the file: " << m;
    EXPECT_NE(m.find(what), std::string::npos) << "expected '" << what << "' in: " << m;
    if (with_line) EXPECT_NE(m.find(" line "), std::string::npos) << "no line number: " << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << "not a one-line message: " << m;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type for " << path << ": " << e.what();
  }
}

TEST(ReaderErrors, TetGen) {
  const Samples& s = samples();
  const std::string dir = testing::temp_dir();
  struct Case {
    std::string name, node, ele, what;
    bool line = true;
  };
  // The first tet line of the .ele, to edit.
  std::istringstream es(s.ele);
  std::string l, first_tet;
  while (std::getline(es, l))
    if (!l.empty() && l[0] != '#' && std::count(l.begin(), l.end(), ' ') > 4) {
      first_tet = l;
      break;
    }
  std::istringstream ft(first_tet);
  std::string idx, a, b, c, d2, rest;
  ft >> idx >> a >> b >> c >> d2;
  std::getline(ft, rest);
  const std::vector<Case> cases = {
      {"truncated_ele", s.node, s.ele.substr(0, s.ele.size() - 15), "truncated"},
      {"truncated_node", s.node.substr(0, s.node.size() / 2), s.ele, "truncated"},
      {"truncated_in_line", s.node, s.ele.substr(0, s.ele.size() - 4), "truncated"},
      {"garbage_node", "hello world\n", s.ele, "expected the number of points"},
      {"index_out_of_range", s.node,
       replace_once(s.ele, first_tet, idx + " " + a + " " + b + " " + c + " 99" + rest),
       "out of range"},
      {"nan_coordinate", replace_once(s.node, "\n2 1 0 0", "\n2 nan 0 0"), s.ele,
       "not a finite number"},
      {"second_order", s.node, replace_once(s.ele, "\n6 4 ", "\n6 10 "), "second-order"},
      {"bad_region", s.node, replace_once(s.ele, first_tet, first_tet + ".5"),
       "not an integer tag"},
      {"trailing_garbage", s.node, s.ele + "7 1 2 3 4 1\n", "unexpected data"},
      {"huge_count", s.node, replace_once(s.ele, "\n6 4 ", "\n600000000 4 "), "too short"},
      {"dimension_4", replace_once(s.node, "\n8 3 ", "\n8 4 "), s.ele, "out of range"},
      {"point_out_of_sequence", replace_once(s.node, "\n2 1 0 0", "\n5 1 0 0"), s.ele,
       "point index 5 out of sequence"},
      {"first_element_index_2", s.node,
       replace_once(s.ele, first_tet, "2 " + a + " " + b + " " + c + " " + d2 + rest),
       "the first element index must be 0 or 1, got 2"},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(k.name);
    const std::string base = dir + "/" + k.name;
    spit(base + ".node", k.node);
    spit(base + ".ele", k.ele);
    expect_input_error([&] { read_tetgen(base + ".node"); }, base, k.what, k.line);
  }
  // A .node without its .ele.
  spit(dir + "/lonely.node", s.node);
  expect_input_error([&] { read_mesh(dir + "/lonely.node"); }, dir + "/lonely.node", "lonely.ele",
                     false);
  // A facet that is not a face of any tet.
  spit(dir + "/badface.node", s.node);
  spit(dir + "/badface.ele", s.ele);
  spit(dir + "/badface.face", "1 1\n1 1 4 5 5\n");
  expect_input_error([&] { read_tetgen(dir + "/badface.node"); }, dir + "/badface.node",
                     "not a face of any tetrahedron", false);
  // A duplicated tet.
  spit(dir + "/dup.node", s.node);
  spit(dir + "/dup.ele",
       replace_once(s.ele, "\n6 4 ", "\n7 4 ") + "7 " + a + " " + b + " " + c + " " + d2 + " 1\n");
  expect_input_error([&] { read_tetgen(dir + "/dup.node"); }, dir + "/dup.node", "shared by 3",
                     false);
  // Two tets on the same side of their common face.
  spit(dir + "/fold.node", "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0.1 0.1 0.5\n");
  spit(dir + "/fold.ele", "2 4 0\n1 1 2 3 4\n2 1 2 3 5\n");
  expect_input_error([&] { read_tetgen(dir + "/fold.node"); }, dir + "/fold.node", "overlap",
                     false);
  // The same, the second tet given in the other vertex order: turned positive, still a fold.
  spit(dir + "/fold2.node", "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0.1 0.1 0.5\n");
  spit(dir + "/fold2.ele", "2 4 0\n1 1 2 3 4\n2 2 1 3 5\n");
  expect_input_error([&] { read_tetgen(dir + "/fold2.node"); }, dir + "/fold2.node", "overlap",
                     false);
  // A tet in the other vertex order inside a valid mesh: read, turned positive.
  spit(dir + "/inverted.node", s.node);
  spit(dir + "/inverted.ele",
       replace_once(s.ele, first_tet, idx + " " + b + " " + a + " " + c + " " + d2 + rest));
  const MeshData inv = read_tetgen(dir + "/inverted.node");
  EXPECT_EQ(inv.model().nb_reoriented, 1);
  EXPECT_TRUE(check_mesh(inv.tet).ok);
}

TEST(ReaderErrors, Medit) {
  const Samples& s = samples();
  const std::string dir = testing::temp_dir();
  struct Case {
    std::string name, text, what;
    bool line = true;
  };
  const std::vector<Case> cases = {
      {"truncated", s.medit.substr(0, s.medit.find("Tetrahedra") + 20), "truncated"},
      {"truncated_no_count", s.medit.substr(0, s.medit.find("Tetrahedra") + 10), "end of file"},
      {"garbage", "this is not a mesh\n", "not a Medit"},
      {"binary_nul", std::string("MeshVersionFormatted 2\n\0\1\2", 26), "NUL"},
      {"index_zero", replace_once(s.medit, "Tetrahedra\n6\n", "Tetrahedra\n6\n0 "), "out of range"},
      {"index_too_big", replace_once(s.medit, "Tetrahedra\n6\n", "Tetrahedra\n6\n9 "),
       "out of range"},
      {"hexahedra", replace_once(s.medit, "End", "Hexahedra\n1\n1 2 3 4 5 6 7 8 1\nEnd"),
       "unsupported element type"},
      {"unknown_keyword", replace_once(s.medit, "End", "Bogus\n1\nEnd"), "unknown keyword"},
      {"nan", replace_once(s.medit, "Vertices\n8\n0 ", "Vertices\n8\nnan "), "not a finite number"},
      {"negative_count", replace_once(s.medit, "Tetrahedra\n6", "Tetrahedra\n-6"), "out of range"},
      {"huge_count", replace_once(s.medit, "Tetrahedra\n6", "Tetrahedra\n2000000000"), "too short"},
      {"no_dimension", replace_once(s.medit, "Dimension 3", ""), "before 'Dimension'"},
      {"tets_in_2d", replace_once(s.medit2, "End", "Tetrahedra\n1\n1 2 3 4 1\nEnd"),
       "tetrahedra in a 2D"},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(k.name);
    const std::string p = dir + "/" + k.name + ".mesh";
    spit(p, k.text);
    expect_input_error([&] { read_mesh(p); }, p, k.what, k.line);
  }
  // A tet in the other vertex order (swap two vertices of the first one).
  std::string t = s.medit;
  const auto at = t.find("Tetrahedra\n6\n") + 13;
  const auto sp1 = t.find(' ', at), sp2 = t.find(' ', sp1 + 1);
  const std::string v0 = t.substr(at, sp1 - at), v1 = t.substr(sp1 + 1, sp2 - sp1 - 1);
  t.replace(at, sp2 - at, v1 + " " + v0);
  const std::string p = dir + "/inverted.mesh";
  spit(p, t);
  const MeshData inv = read_mesh(p);  // turned positive: the mesh is valid
  EXPECT_EQ(inv.model().nb_reoriented, 1);
  EXPECT_TRUE(check_mesh(inv.tet).ok);
}

TEST(ReaderErrors, Vtk) {
  const Samples& s = samples();
  const std::string dir = testing::temp_dir();
  struct Case {
    std::string name, ext, text, what;
    bool line = true;
  };
  const std::vector<Case> cases = {
      {"truncated", ".vtk", s.vtk.substr(0, s.vtk.find("CELL_TYPES") + 15), "truncated"},
      {"truncated_values", ".vtk", s.vtk.substr(0, s.vtk.size() - 3), "end of file"},
      {"garbage", ".vtk", "garbage\n", "not a legacy VTK"},
      {"binary", ".vtk", replace_once(s.vtk, "ASCII", "BINARY"), "binary"},
      {"structured", ".vtk", replace_once(s.vtk, "UNSTRUCTURED_GRID", "STRUCTURED_POINTS"),
       "not supported"},
      {"hexahedron", ".vtk", replace_once(s.vtk, "CELL_TYPES 6\n10", "CELL_TYPES 6\n12"),
       "hexahedron", false},
      {"index_out_of_range", ".vtk", replace_once(s.vtk, "\n4 0 ", "\n4 42 "), "does not exist",
       false},
      {"cells_size", ".vtk", replace_once(s.vtk, "CELLS 6 30", "CELLS 6 31"), "entries"},
      {"nan", ".vtk", replace_once(s.vtk, "POINTS 8 double\n0 ", "POINTS 8 double\nnan "),
       "not a finite number"},
      {"truncated", ".vtu", s.vtu.substr(0, s.vtu.size() / 2), "truncated"},
      {"garbage", ".vtu", "<html></html>", "not a VTK XML"},
      {"polydata", ".vtu", replace_once(s.vtu, "UnstructuredGrid\"", "PolyData\""),
       "not supported"},
      {"appended", ".vtu", replace_once(s.vtu, "format=\"ascii\"", "format=\"appended\""),
       "not supported"},
      {"bad_number", ".vtu",
       replace_once(s.vtu, "Name=\"connectivity\" format=\"ascii\">\n",
                    "Name=\"connectivity\" format=\"ascii\">\nx"),
       "expected"},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(k.name + k.ext);
    const std::string p = dir + "/" + k.name + k.ext;
    spit(p, k.text);
    expect_input_error([&] { read_mesh(p); }, p, k.what, k.line);
  }
}

TEST(ReaderErrors, Surfaces) {
  const std::string dir = testing::temp_dir();
  struct Case {
    std::string name, text, what;
  };
  // Two tetrahedra surfaces glued along one edge: four triangles around that edge.
  const std::string bowtie =
      "OFF\n7 8 0\n0 0 0\n1 0 0\n0.5 1 0.2\n0.5 0.3 1\n0.5 -1 0.2\n0.5 -0.3 -1\n2 2 2\n"
      "3 0 1 2\n3 0 3 1\n3 1 3 2\n3 0 2 3\n3 1 0 4\n3 0 5 4\n3 4 5 1\n3 1 5 0\n";
  const std::vector<Case> cases = {
      {"open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "not closed"},
      {"nonmanifold.off", bowtie, "non-manifold"},
      {"garbage.off", "OFF\nthis is not a surface\n", ""},
      {"bad_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", ""},
      {"open.stl",
       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "endloop\nendfacet\nendsolid x\n",
       "not closed"},
      {"garbage.stl", "definitely not an stl file\n", ""},
      {"open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "not closed"},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(k.name);
    const std::string p = dir + "/" + k.name;
    spit(p, k.text);
    expect_input_error([&] { read_mesh(p); }, p, k.what, false);
  }
}

// Truncations and random byte changes of valid files: the reader either reads a valid mesh or
// throws InputError, nothing else.
void fuzz(const std::string& name, const std::string& valid, int dim,
          const std::function<MeshData(const std::string&)>& read,
          const std::function<void(const std::string&)>& write) {
  std::mt19937 rng(12345);
  const std::string pieces[] = {"0",
                                "1",
                                "-1",
                                "9",
                                "99999999999",
                                " ",
                                "\n",
                                ".",
                                "e",
                                "nan",
                                "inf",
                                "#",
                                "<",
                                ">",
                                "\"",
                                "/",
                                std::string(1, '\0'),
                                "\xff",
                                "x",
                                "-",
                                "2147483648",
                                "1e308"};
  std::vector<std::string> variants;
  for (std::size_t n = 0; n < valid.size(); n += std::max<std::size_t>(1, valid.size() / 150))
    variants.push_back(valid.substr(0, n));
  for (int i = 0; i < 400; ++i) {
    std::string v = valid;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % v.size();
      const std::string& p = pieces[rng() % std::size(pieces)];
      if (rng() % 2)
        v.replace(at, 1 + rng() % 4, p);
      else
        v.insert(at, p);
    }
    variants.push_back(v);
  }
  int ok = 0, refused = 0;
  for (const std::string& v : variants) {
    write(v);
    try {
      const MeshData d = read(name);
      ASSERT_EQ(d.dim, dim);
      const MeshCheck c = dim == 3 ? check_mesh(d.tet) : check_mesh(d.tri);
      EXPECT_TRUE(c.ok) << "accepted an invalid mesh: " << c.problems[0];
      ++ok;
    } catch (const InputError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << name << ": " << e.what() << "\n--- input ---\n" << v;
      return;
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_GT(ok, 0);  // the untouched prefix of full length is not in the list, but some edits
                     // (in comments, numbers of equal value) keep the file valid
}

TEST(ReaderFuzz, OwnReadersRefuseOrReadValidMeshes) {
  const Samples& s = samples();
  // Thousands of small files: in memory (tmpfs) when available, it is much faster than a disk.
  std::string dir = testing::temp_dir();
  char shm[] = "/dev/shm/cvtmesh-fuzz-XXXXXX";
  if (std::filesystem::is_directory("/dev/shm") && mkdtemp(shm)) dir = shm;
  const std::vector<std::tuple<std::string, std::string, int>> medit_vtk = {
      {"/f.mesh", s.medit, 3},
      {"/f2.mesh", s.medit2, 2},
      {"/f.vtk", s.vtk, 3},
      {"/f.vtu", s.vtu, 3}};
  for (const auto& [name, text, dim] : medit_vtk) {
    SCOPED_TRACE(name);
    const std::string p = dir + name;
    fuzz(
        p, text, dim, [](const std::string& f) { return read_mesh(f); },
        [&](const std::string& v) { spit(p, v); });
  }
  // TetGen: mutate one file of the set at a time.
  const std::string base = dir + "/t";
  for (const auto& [which, text, other_node, other_ele, dim] :
       std::vector<std::tuple<std::string, std::string, std::string, std::string, int>>{
           {".ele", s.ele, s.node, "", 3},
           {".node", s.node, "", s.ele, 3},
           {".ele", s.ele2, s.node2, "", 2}}) {
    SCOPED_TRACE("tetgen " + which);
    spit(base + ".node", other_node.empty() ? text : other_node);
    spit(base + ".ele", other_ele.empty() ? text : other_ele);
    std::remove((base + ".face").c_str());
    std::remove((base + ".edge").c_str());
    fuzz(
        base + ".node", text, dim, [](const std::string& f) { return read_mesh(f); },
        [&](const std::string& v) { spit(base + which, v); });
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cvtmesh
