#!/usr/bin/python3
"""End-to-end tests of the scripting routes. In-process Python: Debian's python3-gmsh and the
cvtmesh module in one process act on one Gmsh model, checked through gmsh itself (nodes moved,
boundary nodes and physical groups unchanged, Gmsh's own quality plugin (ICN) sees the better
mesh). And the three examples of docs/examples/ (Python, C++, .geo + CLI) run and write a better,
quality-annotated mesh.

Environment: PYTHONPATH has the module's directory; CVTMESH_SOURCE_DIR is the source tree;
CVTMESH_CPP_EXAMPLE and CVTMESH_CLI the built C++ example and CLI (tests skipped without them).
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

import gmsh
import cvtmesh

SOURCE_DIR = os.environ.get("CVTMESH_SOURCE_DIR",
                            os.path.join(os.path.dirname(__file__), "..", ".."))
GEO = os.path.join(SOURCE_DIR, "geo", "cube_sphere.geo")


def moving_method():
    """The first 3D method that moves nodes (swap alone only flips)."""
    return next(m for m in cvtmesh.methods(3) if m != "swap")


def physical_groups():
    return [(d, t, gmsh.model.getPhysicalName(d, t),
             sorted(gmsh.model.getEntitiesForPhysicalGroup(d, t)))
            for d, t in gmsh.model.getPhysicalGroups()]


def nodes(max_dim):
    """Node tag -> (x, y, z) for the nodes classified on entities of dimension <= max_dim."""
    out = {}
    for d, t in gmsh.model.getEntities():
        if d > max_dim:
            continue
        tags, xyz, _ = gmsh.model.mesh.getNodes(d, t, includeBoundary=False,
                                                returnParametricCoord=False)
        for i, tag in enumerate(tags):
            out[int(tag)] = tuple(xyz[3 * i:3 * i + 3])
    return out


def nb_tets():
    types, tags, _ = gmsh.model.mesh.getElements(3)
    return sum(len(t) for ty, t in zip(types, tags) if ty == 4)


def gmsh_icn():
    """Per-tet ICN (inverse condition number) computed by Gmsh's AnalyseMeshQuality plugin."""
    for k, v in (("ICNMeasure", 1), ("IGEMeasure", 0), ("JacobianDeterminant", 0),
                 ("CreateView", 1), ("Recompute", 1), ("DimensionOfElements", 3)):
        gmsh.plugin.setNumber("AnalyseMeshQuality", k, v)
    old = set(gmsh.view.getTags())
    gmsh.plugin.run("AnalyseMeshQuality")
    values = []
    for tag in gmsh.view.getTags():
        if tag in old:
            continue
        _, _, data, _, _ = gmsh.view.getModelData(tag, 0)
        values = [d[0] for d in data]
        gmsh.view.remove(tag)
    return values


