#!/usr/bin/python3
"""The Python module `cvtmesh` on the inputs the CLI took first: surface meshes in space (triangles
on surfaces that bound no volume), 2D meshes with quadrangles and free curves, order-2 hybrid
meshes (tet10 on prism18) and volumes that overlap or touch without a common mesh. Each is
optimized in place in the live Gmsh model: no refusal, the same model, entities and physical
groups, the elements of every entity of the expected kinds and counts, and the quality read back
through Gmsh's API (cvtmesh.quality() on the model, and measures computed here from the nodes
and elements gmsh returns) not worse than before.

Environment: PYTHONPATH has the module's directory.
"""
import math
import os
import tempfile
import unittest

import gmsh
import cvtmesh


def physical_groups():
    return [(d, t, gmsh.model.getPhysicalName(d, t),
             sorted(gmsh.model.getEntitiesForPhysicalGroup(d, t)))
            for d, t in gmsh.model.getPhysicalGroups()]


def elements():
    """(dim, entity tag, element type) -> (element tags, node tags) of the model."""
    out = {}
    for d, t in gmsh.model.getEntities():
        types, tags, nds = gmsh.model.mesh.getElements(d, t)
        for ty, tg, nd in zip(types, tags, nds):
            out[(d, t, int(ty))] = (list(tg), list(nd))
    return out


def counts(els, dims=(0, 1, 2, 3)):
    return {k: len(v[0]) for k, v in els.items() if k[0] in dims}


def node_xyz():
    tags, xyz, _ = gmsh.model.mesh.getNodes(-1, -1, includeBoundary=False,
                                            returnParametricCoord=False)
    return {int(t): tuple(xyz[3 * i:3 * i + 3]) for i, t in enumerate(tags)}


def nodes_on(dim):
    """Node tag -> xyz of the nodes classified on entities of dimension `dim`."""
    out = {}
    for d, t in gmsh.model.getEntities(dim):
        tags, xyz, _ = gmsh.model.mesh.getNodes(d, t, includeBoundary=False,
                                                returnParametricCoord=False)
        for i, tag in enumerate(tags):
            out[int(tag)] = tuple(xyz[3 * i:3 * i + 3])
    return out


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(sum(x * x for x in a))


def triangle_min_angles():
    """Min angle (degrees) of every triangle of the model (corners of any order), from gmsh."""
    xyz = node_xyz()
    out = []
    for (d, _, ty), (tags, nds) in elements().items():
        if d != 2 or ty not in (2, 9):
            continue
        npe = len(nds) // len(tags)
        for e in range(len(tags)):
            p = [xyz[int(n)] for n in nds[npe * e:npe * e + 3]]
            angles = []
            for k in range(3):
                u, v = sub(p[(k + 1) % 3], p[k]), sub(p[(k + 2) % 3], p[k])
                c = sum(u[i] * v[i] for i in range(3)) / (norm(u) * norm(v))
                angles.append(math.degrees(math.acos(max(-1.0, min(1.0, c)))))
            out.append(min(angles))
    return out


def quad_scaled_jacobians():
    """Scaled Jacobian of every planar quadrangle (min over its corners of the normalized cross
    product of its two edges there, z component), from gmsh's nodes and elements."""
    xyz = node_xyz()
    out = []
    for (d, _, ty), (tags, nds) in elements().items():
        if d != 2 or ty != 3:
            continue
        for e in range(len(tags)):
            p = [xyz[int(n)] for n in nds[4 * e:4 * e + 4]]
            sj = min(cross(sub(p[(k + 1) % 4], p[k]), sub(p[(k + 3) % 4], p[k]))[2] /
                     (norm(sub(p[(k + 1) % 4], p[k])) * norm(sub(p[(k + 3) % 4], p[k])))
                     for k in range(4))
            out.append(sj)
    return out


