"""Helpers for the GUI tests that run under xvfb-run (DISPLAY set): waiting, windows, screenshots.

xdotool and ImageMagick's import/identify/compare come from Debian (scripts/setup.sh).
"""
import json
import os
import subprocess
import time


def wait_for(predicate, timeout, what):
    """Polls predicate() every 0.2 s; returns its value or raises AssertionError after timeout."""
    end = time.time() + timeout
    while time.time() < end:
        value = predicate()
        if value:
            return value
        time.sleep(0.2)
    raise AssertionError(f"timed out after {timeout} s waiting for {what}")


def read_json(path):
    """The JSON object in path, or None if it does not exist (yet)."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def window(name, timeout=60):
    """The id of the first visible window whose title contains name."""
    def find():
        r = subprocess.run(["xdotool", "search", "--onlyvisible", "--name", name],
                           capture_output=True, text=True)
        ids = r.stdout.split()
        return ids[0] if ids else None
    return wait_for(find, timeout, f"a window named '{name}'")


def window_name(wid):
    return subprocess.run(["xdotool", "getwindowname", wid], capture_output=True,
                          text=True).stdout.strip()


def window_size(wid):
    out = subprocess.run(["xdotool", "getwindowgeometry", "--shell", wid], capture_output=True,
                         text=True).stdout
    geo = dict(line.split("=", 1) for line in out.split() if "=" in line)
    return int(geo["WIDTH"]), int(geo["HEIGHT"])


def click(wid, x, y):
    """Left click at (x, y) relative to the window's top-left corner."""
    subprocess.run(["xdotool", "mousemove", "--window", wid, str(x), str(y), "click", "1"],
                   check=True)


def screenshot(path):
    """The whole X screen as PNG; returns (width, height, number of colours)."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    subprocess.run(["import", "-window", "root", path], check=True)
    out = subprocess.run(["identify", "-format", "%w %h %k", path], capture_output=True,
                         text=True, check=True).stdout.split()
    return int(out[0]), int(out[1]), int(out[2])


def pixels_differing(a, b):
    """Number of pixels that differ between two images of the same size."""
    r = subprocess.run(["compare", "-metric", "AE", a, b, "null:"], capture_output=True,
                       text=True)
    return int(float(r.stderr.split()[0]))


def artifacts_dir():
    d = os.environ.get("CVTMESH_ARTIFACTS") or os.path.join(os.getcwd(), "artifacts")
    os.makedirs(d, exist_ok=True)
    return d
