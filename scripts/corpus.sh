#!/usr/bin/env bash
# Runs cvtmesh over the real-model corpus: Gmsh's tutorials t1-t21 (Debian's gmsh-doc, unpacked
# into a temporary directory: some are gzipped, some read data files beside them) and the models
# in ../shared/data/models/ (referenced in place). For each model and method: `optimize` (with a
# timeout), then `check` and `stats --format json` on the output. Prints one line per run:
#   model method exit signal in_Qmin g_Qmin out_Qmin in_avg g_avg out_avg in_mindih g_mindih
#   out_mindih g_seconds seconds cpu_seconds check
# (seconds: wall time of optimize; cpu_seconds: its user + system CPU time, /usr/bin/time;
# out_* read back from the written file; in_* from stats on the input; g_* = Gmsh's own tet
# optimizer on the same input mesh, `cvtmesh mesh IN --gmsh-optimize`; NO_GMSH=1 skips it). No exit status of its
# own beyond the script's failures: it is a survey. The CTest label `corpus` asserts on it.
#
# Usage: scripts/corpus.sh [-m METHOD]... [-t SECONDS] [MODEL...]
#   METHOD default: the default pipeline and cvdt+swap; MODEL: t5, igl_bunny, ... (default: all)
#   CVTMESH=path/to/cvtmesh (default build/cvtmesh), OUT=dir for outputs (default a temp dir).
set -uo pipefail
cd "$(dirname "$0")/.."
CVTMESH=${CVTMESH:-$PWD/build/cvtmesh}
MODELS_DIR=${MODELS_DIR:-$(cd .. && pwd)/shared/data/models}
TUT_SRC=${TUT_SRC:-/usr/share/doc/gmsh-doc/doc/gmsh/tutorial}
timeout_s=300
methods=()
while getopts "m:t:" o; do
  case $o in
    m) methods+=("$OPTARG") ;;
    t) timeout_s=$OPTARG ;;
    *) exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ ${#methods[@]} -eq 0 ] && methods=(default cvdt+swap)

work=$(mktemp -d /tmp/cvtmesh-corpus-XXXXXX)
OUT=${OUT:-$work/out}
mkdir -p "$OUT" "$work/tut"
find "$TUT_SRC" -maxdepth 1 -type f -exec cp {} "$work/tut/" \;
gunzip -f "$work/tut/"*.gz

all=()
for i in $(seq 1 21); do all+=("t$i"); done
for f in "$MODELS_DIR"/*.off "$MODELS_DIR"/*.obj "$MODELS_DIR"/*.mesh; do
  all+=("$(basename "${f%.*}")")
done
[ $# -gt 0 ] && all=("$@")

input_of() {
  case $1 in
    t[0-9]*) echo "$work/tut/$1.geo" ;;
    *) ls "$MODELS_DIR/$1".* 2>/dev/null | head -1 ;;
  esac
}

# json -> "Qmin avg mindih" of the first column (stats --format json).
stats_of() {
  python3 -c '
import json,sys
try:
  t=json.load(open(sys.argv[1])); c=t["meshes"][0] if "meshes" in t else t
  g=lambda *k: next((c[x] for x in k if x in c), float("nan"))
  print("%.4f %.4f %.2f" % (g("q_min"), g("average_quality"), g("min_angle")))
except Exception as e:
  print("- - -")' "$1"
}
printf "%-24s %-16s %4s %4s %8s %8s %8s %8s %8s %8s %7s %7s %7s %8s %8s %8s %s\n" model method exit sig \
  in_Qmin g_Qmin out_Qmin in_avg g_avg out_avg in_dih g_dih out_dih g_sec seconds cpu_s "check / message"
for m in "${all[@]}"; do
  in=$(input_of "$m")
  [ -z "$in" ] && { echo "$m: no input" >&2; continue; }
  for meth in "${methods[@]}"; do
    tag=$m.${meth//+/_}
    out=$OUT/$tag.msh
    args=()
    [ "$meth" != default ] && args=(--method "$meth")
    t0=$(date +%s.%N)
    (cd "$work/tut" && /usr/bin/time -f "%U %S" -o "$work/$tag.time" \
      timeout "$timeout_s" "$CVTMESH" optimize "$in" -o "$out" "${args[@]}" -q \
      >"$work/$tag.out" 2>"$work/$tag.err")
    rc=$?
    # /usr/bin/time reports a non-zero status on its first line ("Command exited with ...").
    cpu=$(tail -1 "$work/$tag.time" 2>/dev/null | awk '{printf "%.1f", $1 + $2}')
    cpu=${cpu:--}
    t1=$(date +%s.%N)
    secs=$(python3 -c "print('%.1f' % ($t1 - $t0))")
    sig=-
    [ $rc -gt 128 ] && sig=$((rc - 128))
    [ $rc -eq 124 ] && sig=TIMEOUT
    # optimize -q prints no table; the input's figures come from stats on the input.
    if [ ! -f "$work/$m.in.json" ]; then
      (cd "$work/tut" && timeout "$timeout_s" "$CVTMESH" stats "$in" --format json \
        >"$work/$m.in.json" 2>/dev/null)
    fi
    read -r iq ia id <<<"$(stats_of "$work/$m.in.json")"
    # Gmsh's own optimizer on the same input mesh (cvtmesh mesh --gmsh-optimize), once a model.
    if [ -z "${NO_GMSH:-}" ] && [ ! -f "$work/$m.g.json" ]; then
      (cd "$work/tut" && timeout "$timeout_s" "$CVTMESH" mesh "$in" --gmsh-optimize \
        -o "$work/$m.g.msh" >/dev/null 2>"$work/$m.g.err") &&
        "$CVTMESH" stats "$work/$m.g.msh" --format json >"$work/$m.g.json" 2>/dev/null
      [ -f "$work/$m.g.json" ] || echo '{}' >"$work/$m.g.json"
    fi
    read -r gq ga gd <<<"$(stats_of "$work/$m.g.json" 2>/dev/null || echo "- - -")"
    gs=$(sed -n 's/.*Gmsh optimize: \([0-9.]*\) s.*/\1/p' "$work/$m.g.err" 2>/dev/null | head -1)
    gs=${gs:--}
    oq=- oa=- od=- chk=-
    if [ $rc -eq 0 ] && [ -f "$out" ]; then
      if "$CVTMESH" check "$out" >"$work/$tag.chk" 2>&1; then chk=ok; else chk="check-rc$?"; fi
      "$CVTMESH" stats "$out" --format json >"$work/$tag.json" 2>/dev/null
      read -r oq oa od <<<"$(stats_of "$work/$tag.json")"
      # What optimize kept or fell back to (its notes), in a few words.
      kept=$(python3 -c '
import re,sys
t=open(sys.argv[1]).read(); out=[]
m=re.search(r"note: (\d+) elements other than tets", t)
if m: out.append(m.group(1)+" non-tet kept")
if "local operations only" in t: out.append("defects: local ops only")
m=re.search(r"made the mesh worse \(([^)]*)\)", t)
if m: out.append("method worse ("+m.group(1)+")")
if "failed (" in t: out.append("method failed")
m=re.search(r"(\d+) vertices were restored", t)
if m and "left" in t: out.append("per-region restore ("+m.group(1)+" restored)")
if "moved locally" in t: out.append("local moves")
if "polish alone" in t: out.append("polish kept")
if "smoothing alone" in t: out.append("smoothing alone kept")
if "input is kept unchanged" in t: out.append("input kept")
if "iteration cap" in t: out.append("iteration cap")
print("; ".join(out))' "$work/$tag.err")
      [ -n "$kept" ] && chk="$chk; $kept"
    else
      chk=$(grep -v '^\s*$' "$work/$tag.err" | tail -1 | cut -c1-150)
    fi
    printf "%-24s %-16s %4s %4s %8s %8s %8s %8s %8s %8s %7s %7s %7s %8s %8s %8s %s\n" "$m" "$meth" "$rc" \
      "$sig" "$iq" "$gq" "$oq" "$ia" "$ga" "$oa" "$id" "$gd" "$od" "$gs" "$secs" "$cpu" "$chk"
  done
done
[ -z "${KEEP:-}" ] && rm -rf "$work"