class InProcessInputs(unittest.TestCase):
    def setUp(self):
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("Mesh.RandomSeed", 1)

    def tearDown(self):
        gmsh.finalize()

    def geo(self, text, name):
        # The .geo text through a temporary file: gmsh.open is how a script loads a model.
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, name + ".geo")
            with open(path, "w") as f:
                f.write(text)
            gmsh.open(path)

    def assert_not_worse(self, before, after):
        # The rows the optimizers never let get worse (their no-worse checks).
        self.assertGreaterEqual(after["q_min"], before["q_min"] - 1e-12)
        self.assertGreater(after["number_of_elements"], 0)

    # 1. A surface mesh in space: a spherical patch (CAD) and a flat plate, open, with groups.
    def test_surface_mesh_in_space_is_optimized_on_its_cad_in_place(self):
        self.geo("Point(1) = {0, 0, 0, 0.15};\nPoint(2) = {1, 0, 0, 0.15};\n"
                 "Point(3) = {0, 1, 0, 0.15};\nPoint(4) = {0, 0, 1, 0.04};\n"
                 "Circle(1) = {2, 1, 3};\nCircle(2) = {3, 1, 4};\nCircle(3) = {4, 1, 2};\n"
                 "Curve Loop(1) = {1, 2, 3};\nSurface(1) = {1};\n"
                 "Line(4) = {1, 2};\nLine(5) = {3, 1};\nCurve Loop(2) = {4, 1, 5};\n"
                 "Plane Surface(2) = {2};\n"
                 "Physical Surface(\"shell\", 10) = {1, 2};\n"
                 "Physical Curve(\"rim\", 11) = {2, 3, 4, 5};\n", "octant")
        gmsh.model.mesh.generate(2)
        groups = physical_groups()
        entities = gmsh.model.getEntities()
        els0 = elements()
        before = cvtmesh.quality()
        angles0 = triangle_min_angles()
        surface0 = nodes_on(2)
        curves0 = {k: v for k, v in els0.items() if k[0] < 2}

        table = cvtmesh.optimize(quality_views=True)  # a surface mesh: no refusal

        self.assertEqual(table["dim"], 3)
        self.assertTrue(table["surface_mesh"])
        self.assertEqual(gmsh.model.list(), ["octant"])
        self.assertEqual(physical_groups(), groups)
        self.assertEqual(gmsh.model.getEntities(), entities)
        els1 = elements()
        # Lines and points kept as they were (tags and nodes); triangles only, on both surfaces.
        self.assertEqual({k: v for k, v in els1.items() if k[0] < 2}, curves0)
        self.assertEqual(sorted(k for k in els1 if k[0] == 2), [(2, 1, 2), (2, 2, 2)])
        self.assertEqual(sorted(k for k in els1 if k[0] == 3), [])
        # The model holds the optimized mesh: its quality is the table's, not worse than before.
        after = cvtmesh.quality()
        self.assertEqual(after["number_of_elements"], table["after"]["number_of_elements"])
        self.assertAlmostEqual(after["q_min"], table["after"]["q_min"], places=12)
        self.assert_not_worse(before, after)
        self.assertGreaterEqual(min(triangle_min_angles()), min(angles0) - 1e-9)
        self.assertEqual(after["number_of_elements"], sum(counts(els1, (2,)).values()))
        # It was optimized: surface nodes moved.
        surface1 = nodes_on(2)
        moved = sum(1 for t, p in surface1.items() if t in surface0 and surface0[t] != p)
        self.assertGreater(moved, 0)
        # On the CAD: the nodes of the spherical patch on the unit sphere, the plate's in z = 0.
        xyz1 = node_xyz()
        for t in gmsh.model.mesh.getNodes(2, 1, includeBoundary=True)[0]:
            self.assertAlmostEqual(norm(xyz1[int(t)]), 1.0, places=9)
        for t in gmsh.model.mesh.getNodes(2, 2, includeBoundary=False)[0]:
            self.assertEqual(surface1[int(t)][2], 0.0)
        # The quality views are the triangles', one value per triangle, keyed by their tags.
        self.assertEqual(len(table["views"]), 3)
        names = [gmsh.option.getString(f"View[{gmsh.view.getIndex(v)}].Name")
                 for v in table["views"]]
        self.assertEqual(names, ["Q (Du-Wang)", "Radius ratio 2r/R", "Min angle"])
        kind, tags, data, _, _ = gmsh.view.getModelData(table["views"][0], 0)
        self.assertEqual(kind, "ElementData")
        tri_tags = sorted(t for k, v in els1.items() if k[0] == 2 for t in v[0])
        self.assertEqual(sorted(int(t) for t in tags), tri_tags)
        self.assertAlmostEqual(min(d[0] for d in data), after["q_min"], places=12)

    # 2a. An all-quadrangle 2D mesh (tutorial t11, coarser): the quadrangles smoothed in place.
    def test_quadrangle_mesh_is_smoothed_in_place(self):
        self.geo("Point(1) = {-1.25, -.5, 0}; Point(2) = {1.25, -.5, 0};\n"
                 "Point(3) = {1.25, 1.25, 0};  Point(4) = {-1.25, 1.25, 0};\n"
                 "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                 "Curve Loop(4) = {1, 2, 3, 4}; Plane Surface(100) = {4};\n"
                 "Field[1] = MathEval;\n"
                 "Field[1].F = \"0.06*(1.0+30.*(y-x*x)*(y-x*x) + (1-x)*(1-x))\";\n"
                 "Background Field = 1;\nRecombine Surface{100};\n"
                 "Physical Surface(\"square\", 5) = {100};\n", "t11")
        gmsh.model.mesh.generate(2)
        els0 = elements()
        self.assertEqual(sorted(k for k in els0 if k[0] == 2), [(2, 100, 3)],
                         "not the case under test: quadrangles only")
        groups = physical_groups()
        xyz0 = node_xyz()
        boundary0 = {t: p for t, p in xyz0.items() if t not in nodes_on(2)}
        sj0 = quad_scaled_jacobians()

        table = cvtmesh.optimize(quality_views=True)  # no triangle: no view, no error

        self.assertEqual(table["dim"], 2)
        self.assertEqual(table["views"], [])
        self.assertEqual(physical_groups(), groups)
        els1 = elements()
        self.assertEqual(els1, els0)  # every element kept: same tags, same nodes
        xyz1 = node_xyz()
        self.assertEqual(set(xyz1), set(xyz0))
        self.assertEqual({t: xyz1[t] for t in boundary0}, boundary0)  # boundary nodes fixed
        moved = sum(1 for t in xyz1 if xyz1[t] != xyz0[t])
        self.assertGreater(moved, 0, "the quadrangles were not smoothed")
        sj1 = quad_scaled_jacobians()
        self.assertGreaterEqual(min(sj1), min(sj0) - 1e-12)
        self.assertGreater(min(sj1), 0)

    # 2b. Triangles and quadrangles side by side, and a free curve (lines on no element).
    def test_hybrid_2d_mesh_with_a_free_curve_is_optimized_in_place(self):
        self.geo("Point(1) = {0,0,0,0.1}; Point(2) = {1,0,0,0.1}; Point(3) = {1,1,0,0.1};\n"
                 "Point(4) = {0,1,0,0.1}; Point(5) = {2,0,0,0.1}; Point(6) = {2,1,0,0.1};\n"
                 "Point(7) = {0,2,0,0.1}; Point(8) = {2,2,0,0.1};\n"
                 "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};\n"
                 "Line(5) = {2,5}; Line(6) = {5,6}; Line(7) = {6,3};\n"
                 "Line(9) = {7,8};\n"
                 "Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};\n"
                 "Curve Loop(2) = {5,6,7,-2}; Plane Surface(2) = {2};\n"
                 "Physical Surface(\"both\", 7) = {1, 2};\n"
                 "Physical Curve(\"outer\", 8) = {1, 3, 4, 5, 6, 7};\n"
                 "Physical Curve(\"free\", 9) = {9};\n"
                 "Recombine Surface{1};\n", "hybrid2d")
        gmsh.model.mesh.generate(2)
        els0 = elements()
        self.assertIn((2, 1, 3), els0)
        self.assertIn((2, 2, 2), els0)
        groups = physical_groups()
        before = cvtmesh.quality()
        sj0 = quad_scaled_jacobians()
        xyz0 = node_xyz()

        table = cvtmesh.optimize(quality_views=True)

        self.assertEqual(table["dim"], 2)
        self.assertEqual(physical_groups(), groups)
        els1 = elements()
        self.assertEqual(sorted(els1), sorted(els0))  # the same kinds of element per entity
        self.assertEqual(els1[(2, 1, 3)], els0[(2, 1, 3)])  # quadrangles kept
        self.assertEqual(els1[(1, 9, 1)], els0[(1, 9, 1)])  # the free curve kept
        xyz1 = node_xyz()
        for t in els0[(1, 9, 1)][1]:
            self.assertEqual(xyz1[int(t)], xyz0[int(t)])
        after = cvtmesh.quality()
        self.assertEqual(after["number_of_elements"], len(els1[(2, 2, 2)][0]))
        self.assert_not_worse(before, after)
        self.assertGreaterEqual(min(quad_scaled_jacobians()), min(sj0) - 1e-12)
        quad_nodes = {int(t) for t in els0[(2, 1, 3)][1]}
        self.assertGreater(sum(1 for t in quad_nodes if xyz1[t] != xyz0[t]), 0)
        kind, tags, data, _, _ = gmsh.view.getModelData(table["views"][0], 0)
        self.assertEqual(sorted(int(t) for t in tags), sorted(els1[(2, 2, 2)][0]))

    # 3a. Order 2, hybrid: tets on a layer of prisms (tutorial t3's kind), tet10 and prism18.
    def test_order2_hybrid_mesh_is_optimized_in_place(self):
        self.geo("Point(1)={0,0,0,0.3};Point(2)={1,0,0,0.3};Point(3)={1,1,0,0.3};"
                 "Point(4)={0,1,0,0.3};\n"
                 "Line(1)={1,2};Line(2)={2,3};Line(3)={3,4};Line(4)={4,1};\n"
                 "Curve Loop(1)={1,2,3,4};Plane Surface(1)={1};\n"
                 "a[] = Extrude{0,0,0.2}{Surface{1}; Layers{2}; Recombine;};\n"
                 "b[] = Extrude{0,0,0.8}{Surface{a[0]};};\n"
                 "Physical Volume(\"prisms\", 1) = {a[1]};\n"
                 "Physical Volume(\"tets\", 2) = {b[1]};\n", "prisms2")
        gmsh.model.mesh.generate(3)
        gmsh.model.mesh.setOrder(2)
        els0 = elements()
        prisms = [k for k in els0 if k[2] == 13]
        tets = [k for k in els0 if k[2] == 11]
        self.assertTrue(prisms and tets, "not the case under test: prism18 and tet10")
        groups = physical_groups()
        before = cvtmesh.quality()

        table = cvtmesh.optimize(quality_views=True)

        self.assertEqual(table["dim"], 3)
        self.assertFalse(table["surface_mesh"])
        self.assertEqual(physical_groups(), groups)
        els1 = elements()
        for k in prisms:  # the prisms kept with all their nodes
            self.assertEqual(els1[k], els0[k])
        # The same kinds per entity: still order 2 (tet10, tri6, quad9, line3), nothing linear.
        self.assertEqual(sorted(els1), sorted(els0))
        xyz = node_xyz()
        for k in tets:
            tg, nd = els1[k]
            self.assertEqual(len(nd), 10 * len(tg))
            for n in nd:
                self.assertIn(int(n), xyz)
        after = cvtmesh.quality()
        self.assertEqual(after["number_of_elements"], sum(len(els1[k][0]) for k in tets))
        self.assert_not_worse(before, after)
        self.assertGreater(after["average_quality"], before["average_quality"])

    # 3b. Volumes apart: two OCC boxes that overlap, and two that touch, without a common mesh.
    def volumes_apart(self, dx):
        gmsh.model.add("boxes")
        gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
        gmsh.model.occ.addBox(dx, 0.3, 0.2, 1, 1, 1)
        gmsh.model.occ.synchronize()
        gmsh.model.addPhysicalGroup(3, [1], 1)
        gmsh.model.setPhysicalName(3, 1, "first")
        gmsh.model.addPhysicalGroup(3, [2], 2)
        gmsh.option.setNumber("Mesh.MeshSizeMax", 0.25)
        gmsh.model.mesh.generate(3)
        els0 = elements()
        groups = physical_groups()
        entities = gmsh.model.getEntities()
        before = cvtmesh.quality()

        table = cvtmesh.optimize(quality_views=True)

        self.assertEqual(table["dim"], 3)
        self.assertFalse(table["surface_mesh"])
        self.assertEqual(physical_groups(), groups)
        self.assertEqual(gmsh.model.getEntities(), entities)
        els1 = elements()
        # Both volumes still meshed with tets, every surface with triangles; nothing else.
        self.assertEqual(sorted(els1), sorted(els0))
        for k in els1:
            self.assertGreater(len(els1[k][0]), 0)
        after = cvtmesh.quality()
        self.assertEqual(after["number_of_elements"], sum(counts(els1, (3,)).values()))
        self.assert_not_worse(before, after)

    def test_overlapping_volumes_are_optimized_in_place(self):
        self.volumes_apart(0.5)

    def test_touching_volumes_are_optimized_in_place(self):
        self.volumes_apart(1.0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
