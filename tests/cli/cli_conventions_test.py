#!/usr/bin/env python3
"""One CLI convention across every subcommand (docs/cli.md): exit codes (1 usage, 2 bad input,
3 cannot write, 5 check found problems), -q silence, -v and --threads accepted everywhere,
--no-clobber / --force, help texts from the option schema and the method registry, and one JSON
schema for 2D and 3D with integers as integers.

Usage: cli_conventions_test.py CVTMESH_CLI SOURCE_DIR   (PYTHONPATH: the built module, for the
method registry)
"""
import json
import os
import re
import subprocess
import sys
import tempfile

CLI, SRC = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
QUAD = os.path.join(SRC, "geo", "quad.geo")
CUBE = os.path.join(SRC, "geo", "cube_sphere.geo")
tmp = tempfile.mkdtemp(prefix="cvtmesh-cli-")
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(*args, cwd=tmp):
    p = subprocess.run([CLI, *args], capture_output=True, text=True, cwd=cwd)
    return p.returncode, p.stdout, p.stderr


def out(name):
    return os.path.join(tmp, name)


# A quick successful run of every subcommand that reads an input (args after the input).
quick = {
    "stats": [QUAD],
    "convert": [QUAD, out("c.msh")],
    "optimize": [QUAD, "-o", out("o.msh"), "--max-iterations", "2"],
    "mesh": [QUAD, "-o", out("m.msh")],
    "check": [QUAD],
    "perturb": [QUAD, "-o", out("p.msh"), "--cluster"],
    "compare": [CUBE, "--size-factor", "4", "--no-baselines", "--max-iterations", "2"],
}
subcommands = list(quick) + ["bench"]

# ---- help: from the schema and the registry ---------------------------------------------------
code, text, _ = run("--help")
check(code == 0, "cvtmesh --help exits 0")
for sub in subcommands:
    check(re.search(r"\b" + sub + r"\b", text) is not None, f"--help lists {sub}")
    code, text_sub, _ = run(sub, "--help")
    check(code == 0, f"{sub} --help exits 0")
    check("{false}" not in text_sub and "{true}" not in text_sub,
          f"{sub} --help has no {{false}} suffixes")
    for flag in ("-q", "-v", "--threads"):
        # The global options are listed by the main help and accepted after the subcommand.
        check(flag in text, f"cvtmesh --help lists {flag}")
try:
    import cvtmesh  # the built module: the method registry
    methods = set(cvtmesh.methods(3)) | set(cvtmesh.methods(2))
except ImportError:
    methods = set()
    print("note: the Python module is not on PYTHONPATH: method list not checked")
_, opt_help, _ = run("optimize", "--help")
for m in methods:
    check(re.search(r"^\s+" + re.escape(m) + r" \(", opt_help, re.M) is not None,
          f"optimize --help lists method {m}")

# ---- exit codes ---------------------------------------------------------------------------
for sub in subcommands:
    code, _, err = run(sub, "--no-such-option")
    check(code == 1, f"{sub} --no-such-option exits 1 (usage), got {code}: {err.strip()}")
for sub in quick:
    code, _, err = run(sub)
    check(code == 1, f"{sub} without its input exits 1 (usage), got {code}")
    missing = out("does-not-exist.msh")
    code, _, err = run(sub, missing, *quick[sub][1:])
    check(code == 2 and "does-not-exist.msh" in err,
          f"{sub} on a missing file exits 2 and names it, got {code}: {err.strip()}")
    code, _, err = run(*[sub, *quick[sub], "--threads", "0"])
    check(code == 1, f"{sub} --threads 0 exits 1 (usage), got {code}")

code, _, err = run("optimize", QUAD, "-o", out("u.msh"), "--method", "no-such-method")
check(code == 2, f"an unknown method exits 2 (bad input), got {code}: {err.strip()}")
code, _, err = run("convert", QUAD, os.path.join(tmp, "no-dir", "x.msh"))
check(code == 3, f"an output in a missing directory exits 3, got {code}: {err.strip()}")
code, _, err = run("convert", QUAD, out("c.msh"))
code, _, err = run("convert", QUAD, out("c.msh"), "--no-clobber")
check(code == 3 and "--force" in err, f"--no-clobber on an existing file exits 3 naming --force, "
      f"got {code}: {err.strip()}")
