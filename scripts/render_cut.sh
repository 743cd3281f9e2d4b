#!/usr/bin/env bash
# Renders a cut view of a tet mesh written by cvtmesh with --quality (the analogue of the paper's
# Figs. 9 and 11): the elements behind a clipping plane, coloured by the Q view, as a PNG, with
# Gmsh under Xvfb.
# Usage: scripts/render_cut.sh MESH.msh OUT.png [axis x|y|z] [position] [rotation "rx ry rz"] [scale]
set -euo pipefail
mesh=$(realpath "$1"); out=$(realpath -m "$2"); axis=${3:-y}; pos=${4:-0.5}; rot=${5:-"-90 0 0"}
read -r rx ry rz <<<"$rot"; scale=${6:-1}
case $axis in
  x) a=1 b=0 c=0 ;; y) a=0 b=1 c=0 ;; z) a=0 b=0 c=1 ;; *) echo "axis must be x, y or z" >&2; exit 2 ;;
esac
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/cut.geo" <<GEO
Merge "$mesh";
General.Trackball = 0;
General.RotationX = $rx; General.RotationY = $ry; General.RotationZ = $rz;
General.GraphicsWidth = 700; General.GraphicsHeight = 700; General.SmallAxes = 0;
General.ScaleX = $scale; General.ScaleY = $scale; General.ScaleZ = $scale;
Mesh.SurfaceFaces = 0; Mesh.SurfaceEdges = 0; Mesh.VolumeFaces = 0; Mesh.VolumeEdges = 0;
Mesh.Points = 0; Mesh.Lines = 0;
General.Clip0A = $a; General.Clip0B = $b; General.Clip0C = $c; General.Clip0D = -$pos;
General.ClipWholeElements = 1;
For i In {0:PostProcessing.NbViews-1}
  View[i].Visible = 0;
EndFor
View[0].Visible = 1; View[0].Clip = 1; View[0].ShowElement = 1;
View[0].RangeType = 2; View[0].CustomMin = 0.3; View[0].CustomMax = 1; View[0].ColormapNumber = 2;
Print "$out";
Exit;
GEO
xvfb-run -a -s "-screen 0 1024x768x24" gmsh "$tmp/cut.geo" >/dev/null 2>&1
test -s "$out" && echo "wrote $out"
