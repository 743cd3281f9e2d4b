#!/usr/bin/env python3
"""Checks that every #include under core/ follows the layer table of docs/architecture.md.

A file of core/<dir>/ may include headers of its own directory and of the directories listed for
it below (directly or not: the table is closed under the arrows), the standard library and the
third-party headers allowed for it. Nothing under core/ includes plugin/, convert/, bench/, FLTK or
ONELAB headers; only core/io/ includes gmsh.h. Exit 1 with one line per violation.
Usage: scripts/check_layers.py [SOURCE_DIR]
"""
import pathlib
import re
import sys

# Each layer and the layers directly below it (the CMake targets of CMakeLists.txt link the same).
BELOW = {
    "util": [],
    "geometry": ["util"],
    "mesh": ["geometry"],
    "quality": ["mesh"],
    "swap": ["quality"],
    "delaunay": ["swap"],
    "cvt": ["delaunay"],
    "smoothing": ["cvt"],
    "boundary": ["smoothing"],
    "pipeline": ["smoothing", "boundary"],
    "distributed": ["pipeline"],
    "io": ["quality"],
}
# Third-party headers a layer may use (prefix match); anything else with <...> that is not the
# standard library is a violation.
THIRD_PARTY = {
    "io": ["gmsh.h", "OpenMesh/", "nlohmann/", "tetgen.h", "pugixml.hpp"],
    "geometry": ["tetgen.h"],
    "delaunay": ["tetgen.h"],
    "quality": ["nlohmann/", "Eigen/"],  # Eigen: the FE measures (issue 16)
    "boundary": ["CGAL/"],
    "distributed": ["metis.h"],
}
FORBIDDEN = ["FL/", "onelab", "GmshSocket", "gmsh.h_cwrap", "CLI/", "pybind11"]
STD = re.compile(r"^[a-z_0-9]+(\.h)?$")  # <vector>, <cmath>, <omp.h>, <dlfcn.h>, ...
SYS_OK = {"omp.h", "dlfcn.h", "unistd.h", "fcntl.h", "sys/stat.h", "sys/types.h", "sys/wait.h",
          "sys/resource.h", "signal.h", "errno.h", "link.h", "sys/mman.h", "poll.h",
          "sys/time.h", "execinfo.h", "cxxabi.h",
          "parallel/algorithm"}  # libstdc++'s parallel mode (__gnu_parallel::sort, OpenMP)


def closure(layer):
    seen, todo = set(), [layer]
    while todo:
        for d in BELOW[todo.pop()]:
            if d not in seen:
                seen.add(d)
                todo.append(d)
    return seen


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
    bad = []
    files = sorted(p for p in (root / "core").rglob("*") if p.suffix in (".h", ".cpp"))
    for path in files:
        layer = path.relative_to(root / "core").parts[0]
        rel = path.relative_to(root)
        if layer not in BELOW:
            bad.append(f"{rel}: core/{layer}/ is not in the layer table (scripts/check_layers.py)")
            continue
        allowed = closure(layer) | {layer}
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = re.match(r'\s*#\s*include\s*([<"])([^>"]+)[>"]', line)
            if not m:
                continue
            kind, inc = m.groups()
            where = f"{rel}:{n}: #include {kind}{inc}"
            if any(f in inc for f in FORBIDDEN):
                bad.append(f"{where}: front-end header under core/")
            elif kind == '"':
                parts = inc.split("/")
                if parts[0] != "core" or len(parts) < 3:
                    bad.append(f"{where}: core/ includes only core/ headers")
                elif parts[1] not in allowed:
                    bad.append(f"{where}: {layer} may not include {parts[1]} "
                               f"(allowed: {', '.join(sorted(allowed))})")
            else:
                if inc == "gmsh.h" and layer != "io":
                    bad.append(f"{where}: only core/io/ calls Gmsh")
                elif any(inc.startswith(t) for t in THIRD_PARTY.get(layer, [])):
                    pass
                elif STD.match(inc) or inc in SYS_OK:
                    pass
                else:
                    bad.append(f"{where}: third-party header not allowed in {layer}")
    for b in bad:
        print(b)
    print(f"check_layers: {len(files)} files under core/, {len(bad)} violations")
    return 1 if bad or not files else 0


if __name__ == "__main__":
    sys.exit(main())