code, _, err = run("convert", QUAD, out("c.msh"), "--no-clobber", "--force")
check(code == 0, f"--force replaces it, got {code}: {err.strip()}")
bad = out("inverted.mesh")
with open(bad, "w") as f:  # one tet with negative volume: check reports it (5)
    f.write("MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
            "0 0 1 0\nTetrahedra\n1\n1 3 2 4 1\nEnd\n")
code, _, err = run("check", bad)
check(code in (2, 5), f"check of an inverted tet exits 2 or 5, got {code}: {err.strip()}")

# ---- -q silence, -v and --threads accepted ------------------------------------------------
for sub, args in quick.items():
    code, _, err = run(sub, *args, "-q")
    check(code == 0 and err == "", f"{sub} -q: exit 0 and nothing on stderr, got {code}: {err!r}")
    code, _, err = run("-q", sub, *args)
    check(code == 0 and err == "", f"-q before {sub}: silent, got {code}: {err!r}")
    code, _, err = run(sub, *args, "-v", "--threads", "1")
    check(code == 0, f"{sub} -v --threads 1 accepted, got {code}: {err.strip()}")

# ---- JSON: one object per mesh, the same keys in 2D and 3D, integers as integers ----------
MESH_KEYS = {"label", "dim", "number_of_elements", "q_0.7_1.0", "q_0.5_0.7", "q_0.3_0.5",
             "q_0.0_0.3", "inverted", "q_min", "q_max", "average_quality", "min_angle",
             "max_angle", "angle", "average_radius_ratio"}
COUNTS = {"number_of_elements", "q_0.7_1.0", "q_0.5_0.7", "q_0.3_0.5", "q_0.0_0.3", "inverted"}


def check_mesh_object(o, tag):
    check(isinstance(o, dict), f"{tag}: an object")
    if not isinstance(o, dict):
        return set()
    check(MESH_KEYS <= set(o), f"{tag}: schema keys, missing {MESH_KEYS - set(o)}")
    for k in COUNTS & set(o):
        check(isinstance(o[k], int), f"{tag}: {k} is an integer ({o[k]!r})")
    check(o.get("q_0.7_1.0", 0) + o.get("q_0.5_0.7", 0) + o.get("q_0.3_0.5", 0) +
          o.get("q_0.0_0.3", 0) == o.get("number_of_elements"), f"{tag}: the bins add up")
    return set(o)


keys = {}
for model, dim in ((QUAD, 2), (CUBE, 3)):
    code, text, err = run("stats", model, "--format", "json")
    check(code == 0, f"stats --format json on {dim}D")
    try:
        o = json.loads(text)
    except ValueError as e:
        check(False, f"stats --format json parses ({e}): {text[:200]}")
        continue
    keys[dim] = check_mesh_object(o, f"stats {dim}D")
    check(o.get("dim") == dim, f"stats {dim}D: dim")
if 2 in keys and 3 in keys:
    check(keys[2] == keys[3], f"the same keys in 2D and 3D: {keys[2] ^ keys[3]}")

report = out("report.json")
code, text, err = run("optimize", QUAD, "-o", out("o2.msh"), "--max-iterations", "3",
                      "--format", "json", "--report", report, "-q")
check(code == 0 and err == "", f"optimize --format json --report -q, got {code}: {err!r}")
try:
    stdout_json = json.loads(text)
    with open(report) as f:
        file_json = json.load(f)
    check(stdout_json == file_json, "optimize: --report holds what --format json prints")
    for k in ("schema", "method", "iterations", "converged", "before", "after"):
        check(k in file_json, f"optimize report has {k}")
    check(isinstance(file_json.get("iterations"), int), "optimize report: iterations an integer")
    check(0 < file_json.get("iterations", 0) <= 3, "optimize report: iterations within the cap")
    check_mesh_object(file_json.get("before"), "optimize report before")
    check_mesh_object(file_json.get("after"), "optimize report after")
except (ValueError, OSError) as e:
    check(False, f"optimize JSON parses: {e}")

code, text, err = run("compare", *quick["compare"], "--format", "json", "-q")
try:
    o = json.loads(text)
    check(isinstance(o.get("meshes"), list) and len(o["meshes"]) >= 2,
          "compare --format json: a list of meshes")
    for i, m in enumerate(o.get("meshes", [])):
        check_mesh_object(m, f"compare mesh {i}")
except ValueError as e:
    check(False, f"compare JSON parses: {e}")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
