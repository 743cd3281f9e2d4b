#!/usr/bin/python3
"""cvtmesh-gui under Xvfb (run me with xvfb-run -a): the real Gmsh GUI with the panel.

- Show quality (--show-quality), then a synthetic click on the Run button (xdotool): the quality
  shown before is the "before" of the run, the run raises it, screenshots before/after are kept
  as artifacts.
- Run triggered programmatically (--run-on-start, the same ONELAB action a press sets).
- After a run (read back through Gmsh's option API, the result file's "display"): the histogram
  is a graph view (View.Type 2) beside the Q view; the Q view's colour range is its data range;
  the cut plane faces the camera (its normal is the view direction of General.RotationX/Y/Z).
- Stop (the Run button while running) ends a long run; the mesh is left alone; it is reported as
  a notice (Info), not an error.
- An input changed after a run (a click on a check box) renames the run's views "... (stale)".
- A model that cannot be read: the error reaches the console and the result file, no crash.
- A surface mesh in space (surfaces bounding no volume): the 3D panel, a click on Run optimizes
  it, the views are the triangles' and seen whole.

Environment: CVTMESH_GUI (the executable), CVTMESH_SOURCE_DIR, CVTMESH_ARTIFACTS (screenshots).
"""
import os
import subprocess
import tempfile
import time
import unittest

import xvfb_util as xu

GUI = os.environ.get("CVTMESH_GUI", "cvtmesh-gui")
SOURCE_DIR = os.environ.get("CVTMESH_SOURCE_DIR",
                            os.path.join(os.path.dirname(__file__), "..", ".."))
GEO = os.path.join(SOURCE_DIR, "geo", "cube_sphere.geo")
MENU_WIDTH = 300  # cvtmesh-gui widens Gmsh's menu tree to this
# A 3/4 view of the cube, and a window that fits the 1280x900 Xvfb screen.
VIEW_OPTIONS = """General.Trackball = 0;
General.RotationX = -65; General.RotationY = 0; General.RotationZ = -115;
General.GraphicsWidth = 820; General.GraphicsHeight = 640;
"""