class InProcessScripting(unittest.TestCase):
    def setUp(self):
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFactor", 2.5)
        gmsh.option.setNumber("Mesh.RandomSeed", 1)
        gmsh.open(GEO)
        gmsh.model.mesh.generate(3)

    def tearDown(self):
        gmsh.finalize()

    def test_optimize_acts_on_the_current_model(self):
        groups = physical_groups()
        entities = gmsh.model.getEntities()
        boundary = nodes(2)
        before = nodes(3)
        icn_before = gmsh_icn()
        self.assertEqual(len(icn_before), nb_tets())
        progress = []

        # fix_boundary: this test checks the fixed-boundary contract (the default method moves
        # the boundary since issue 13; tests/boundary/ covers that).
        table = cvtmesh.optimize(method=moving_method(), max_iterations=10, quality_views=True,
                                 fix_boundary=True, progress=progress.append)

        # The table: the paper's rows, before and after.
        self.assertEqual(table["method"], moving_method())
        self.assertEqual(table["dim"], 3)
        self.assertGreaterEqual(table["iterations"], 1)
        self.assertGreaterEqual(len(progress), 1)  # reported while it ran
        for p in progress:
            self.assertEqual(set(p), {"phase", "start", "iteration", "D", "energy", "q_min", "q_avg"})
        for col in ("before", "after"):
            for row in ("number_of_elements", "q_min", "average_quality", "bad_elements_pct",
                        "min_dihedral_angle", "q_0.7_1.0", "q_0.0_0.3"):
                self.assertIn(row, table[col])
        self.assertGreater(table["after"]["average_quality"],
                           table["before"]["average_quality"])
        # Through gmsh: same model, same entities and groups, boundary fixed, interior moved.
        self.assertEqual(gmsh.model.list(), ["cube_sphere"])
        self.assertEqual(physical_groups(), groups)
        self.assertEqual(gmsh.model.getEntities(), entities)
        self.assertEqual(nodes(2), boundary)
        after = nodes(3)
        interior = [t for t in after if t not in boundary]
        moved = sum(1 for t in interior if t in before and before[t] != after[t])
        self.assertGreater(moved, len(interior) // 2)  # Lloyd moves every free generator
        self.assertEqual(nb_tets(), table["after"]["number_of_elements"])
        # Gmsh's own measure sees a better mesh on average.
        icn_after = gmsh_icn()
        self.assertEqual(len(icn_after), nb_tets())
        self.assertGreater(sum(icn_after) / len(icn_after), sum(icn_before) / len(icn_before))
        # The quality views live in gmsh, one value per tet; Q first.
        self.assertEqual(len(table["views"]), 3)
        kind, tags, data, _, _ = gmsh.view.getModelData(table["views"][0], 0)
        self.assertEqual(kind, "ElementData")
        self.assertEqual(len(data), nb_tets())
        self.assertAlmostEqual(min(d[0] for d in data), table["after"]["q_min"], places=12)
        # quality() measures the mesh gmsh now holds.
        q = cvtmesh.quality()
        self.assertAlmostEqual(q["average_quality"], table["after"]["average_quality"], places=12)

    def test_lbfgs_and_plain_lloyd_are_reachable(self):
        # L-BFGS (lbfgs=5, the 3D default), Anderson and the paper's plain Lloyd (lbfgs=0,
        # anderson=0, relaxation=1) all run on the current model and improve it; basin hopping is
        # 2D only and refused on this 3D mesh.
        for kwargs in ({"lbfgs": 5}, {"lbfgs": 0},
                       {"lbfgs": 0, "anderson": 0, "relaxation": 1.0}):
            gmsh.model.mesh.clear()
            gmsh.model.mesh.generate(3)
            table = cvtmesh.optimize(method="cvdt", max_iterations=8, tolerance=0,
                                     never_worse=False, **kwargs)  # the method itself
            self.assertEqual(table["iterations"], 8, kwargs)
            self.assertGreater(table["after"]["average_quality"],
                               table["before"]["average_quality"], kwargs)
        boundary = nodes(2)
        with self.assertRaises(ValueError):
            cvtmesh.optimize(method="cvdt", hops=2)
        with self.assertRaises(ValueError):
            cvtmesh.optimize(method="cvdt", lbfgs=-2)
        self.assertEqual(nodes(2), boundary)

    def test_a_bad_option_is_refused_with_the_cli_message(self):
        # The option schema is checked in the core: Python, the CLI and the GUI panel refuse the
        # same value with the same message (the panel: tests/plugin/frontend_options_test.cpp).
        cli = os.environ.get("CVTMESH_CLI")
        if not cli:
            self.skipTest("CVTMESH_CLI not set")
        before = nodes(3)
        with self.assertRaises(cvtmesh.InputError) as e:
            cvtmesh.optimize(relaxation=-2.0)
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out.msh")
            run = subprocess.run([cli, "optimize", os.path.join(SOURCE_DIR, "geo", "cube_sphere.geo"),
                                  "-o", out, "--relaxation", "-2"], capture_output=True, text=True)
            self.assertEqual(run.returncode, 2, run.stderr)
            self.assertFalse(os.path.exists(out))
        self.assertIn(str(e.exception), run.stderr)
        self.assertIn("relaxation (--relaxation)", str(e.exception))
        self.assertEqual(nodes(3), before)
        for bad in ({"max_iterations": -3}, {"tolerance": -2.0}, {"max_iterations": 2.5},
                    {"sizing": "fancy"}):
            with self.assertRaises(cvtmesh.InputError, msg=str(bad)):
                cvtmesh.optimize(**bad)
        with self.assertRaises(TypeError):
            cvtmesh.optimize(no_such_option=1)
        names = [o["name"] for o in cvtmesh.options()]
        self.assertIn("relaxation", names)
        self.assertIn("relaxation", cvtmesh.optimize.__doc__)

    def test_scan_geo_finds_a_system_call_in_an_included_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "part.geo"), "w") as f:
                f.write("// SystemCall in a comment is fine\nOnelabRun \"x\";\n")
            with open(os.path.join(tmp, "m.geo"), "w") as f:
                f.write("Include \"part.geo\";\n")
            found = cvtmesh.scan_geo(os.path.join(tmp, "m.geo"))
            self.assertEqual([(os.path.basename(x["file"]), x["line"], x["command"]) for x in found],
                             [("part.geo", 2, "OnelabRun")])
        self.assertEqual(cvtmesh.scan_geo(os.path.join(SOURCE_DIR, "geo", "cube_sphere.geo")), [])

    def test_sizing_from_a_reference_mesh_file(self):
        entities = gmsh.model.getEntities()
        before = nodes(3)
        with tempfile.TemporaryDirectory() as tmp:
            ref = os.path.join(tmp, "ref.msh")
            gmsh.write(ref)
            # A missing file and a model file (it would be meshed in this session) are refused,
            # named, before anything moves.
            for bad, words in ((os.path.join(tmp, "none.msh"), "no such file"),
                               (GEO, "a model file")):
                with self.assertRaises(cvtmesh.InputError) as e:
                    cvtmesh.optimize(sizing=bad, max_iterations=3)
                self.assertIn(bad, str(e.exception))
                self.assertIn(words, str(e.exception))
            self.assertEqual(nodes(3), before)
            table = cvtmesh.optimize(sizing=ref, method=moving_method(), max_iterations=5,
                                     fix_boundary=True)
        self.assertEqual(table["method"], moving_method())
        # The reference went into a model of its own: the current model is the one optimized.
        self.assertEqual(gmsh.model.getEntities(), entities)
        self.assertNotEqual(nodes(3), before)

    def test_errors_are_exceptions_and_leave_the_model_alone(self):
        before = nodes(3)
        with self.assertRaises(ValueError):
            cvtmesh.optimize(method="no-such-method")

        def interrupt(_):
            raise KeyboardInterrupt

        with self.assertRaises(KeyboardInterrupt):
            cvtmesh.optimize(method=moving_method(), progress=interrupt)
        with self.assertRaises(TypeError):
            cvtmesh.optimize(method=moving_method(), progress=42)
        self.assertEqual(nodes(3), before)
        gmsh.model.mesh.clear()
        with self.assertRaises(cvtmesh.InputError) as e:
            cvtmesh.optimize()
        self.assertIn("has no mesh", str(e.exception))
        self.assertTrue(issubclass(cvtmesh.InputError, ValueError))


