#!/usr/bin/python3
"""cvtmesh-onelab driven by a real, stock gmsh process (run me with xvfb-run -a).

- Batch: `gmsh model.geo cvtmesh.exe -run` (Gmsh's batch ONELAB loop: initialize, check,
  compute over the socket; a client is picked for batch runs by opening an executable file named
  *.exe, hence a symlink). The client optimizes Gmsh's mesh (Gmsh/MshFileName), writes
  model_cvt.msh with the quality views and has Gmsh load it in place of the model; the results
  land in Gmsh's ONELAB database (saved as model.db), equal to what the written mesh measures.
- GUI: the documented registration (-setstring Solver.Name0/Solver.Executable0), the solver picked
  in Modules > Solver and Run pressed by synthetic clicks; the optimized mesh replaces the model
  in the window; pressing Run again re-meshes the model and optimizes again, without errors.
  Screenshots before/after are kept as artifacts.
- Without -onelab, the client explains how to register it.

Environment: CVTMESH_ONELAB (the client), CVTMESH_CLI (cvtmesh, to measure files),
CVTMESH_SOURCE_DIR, CVTMESH_ARTIFACTS.
"""
import json
import os
import subprocess
import tempfile
import time
import unittest

import xvfb_util as xu

CLIENT = os.environ.get("CVTMESH_ONELAB", "cvtmesh-onelab")
CLI = os.environ.get("CVTMESH_CLI", "cvtmesh")
SOURCE_DIR = os.environ.get("CVTMESH_SOURCE_DIR",
                            os.path.join(os.path.dirname(__file__), "..", ".."))
GEO = os.path.join(SOURCE_DIR, "geo", "cube_sphere.geo")
GROUP = "Mesh optimization (CVT)"


def write_model(directory, iterations):
    """cube_sphere.geo with the panel's max iterations preset from the .geo: a ONELAB parameter
    the model defines keeps its value when the client defines the panel."""
    path = os.path.join(directory, "model.geo")
    with open(path, "w") as f:
        f.write(f'Include "{GEO}";\n'
                f'DefineConstant[ it = {{{iterations}, Name "{GROUP}/1Max iterations"}} ];\n')
    return path


def read_db(path):
    """Gmsh's saved ONELAB database: {name: [values]} (numbers as floats)."""
    with open(path, "rb") as f:
        data = f.read()
    pos = data.index(b"\n") + 1  # header line
    params = {}
    while pos < len(data):
        space = data.index(b" ", pos)
        size = int(data[pos:space])
        record = data[space + 1:space + 1 + size].decode()
        pos = space + 1 + size + 1
        fields = record.split("\0")
        kind, name = fields[1], fields[2]
        i = 8
        i += 1 + 2 * int(fields[i])  # attributes
        i += 1 + 2 * int(fields[i])  # clients
        n = int(fields[i])
        values = fields[i + 1:i + 1 + n]
        params[name] = [float(v) for v in values] if kind == "number" else values
    return params


def stats(path):
    """The quality table column of a mesh file, measured by the cvtmesh CLI."""
    run = subprocess.run([CLI, "stats", path, "--format", "json"], capture_output=True,
                         text=True, check=True)
    return json.loads(run.stdout)  # one object per mesh (docs/cli.md, JSON)


