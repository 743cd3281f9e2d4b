#!/usr/bin/python3
"""Issue 15, item 4: the progress of `cvtmesh optimize` a person can read.

On a terminal (stderr a TTY, here a pseudo-terminal from the pty module) each phase has one line
that is redrawn in place ("\\r" + clear to the end of the line) and kept when the phase ends;
when stderr is not a terminal, plain lines (one per phase, no "\\r"); -q prints nothing; -v prints
every Lloyd iteration on a line of its own.

Usage: progress_test.py CVTMESH SOURCE_DIR
"""
import os
import pty
import re
import subprocess
import sys
import tempfile

CLI, SRC = sys.argv[1], sys.argv[2]
tmp = tempfile.mkdtemp(prefix="cvtmesh_progress_")
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run_tty(args):
    """Runs the CLI with stderr on a pseudo-terminal; returns (exit code, what it wrote there)."""
    master, slave = pty.openpty()
    # Every report redrawn: on a fast machine the whole Lloyd phase fits in one 0.1 s interval.
    env = dict(os.environ, CVTMESH_PROGRESS_INTERVAL="0")
    p = subprocess.Popen([CLI, *args], stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                         stderr=slave, cwd=tmp, env=env)
    os.close(slave)
    out = b""
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the child closed the terminal
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    return p.wait(), out.decode("utf-8", "replace")


def run_plain(args):
    p = subprocess.run([CLI, *args], capture_output=True, text=True, cwd=tmp)
    return p.returncode, p.stderr


init = os.path.join(tmp, "init.msh")
code, _ = run_plain(["mesh", os.path.join(SRC, "geo", "cube_sphere.geo"), "--set", "h=0.14",
                     "--set", "h_ball=0.1", "-o", init, "-q"])
assert code == 0, "meshing the input failed"
args = ["optimize", init, "-o", os.path.join(tmp, "out.msh"), "--method", "cvdt+swap",
        "--max-iterations", "6"]

# ---- a terminal: lines redrawn in place ------------------------------------------------------
code, err = run_tty(args)
check(code == 0, f"optimize on a terminal exits 0 (got {code})")
check("\r\x1b[K" in err, "the terminal gets redraws (\\r + clear line)")
# What stays on screen: each redraw replaces the line up to the last one before a newline.
screen = [seg.split("\r\x1b[K")[-1] for seg in err.replace("\r\n", "\n").split("\n")]
kept = [line for line in screen if line.strip()]
for phase in ("reading", "lloyd", "swap", "verify", "writing"):
    n = sum(1 for line in kept if line.startswith(phase))
    check(n == 1, f"terminal: one line kept for the phase '{phase}' (got {n})"
          + ("" if n == 1 else f": {kept}"))
lloyd = [line for line in kept if line.startswith("lloyd")]
check(bool(lloyd) and "/6" in lloyd[0] and "tol" in lloyd[0],
      f"terminal: the Lloyd line shows iteration / cap and D against the tolerance: {lloyd}")
drawn = {m.group(1) for seg in err.split("\r\x1b[K") if seg.startswith("lloyd ")
         for m in [re.search(r" it (\d+)/", seg)] if m}
check(len(drawn) >= 2, f"terminal: the Lloyd line redrawn in place as it runs: {sorted(drawn)}")
check("ETA" in err and "ETA" not in lloyd[0],
      "terminal: the Lloyd line has an ETA while it runs, not once it has ended")

# ---- not a terminal: plain lines -------------------------------------------------------------
code, err = run_plain(args)
check(code == 0, f"optimize into a pipe exits 0 (got {code})")
check("\r" not in err and "\x1b[" not in err, "pipe: no \\r and no escape sequences")
lines = err.splitlines()
for phase in ("reading", "lloyd", "swap", "verify", "writing"):
    n = sum(1 for line in lines if line.startswith(phase))
    check(n == 1, f"pipe: one line for the phase '{phase}' (got {n})")

# ---- -q: nothing; -v: every iteration --------------------------------------------------------
code, err = run_tty(args + ["-q"])
check(code == 0 and err == "", f"-q on a terminal: silent (got {code}: {err!r})")
code, err = run_plain(args + ["-v"])
n = sum(1 for line in err.splitlines() if line.startswith("lloyd"))
check(code == 0 and n >= 2, f"-v: one line per Lloyd iteration (got {n})")
check("Delaunay" in err, "-v: the Lloyd internals (cells, Delaunay timings)")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
