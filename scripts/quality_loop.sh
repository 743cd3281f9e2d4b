#!/usr/bin/env bash
# The corpus quality loop the docs' before/after tables name as `loop.sh BIN OUT MODEL...`
# (docs/reproduction.md, stops 40-45): each model's Init made once by `cvtmesh convert` (Gmsh's
# mesh of the model with its optimizer, kept in INITS, binary .msh), then `BIN optimize` with the
# defaults and `BIN stats` of the output. One line per model:
#   model rc=EXIT Q_min average min_dihedral max_dihedral time_step element_time_step seconds
# (seconds: wall time of optimize.) Nothing is asserted: compare two binaries' lines.
#
# Usage: scripts/quality_loop.sh BIN OUTDIR MODEL...
#   MODEL: t2 ... t21 (Gmsh's tutorials, from Debian's gmsh-doc), femur, cube_sphere (geo/), or a
#   model of ../shared/data/models by its name without extension (igl_bunny, mmg_torus, ...).
#   The loop's usual 23: femur cube_sphere t2 t3 t5 t13 t14 t15 t16 t18 t19 t20 mmg_cube mmg_torus
#   mmg_tinyBoxt igl_decimated-knight igl_bunny igl_screwdriver igl_fandisk igl_fertility
#   igl_3holes igl_cheburashka cgalswig_elephant
#   INITS=dir (default ~/.cache/cvtmesh/inits): where the Inits are kept (made by BIN if missing).
set -uo pipefail
[ $# -ge 3 ] || { sed -n 2,16p "$0" >&2; exit 2; }
BIN=$(realpath "$1")
OUT=$(realpath -m "$2")
shift 2
ROOT=$(cd "$(dirname "$0")/.." && pwd)
MODELS_DIR=${MODELS_DIR:-$(cd "$ROOT/.." && pwd)/shared/data/models}
TUT_SRC=${TUT_SRC:-/usr/share/doc/gmsh-doc/doc/gmsh/tutorial}
INITS=${INITS:-$HOME/.cache/cvtmesh/inits}
mkdir -p "$OUT" "$INITS"

init_of() {  # makes $INITS/$1.init.msh if missing; prints nothing
  local m=$1 init="$INITS/$1.init.msh" src dir
  [ -f "$init" ] && return 0
  case $m in
    t[0-9]*)
      dir=$(mktemp -d /tmp/cvtmesh-loop-XXXXXX)
      find "$TUT_SRC" -maxdepth 1 -type f -exec cp {} "$dir/" \;
      gunzip -f "$dir/"*.gz 2>/dev/null
      src=$dir/$m.geo ;;
    femur | cube_sphere) src=$ROOT/geo/$m.geo ;;
    *) src=$(ls "$MODELS_DIR/$m".* 2>/dev/null | head -1) ;;
  esac
  [ -n "$src" ] && [ -f "$src" ] || { echo "$m: no such model" >&2; return 1; }
  (cd "$(dirname "$src")" && "$BIN" convert "$src" "$init" --binary > /dev/null 2>&1) ||
    { echo "$m: the Init could not be made" >&2; return 1; }
  [ -n "${dir:-}" ] && rm -rf "$dir"
  return 0
}

for m in "$@"; do
  init_of "$m" || continue
  s=$(date +%s.%N)
  "$BIN" optimize "$INITS/$m.init.msh" -o "$OUT/$m.msh" --binary > "$OUT/$m.log" 2>&1
  rc=$?
  e=$(date +%s.%N)
  "$BIN" stats "$OUT/$m.msh" --format json 2> /dev/null | /usr/bin/python3 -c '
import json, sys
t = json.load(sys.stdin)
c = t["meshes"][0] if "meshes" in t else t
print("%-22s rc=%s %.4f %.4f %.2f %.2f %.4e %.4e %6.1fs" % (sys.argv[1], sys.argv[2],
      c["q_min"], c["average_quality"], c["min_angle"], c["max_angle"], c["time_step"],
      c["element_time_step"], float(sys.argv[4]) - float(sys.argv[3])))' "$m" "$rc" "$s" "$e" ||
    echo "$m rc=$rc (no stats)"
done
