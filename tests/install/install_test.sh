#!/usr/bin/env bash
# Installs the build into a temporary prefix and uses it as a user would: the CLI and front ends
# run, docs/examples builds as a standalone CMake project (find_package(cvtmesh)) and runs, a
# program builds with `pkg-config cvtmesh`, and Debian's python3 imports the module from the
# prefix's dist-packages.   Usage: install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
P=$(mktemp -d /tmp/cvtmesh-install-XXXXXX)
trap 'rm -rf "$P"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$BUILD" --prefix "$P" > "$P.log" 2>&1 || { cat "$P.log"; fail "cmake --install"; }
rm -f "$P.log"
for f in bin/cvtmesh bin/cvtmesh-gui bin/cvtmesh-onelab include/cvtmesh/cvtmesh.h \
         include/cvtmesh/core/io/read_mesh.h include/cvtmesh/plugin/gmsh_inprocess.h \
         lib/cmake/cvtmesh/cvtmeshConfig.cmake lib/pkgconfig/cvtmesh.pc \
         lib/libcvtmesh_pipeline.a lib/libcvtmesh_io.a share/cvtmesh/geo/cube_sphere.geo; do
  [ -e "$P/$f" ] || fail "not installed: $f"
done
"$P/bin/cvtmesh" --version | grep -q "cvtmesh" || fail "installed cvtmesh --version"
"$P/bin/cvtmesh" stats "$P/share/cvtmesh/geo/quad.geo" > /dev/null || fail "installed cvtmesh stats"

# docs/examples against the installed package.
cmake -S "$SRC/docs/examples" -B "$P/ex" -G Ninja -DCMAKE_PREFIX_PATH="$P" > "$P/ex.log" 2>&1 ||
  { cat "$P/ex.log"; fail "configure docs/examples against the package"; }
cmake --build "$P/ex" > "$P/ex.log" 2>&1 || { cat "$P/ex.log"; fail "build docs/examples"; }
(cd "$P" && ex/read_optimize_write "$SRC/geo/quad.geo" quad_out.msh) > "$P/run.log" 2>&1 ||
  { cat "$P/run.log"; fail "read_optimize_write"; }
grep -q "average quality" "$P/run.log" || { cat "$P/run.log"; fail "read_optimize_write table"; }
"$P/bin/cvtmesh" check "$P/quad_out.msh" > /dev/null || fail "example output refused by check"
(cd "$P" && ex/optimize_current_model "$SRC/geo/cube_sphere.geo" cs_out.msh) > "$P/run.log" 2>&1 ||
  { cat "$P/run.log"; fail "optimize_current_model"; }
"$P/bin/cvtmesh" check "$P/cs_out.msh" > /dev/null || fail "example output refused by check"

# pkg-config: compile and link a program with the flags alone.
cat > "$P/pc.cpp" <<'CPP'
#include <cvtmesh/cvtmesh.h>
#include <iostream>
int main(int argc, char** argv) {
  const cvtmesh::MeshData d = cvtmesh::read_mesh(argv[1]);
  std::cout << cvtmesh::quality_stats(d.tri, "in").nb_elements << "\n";
}
CPP
PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config --exists cvtmesh || fail "pkg-config cvtmesh"
# shellcheck disable=SC2046
g++ -std=c++20 -O0 "$P/pc.cpp" -o "$P/pc" $(PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config --cflags --libs cvtmesh) ||
  fail "build with pkg-config"
n=$("$P/pc" "$SRC/geo/quad.geo")
[ "$n" -gt 100 ] || fail "pkg-config program read $n triangles"

# Python: the module where Debian's python3 looks under such a prefix.
mod=$(find "$P/lib" -name 'cvtmesh*.so' -path '*dist-packages*' | head -1)
[ -n "$mod" ] || fail "Python module not installed in a dist-packages directory"
rel=${mod#"$P/"}
rel=$(dirname "$rel")
/usr/bin/python3 - "$rel" <<'PY' || fail "dist-packages directory not on Debian's sys.path for /usr/local"
import sys
rel = sys.argv[1]
assert "/usr/local/" + rel in sys.path, (rel, sys.path)
PY
PYTHONPATH="$P/$rel" /usr/bin/python3 -c "import cvtmesh; assert 'cvdt' in ' '.join(cvtmesh.methods())" ||
  fail "import cvtmesh from the prefix"
echo "install test: ok ($P)"