class PlanarModel(unittest.TestCase):
    """A 2D model (the paper's washer): every surface is optimized in its plane."""

    def setUp(self):
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(os.path.join(SOURCE_DIR, "geo", "washer.geo"))
        gmsh.model.mesh.generate(2)

    def tearDown(self):
        gmsh.finalize()

    def test_surfaces_are_optimized_in_place(self):
        if not cvtmesh.methods(2):
            self.skipTest("no 2D method in this build")
        boundary = nodes(1)
        before = nodes(2)
        table = cvtmesh.optimize(max_iterations=10, quality_views=True, never_worse=False)
        self.assertEqual(table["dim"], 2)
        self.assertEqual(table["method"], cvtmesh.methods(2)[0])
        self.assertGreater(table["after"]["average_quality"],
                           table["before"]["average_quality"])
        self.assertEqual(nodes(1), boundary)  # nodes on the circles stay
        after = nodes(2)
        self.assertTrue(all(x[2] == 0 for x in after.values()))  # still in the plane z = 0
        moved = sum(1 for t in after if t in before and t not in boundary and before[t] != after[t])
        self.assertGreater(moved, 0)
        _, _, data, _, _ = gmsh.view.getModelData(table["views"][0], 0)
        self.assertEqual(len(data), table["after"]["number_of_elements"])


class CadBoundary(unittest.TestCase):
    """The default method on an OpenCASCADE ball built in Python: the free boundary moves on the
    CAD sphere itself, to 1e-12, and the boundary options are keyword arguments."""

    def setUp(self):
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)

    def tearDown(self):
        gmsh.finalize()

    def test_boundary_options_are_keywords(self):
        names = {o["name"] for o in cvtmesh.options()}
        for k in ("fix_boundary", "hausdorff", "feature_angle", "volume_tolerance",
                  "boundary_lloyd_rounds", "free_smooth_curves"):
            self.assertIn(k, names)

    def test_ball_boundary_stays_on_the_sphere(self):
        gmsh.model.add("ball")
        gmsh.model.occ.addSphere(0.1, 0.2, 0.3, 1)
        gmsh.model.occ.synchronize()
        gmsh.option.setNumber("Mesh.MeshSizeMax", 0.3)
        gmsh.option.setNumber("Mesh.MeshSizeMin", 0.3)
        gmsh.model.mesh.generate(3)
        before = nodes(2)
        table = cvtmesh.optimize(max_iterations=10, hausdorff=0.02)
        fb = table["free_boundary"]
        self.assertEqual(fb["geometry"], "cad")
        self.assertGreater(fb["moved"], 0)
        # On a CAD model the bound is on top of the input mesh's own chord error.
        self.assertGreaterEqual(fb["hausdorff_bound"], 0.02)
        self.assertLessEqual(fb["hausdorff"], fb["hausdorff_bound"])
        # The surface coarsening may remove surface nodes (gone from the model); none is new.
        after = nodes(2)
        self.assertLessEqual(set(after), set(before))
        self.assertEqual(len(before) - len(after), fb["removed"])
        self.assertTrue(0 <= fb["folds_removed"] <= fb["removed"])
        for tag, (x, y, z) in after.items():
            r = ((x - 0.1) ** 2 + (y - 0.2) ** 2 + (z - 0.3) ** 2) ** 0.5
            self.assertLessEqual(abs(r - 1), 1e-12, tag)
        self.assertGreater(sum(1 for t in after if after[t] != before[t]), 0)


