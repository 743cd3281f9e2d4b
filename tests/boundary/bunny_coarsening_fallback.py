#!/usr/bin/python3
"""igl_bunny with the default method and no auto_refine: its run with the surface coarsening ends
past the Hausdorff bound, and optimize() runs it again without the coarsening. That run takes the
first run's first Lloyd phase instead of computing it again (FirstLloyd in
core/pipeline/optimize.cpp: same input and options up to there). Checked here: where the fallback
happens, its note says that the first Lloyd phase was not run again, and the output is
byte-identical to a run given `--coarsen-surface 0` from the start (which runs its own Lloyd).
Where the coarsened run holds the bound (no fallback), the run must not say it reused anything.
CTest label `long` (about 80 s on 2 cores).

Usage: bunny_coarsening_fallback.py CVTMESH_CLI SOURCE_DIR
"""
import filecmp
import os
import subprocess
import sys
import tempfile


def main():
    cli, source = sys.argv[1], sys.argv[2]
    off = os.path.join(source, "..", "shared", "data", "models", "igl_bunny.off")
    if not os.path.exists(off):
        print("skipped: no igl_bunny.off at", off)
        return 0
    with tempfile.TemporaryDirectory() as tmp:
        init = os.path.join(tmp, "init.msh")
        a, b = os.path.join(tmp, "a.msh"), os.path.join(tmp, "b.msh")
        subprocess.run([cli, "convert", off, init, "--binary"], check=True, capture_output=True)
        run = subprocess.run([cli, "optimize", init, "-o", a, "--binary", "--no-auto-refine"],
                             capture_output=True, text=True)
        log = run.stdout + run.stderr
        assert run.returncode == 0, log
        reused = "is the run's with the surface coarsening, not run again" in log
        if "without the surface coarsening is kept instead" not in log:
            assert not reused, "a Lloyd phase reused without the fallback:\n" + log
            print("the coarsened run held the bound: no fallback, nothing reused")
            return 0
        assert reused, "the fallback ran its first Lloyd phase again:\n" + log
        plain = subprocess.run([cli, "optimize", init, "-o", b, "--binary", "--no-auto-refine",
                                "--coarsen-surface", "0"], capture_output=True, text=True)
        assert plain.returncode == 0, plain.stdout + plain.stderr
        assert filecmp.cmp(a, b, shallow=False), (
            "the fallback's result differs from the run without the coarsening:\n" + log)
        print("fallback with the first Lloyd reused: the same file as --coarsen-surface 0")
    return 0


if __name__ == "__main__":
    sys.exit(main())