class Gui(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.env = dict(os.environ, HOME=self.tmp.name)  # no user Gmsh options, no session file
        self.view = os.path.join(self.tmp.name, "view.opt")
        with open(self.view, "w") as f:
            f.write(VIEW_OPTIONS)
        self.result = os.path.join(self.tmp.name, "result.json")
        self.proc = None

    def tearDown(self):
        if self.proc and self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()
        if self.proc:
            self.log.close()
        self.tmp.cleanup()

    def start(self, *args, model=GEO):
        cmd = [GUI, model, "--result-json", self.result, *args, "--", "-clscale", "2.5",
               "-option", self.view]
        # Output to a file: a pipe nobody reads while the GUI runs would fill up and block it.
        self.log = open(os.path.join(self.tmp.name, "gui.log"), "w")
        self.proc = subprocess.Popen(cmd, env=self.env, cwd=self.tmp.name, stdout=self.log,
                                     stderr=subprocess.STDOUT)

    def result_of(self, action, timeout=120, keys=("result", "error")):
        def done():
            r = xu.read_json(self.result)
            return r if r and r.get("action") == action and any(k in r for k in keys) else None
        return xu.wait_for(done, timeout, f"the '{action}' {'/'.join(keys)} in {self.result}")

    def finish(self):
        self.proc.wait(timeout=60)
        self.log.close()
        with open(self.log.name) as f:
            return self.proc.returncode, f.read()

    def test_show_quality_then_click_run(self):
        art = xu.artifacts_dir()
        before_png = os.path.join(art, "gui_before.png")
        after_png = os.path.join(art, "gui_after.png")
        self.start("--show-quality", "--max-iterations", "8", "--exit-after-run", "2")
        wid = xu.window("Gmsh")
        q = self.result_of("quality")
        quality, self.quality_display = q["result"], q["display"]
        time.sleep(1.0)  # let the window repaint
        w, h, colours = xu.screenshot(before_png)
        # A synthetic click on the Run button, at the bottom right of the menu tree.
        _, height = xu.window_size(wid)
        xu.click(wid, MENU_WIDTH - 80, height - 39)
        self.result_of("optimize", timeout=30, keys=("status", "result", "error"))  # started
        run = self.result_of("optimize")
        time.sleep(1.0)
        xu.screenshot(after_png)
        status, out = self.finish()
        self.assertEqual(status, 0, out)

        self.assertNotIn("error", run, run)
        r = run["result"]
        self.assertEqual(r["iterations"], 8)
        # Show quality measured the mesh the run started from; the run raised its quality.
        self.assertEqual(r["before"]["number_of_elements"], quality["number_of_elements"])
        self.assertAlmostEqual(r["before"]["average_quality"], quality["average_quality"],
                               places=12)
        self.assertGreater(r["after"]["average_quality"], r["before"]["average_quality"])
        self.assertEqual(len(r["views"]), 3)
        self.assertIn(f"cvtmesh: {r['method']} on", out)  # summary in the message console
        self.check_display(run["display"], r["views"][0], r["histogram_view"])
        self.check_display(self.quality_display, quality["views"][0], quality["histogram_view"])
        # The screenshots show a drawn window (many colours: the view's colour map) that changed.
        self.assertEqual((w, h), (1280, 900))
        self.assertGreater(colours, 200)
        self.assertGreater(xu.pixels_differing(before_png, after_png), 5000)

    def check_display(self, display, q_tag, graph_tag):
        views = {v["tag"]: v for v in display["views"]}
        # The histogram: a graph (2D space) view, visible with the Q view, nothing else shown.
        self.assertIn(graph_tag, views, display)
        graph, q = views[graph_tag], views[q_tag]
        self.assertEqual(graph["type"], 2, graph)
        self.assertEqual(graph["visible"], 1, graph)
        self.assertEqual(graph["name"], "Q histogram (% of elements)")
        self.assertEqual([v["tag"] for v in display["views"] if v["visible"]],
                         sorted([q_tag, graph_tag]))
        # The Q view's colour range is the range of its values (custom, so the cut keeps it).
        self.assertEqual(q["range_type"], 2, q)
        self.assertAlmostEqual(q["custom_min"], q["min"], places=12)
        self.assertAlmostEqual(q["custom_max"], q["max"], places=12)
        self.assertGreater(q["custom_min"], 0)
        self.assertLess(q["custom_max"], 1)
        # The cut faces the camera: the plane's normal is minus the direction toward the camera.
        self.assertEqual(q["clip"], 1)
        self.assertEqual(display["mesh_clip"], 1)
        plane, toward = display["clip_plane"], display["toward_camera"]
        for k in range(3):
            self.assertAlmostEqual(plane[k], -toward[k], places=9, msg=display)
        self.assertGreater(abs(toward[2]), 0.1)  # with the test's 3/4 view, not the plane x = c

    def test_run_on_start(self):
        self.start("--run-on-start", "--max-iterations", "8", "--exit-after-run", "0")
        run = self.result_of("optimize")
        status, out = self.finish()
        self.assertEqual(status, 0, out)
        self.assertEqual(run["result"]["iterations"], 8)
        self.assertGreater(run["result"]["after"]["average_quality"],
                           run["result"]["before"]["average_quality"])

    def test_views_are_marked_stale_when_an_option_changes(self):
        self.start("--run-on-start", "--max-iterations", "4")
        wid = xu.window("Gmsh")
        run = self.result_of("optimize")
        self.assertIn("result", run, run)
        time.sleep(1.5)  # the watch compares once a second: nothing changed yet
        self.assertEqual(xu.read_json(self.result)["action"], "optimize")
        # A synthetic click on the panel's "Quality views" check box (left of the tree, below
        # Sizing): an input changed after the run.
        xu.click(wid, 51, 302)
        stale = self.result_of("stale", timeout=30, keys=("changed",))
        self.assertEqual(stale["changed"], "options")
        names = [v["name"] for v in stale["display"]["views"]]
        self.assertEqual(len(names), 4, names)  # Q, radius ratio, min angle, histogram
        for n in names:
            self.assertTrue(n.endswith(" (stale)"), names)

    def test_a_cad_ball_moves_its_boundary_on_the_cad(self):
        ball = os.path.join(self.tmp.name, "ball.geo")
        with open(ball, "w") as f:
            f.write('SetFactory("OpenCASCADE");\nSphere(1) = {0.1, 0.2, 0.3, 1};\n'
                    "Mesh.MeshSizeMax = 0.12;\nMesh.MeshSizeMin = 0.12;\n")
        # 0.3 after the GUI tests' -clscale 2.5: ~900 tets (at 0.75, 78 tets, no run improves
        # the mesh and the input comes back unchanged).
        self.start("--run-on-start", "--max-iterations", "8", "--exit-after-run", "0",
                   model=ball)
        run = self.result_of("optimize")
        status, out = self.finish()
        self.assertEqual(status, 0, out)
        self.assertGreater(run["result"]["after"]["average_quality"],
                           run["result"]["before"]["average_quality"])
        fb = run["result"]["free_boundary"]  # the default method, queried from the worker thread
        self.assertEqual(fb["geometry"], "cad")
        self.assertGreater(fb["moved"], 0)
        self.assertLessEqual(fb["hausdorff"], fb["hausdorff_bound"])

    def test_a_surface_mesh_in_space_is_optimized_and_its_triangles_shown(self):
        # An open spherical patch and a flat plate: triangles on surfaces that bound no volume.
        octant = os.path.join(self.tmp.name, "octant.geo")
        with open(octant, "w") as f:
            f.write("Point(1) = {0, 0, 0, 0.4};\nPoint(2) = {1, 0, 0, 0.4};\n"
                    "Point(3) = {0, 1, 0, 0.4};\nPoint(4) = {0, 0, 1, 0.1};\n"
                    "Circle(1) = {2, 1, 3};\nCircle(2) = {3, 1, 4};\nCircle(3) = {4, 1, 2};\n"
                    "Curve Loop(1) = {1, 2, 3};\nSurface(1) = {1};\n"
                    "Line(4) = {1, 2};\nLine(5) = {3, 1};\nCurve Loop(2) = {4, 1, 5};\n"
                    "Plane Surface(2) = {2};\n")
        self.start("--show-quality", "--exit-after-run", "0", model=octant)
        wid = xu.window("Gmsh")
        q = self.result_of("quality")
        self.assertIn("result", q, q)
        time.sleep(1.0)  # let the window repaint
        # A synthetic click on the Run button, as a user would.
        _, height = xu.window_size(wid)
        xu.click(wid, MENU_WIDTH - 80, height - 39)
        run = self.result_of("optimize")
        status, out = self.finish()
        self.assertEqual(status, 0, out)
        self.assertNotIn("error", run, run)
        r = run["result"]
        self.assertEqual(r["dim"], 3)  # the 3D panel: a surface mesh in space
        self.assertTrue(r["surface_mesh"])
        self.assertIn(f"on {r['after']['number_of_elements']} triangles", out)  # the summary
        self.assertEqual(r["before"]["number_of_elements"], q["result"]["number_of_elements"])
        self.assertGreaterEqual(r["after"]["q_min"], r["before"]["q_min"])
        # The views are the triangles': their names, Q over its range, the histogram beside it,
        # the surface seen whole (no cut).
        views = {v["tag"]: v for v in run["display"]["views"]}
        self.assertEqual([views[t]["name"] for t in r["views"]],
                         ["Q (Du-Wang)", "Radius ratio 2r/R", "Min angle"])
        qv = views[r["views"][0]]
        self.assertEqual(qv["visible"], 1)
        self.assertEqual(qv["clip"], 0)
        self.assertAlmostEqual(qv["custom_min"], r["after"]["q_min"], places=9)
        self.assertEqual(views[run["result"]["histogram_view"]]["type"], 2)

    def test_stop_button_ends_a_long_run(self):
        # Tolerance 0 never converges: 1000 iterations would take minutes.
        self.start("--method", "cvdt", "--tolerance", "0", "--max-iterations", "1000",
                   "--run-on-start", "--exit-after-run", "0")
        wid = xu.window("Gmsh")
        self.result_of("optimize", timeout=60, keys=("status",))  # running
        time.sleep(1.0)
        _, height = xu.window_size(wid)
        xu.click(wid, MENU_WIDTH - 80, height - 39)  # the Run button reads Stop while running
        run = self.result_of("optimize", timeout=60, keys=("stopped", "result", "error"))
        status, out = self.finish()
        self.assertEqual(status, 1, out)  # not a success, for --exit-after-run
        self.assertNotIn("error", run, run)
        self.assertIn("stopped; the mesh was left unchanged", run["stopped"])
        # A notice in the message console (Gmsh's "Info" level), not a red error.
        self.assertIn("Info    : cvtmesh: stopped; the mesh was left unchanged", out)
        self.assertNotIn("Error   : cvtmesh", out)

    def test_unreadable_model_is_reported_not_crashed(self):
        missing = os.path.join(self.tmp.name, "missing.geo")
        self.start("--run-on-start", "--exit-after-run", "0", model=missing)
        run = self.result_of("optimize")
        status, out = self.finish()
        self.assertEqual(status, 1, out)  # an error, reported, not a signal
        self.assertIn("empty", run["error"])
        self.assertIn("missing.geo': no such file", out)  # the open error reached the console


if __name__ == "__main__":
    unittest.main(verbosity=2)