def initial_quality(size_factor):
    """Average Q of Gmsh's own mesh of the model (what the examples start from)."""
    gmsh.option.setNumber("Mesh.MeshSizeFactor", size_factor)
    gmsh.open(GEO)
    gmsh.model.mesh.generate(3)
    q = cvtmesh.quality()["average_quality"]
    gmsh.clear()
    return q


class Examples(unittest.TestCase):
    """Each example writes a mesh with the quality views; its Q is better than Gmsh's mesh."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)

    def tearDown(self):
        gmsh.finalize()
        self.tmp.cleanup()

    def check_output(self, path, initial):
        gmsh.clear()
        gmsh.open(path)
        views = gmsh.view.getTags()
        names = [gmsh.option.getString(f"View[{gmsh.view.getIndex(v)}].Name") for v in views]
        self.assertEqual(len(views), 3, names)
        self.assertIn("Q (Du-Wang)", names)
        _, _, data, _, _ = gmsh.view.getModelData(views[names.index("Q (Du-Wang)")], 0)
        # One value per tet; a file cvtmesh wrote has one per element, NaN on the others
        # (meshio reads element data by cell block: docs/cli.md).
        data = [d for d in data if not math.isnan(d[0])]
        self.assertEqual(len(data), nb_tets())
        q_file = sum(d[0] for d in data) / len(data)
        # The stored Q is the quality of the stored mesh, and it beats Gmsh's mesh.
        self.assertAlmostEqual(q_file, cvtmesh.quality()["average_quality"], places=9)
        self.assertGreater(q_file, initial)
        self.assertEqual([n for _, _, n, _ in physical_groups()],
                         ["ball_surface", "cube_faces", "fluid"])

    def run_ok(self, cmd, **kw):
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=300, **kw)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        return run

    def test_python_example(self):
        out = os.path.join(self.tmp.name, "out.msh")
        example = os.path.join(SOURCE_DIR, "docs", "examples", "optimize_current_model.py")
        run = self.run_ok([sys.executable, example, GEO, out])
        self.assertIn("wrote " + out, run.stdout)
        self.check_output(out, initial_quality(2))

    def test_cpp_example(self):
        exe = os.environ.get("CVTMESH_CPP_EXAMPLE")
        if not exe:
            self.skipTest("CVTMESH_CPP_EXAMPLE not set")
        out = os.path.join(self.tmp.name, "out.msh")
        run = self.run_ok([exe, GEO, out])
        self.assertIn("average quality", run.stdout)  # the paper's table is printed
        self.check_output(out, initial_quality(2))

    def test_geo_example(self):
        cli = os.environ.get("CVTMESH_CLI")
        if not cli:
            self.skipTest("CVTMESH_CLI not set")
        geo = os.path.join(self.tmp.name, "optimize_with_cli.geo")
        with open(os.path.join(SOURCE_DIR, "docs", "examples", "optimize_with_cli.geo")) as f:
            text = f.read()
        with open(geo, "w") as f:
            f.write(text)
        run = self.run_ok(["gmsh", geo, "-setstring", "cvtmesh_exe", cli, "-setstring", "model",
                           GEO, "-setstring", "method", moving_method(), "-setnumber",
                           "iterations", "5", "-clscale", "2.5", "-"], cwd=self.tmp.name)
        result = os.path.join(self.tmp.name, "cube_sphere_cvt.msh")
        self.assertIn(f"Reading '{result}'", run.stdout)  # merged back by the .geo
        gmsh.open(os.path.join(self.tmp.name, "cube_sphere_init.msh"))
        initial = cvtmesh.quality()["average_quality"]
        self.check_output(result, initial)


if __name__ == "__main__":
    unittest.main(verbosity=2)