class Onelab(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.env = dict(os.environ, HOME=self.dir)  # Gmsh's socket and options live in HOME

    def tearDown(self):
        self.tmp.cleanup()

    def check_results(self, db, msh_in, msh_out, iterations):
        """The results in Gmsh's tree are those of the meshes on disk, and quality rose."""
        before, after = stats(msh_in), stats(msh_out)
        self.assertGreater(after["average_quality"], before["average_quality"])
        p = read_db(db)
        res = f"{GROUP}/9Results/"
        self.assertEqual(p[res + "0Iterations"], [iterations])
        self.assertAlmostEqual(p[res + "2Q avg"][0], after["average_quality"], places=9)
        self.assertAlmostEqual(p[res + "3Q avg (init)"][0], before["average_quality"], places=9)
        self.assertAlmostEqual(p[res + "4Q min"][0], after["q_min"], places=9)
        # The panel's inputs are in the tree too.
        for name in ("0Method", "1Max iterations", "2Lloyd step", "2Tolerance", "3Sizing",
                     "4Quality views"):
            self.assertIn(f"{GROUP}/{name}", p)
        return before, after

    def test_batch_run(self):
        model = write_model(self.dir, 8)
        os.symlink(CLIENT, os.path.join(self.dir, "cvtmesh.exe"))
        run = subprocess.run(["gmsh", model, "cvtmesh.exe", "-run", "-clscale", "2.5",
                              "-setnumber", "General.Terminal", "1"], cwd=self.dir, env=self.env,
                             capture_output=True, text=True, timeout=300)
        log = run.stdout + run.stderr
        self.assertEqual(run.returncode, 0, log)
        msh_in = os.path.join(self.dir, "model.msh")
        msh_out = os.path.join(self.dir, "model_cvt.msh")
        self.assertIn(f"cvtmesh - cvtmesh: optimizing {msh_in}", log)  # client messages
        self.assertIn(f"Reading '{msh_out}'", log)  # Gmsh opened the result
        self.check_results(os.path.join(self.dir, "model.db"), msh_in, msh_out, 8)
        # Gmsh ran the client's .geo text (views of an earlier run removed, Q over its range, the
        # cut facing the camera, the histogram graph) without an error.
        self.assertNotIn("Error", log)
        # The options of the run are kept (hidden) to mark its views stale when they change.
        self.assertIn("method=", read_db(os.path.join(self.dir, "model.db"))[
            f"{GROUP}/9Results/run options"][0])
        # The result carries the quality views and the model's physical groups.
        with open(msh_out, errors="replace") as f:
            text = f.read()
        self.assertEqual(text.count("$ElementData"), 3)
        for name in ("Q (Du-Wang)", "fluid", "ball_surface", "cube_faces"):
            self.assertIn(f'"{name}"', text)

    def test_batch_run_on_a_surface_mesh_in_space(self):
        # An open spherical patch and a plate (surfaces that bound no volume): Gmsh says the
        # model is 2D, the client finds a surface mesh in space and runs the 3D default method.
        model = os.path.join(self.dir, "model.geo")
        with open(model, "w") as f:
            f.write("Point(1) = {0, 0, 0, 0.4};\nPoint(2) = {1, 0, 0, 0.4};\n"
                    "Point(3) = {0, 1, 0, 0.4};\nPoint(4) = {0, 0, 1, 0.1};\n"
                    "Circle(1) = {2, 1, 3};\nCircle(2) = {3, 1, 4};\nCircle(3) = {4, 1, 2};\n"
                    "Curve Loop(1) = {1, 2, 3};\nSurface(1) = {1};\n"
                    "Line(4) = {1, 2};\nLine(5) = {3, 1};\nCurve Loop(2) = {4, 1, 5};\n"
                    "Plane Surface(2) = {2};\n")
        os.symlink(CLIENT, os.path.join(self.dir, "cvtmesh.exe"))
        run = subprocess.run(["gmsh", model, "cvtmesh.exe", "-run",
                              "-setnumber", "General.Terminal", "1"], cwd=self.dir, env=self.env,
                             capture_output=True, text=True, timeout=300)
        log = run.stdout + run.stderr
        self.assertEqual(run.returncode, 0, log)
        self.assertNotIn("Error", log)
        msh_in = os.path.join(self.dir, "model.msh")
        msh_out = os.path.join(self.dir, "model_cvt.msh")
        self.assertIn(f"Reading '{msh_out}'", log)
        before, after = stats(msh_in), stats(msh_out)
        self.assertGreater(after["number_of_elements"], 0)
        self.assertGreaterEqual(after["q_min"], before["q_min"])
        # The 3D default moves the vertices on the surfaces (2D's default, picked from the list
        # Gmsh's 2D model shows first, would only flip coplanar edges here).
        self.assertGreater(after["average_quality"], before["average_quality"])
        self.assertIn(f" on {after['number_of_elements']} triangles", log)

    def test_gui_registered_solver(self):
        art = xu.artifacts_dir()
        model = write_model(self.dir, 8)
        view = os.path.join(self.dir, "view.opt")  # a 3/4 view of the cube for the screenshots
        with open(view, "w") as f:
            f.write("General.Trackball = 0; General.RotationX = -65; General.RotationZ = -115;\n"
                    "General.ScaleX = 0.7; General.ScaleY = 0.7; General.ScaleZ = 0.7;\n")
        log_path = os.path.join(self.dir, "gmsh.log")
        log = open(log_path, "w")
        gmsh = subprocess.Popen(["gmsh", model, "-clscale", "2.5", "-option", view,
                                 "-setstring", "Solver.Name0", "cvtmesh",
                                 "-setstring", "Solver.Executable0", CLIENT,
                                 "-setnumber", "General.Terminal", "1"],
                                cwd=self.dir, env=self.env, stdout=log, stderr=subprocess.STDOUT)

        def log_count(text):
            with open(log_path) as f:
                return f.read().count(text)

        msh_out = os.path.join(self.dir, "model_cvt.msh")
        try:
            wid = xu.window("Gmsh")
            time.sleep(2.0)
            # Default layout (fresh HOME): menu tree 200 px wide, Run button at its bottom right.
            _, height = xu.window_size(wid)
            xu.click(wid, 34, 83)  # Modules > Solver: expand
            time.sleep(0.5)
            xu.click(wid, 67, 99)  # Modules > Solver > cvtmesh: start the client (check)
            time.sleep(3.0)
            xu.screenshot(os.path.join(art, "onelab_before.png"))
            xu.click(wid, 120, height - 39)  # Run (compute)
            # Gmsh loads the result, then saves its database: the computation is over.
            xu.wait_for(lambda: log_count("Saving database") >= 1, 120, "the first run")
            self.assertEqual(log_count(f"Reading '{msh_out}'"), 1)
            time.sleep(2.0)
            xu.screenshot(os.path.join(art, "onelab_after.png"))
            self.check_results(os.path.join(self.dir, "model.db"),
                               os.path.join(self.dir, "model.msh"), msh_out, 8)
            # Run again: Gmsh re-meshes the model, the client optimizes and shows it again.
            xu.click(wid, 120, height - 39)
            xu.wait_for(lambda: log_count("Saving database") >= 2, 120, "the second run")
            self.assertEqual(log_count(f"Reading '{msh_out}'"), 2)
            self.assertEqual(log_count("cvtmesh - cvtmesh: optimizing"), 2)
            self.assertEqual(log_count("Error"), 0)
            self.assertIn("model.geo", xu.window_name(wid))  # the project is still the model
        finally:
            gmsh.kill()
            gmsh.wait()
            log.close()

    def test_without_gmsh_it_explains_itself(self):
        run = subprocess.run([CLIENT], capture_output=True, text=True, timeout=30)
        self.assertEqual(run.returncode, 2)
        self.assertIn("Solver.Executable0", run.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
