#!/usr/bin/env bash
# Installs the dependencies, builds the program and runs it on the default model.
#
#   scripts/run.sh [CONTROL.json]      (default: assets/block3.json)
#
# It builds `sculpt` (the window) and `sculpt-cli`, runs the command-line demo on the control mesh
# and then opens the window on the default model (the Stanford bunny). Without a display the
# window renders headless under xvfb-run into out/sculpt_default.png. The demo prints
# `sculpt-cli info` of the model at level 2, writes its level-2 subdivision to out/ and
# simulates one second of it sagging under gravity:
#   out/<name>_level2.vtk            the level-2 cell complex (open it in ParaView)
#   out/<name>_level2_boundary.obj   its boundary surface
#   out/<name>_sag.vtk               the deformed control mesh with its displacement field
#   out/<name>_sag_surface.obj       the boundary surface carried by the sagging control mesh
#                                    with Phong deformation (sculpt-cli deform)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

if [[ $# -gt 1 || "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then
  sed -n '2,13p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  [[ $# -gt 1 ]] && exit 2
  exit 0
fi
ASSET="${1:-assets/block3.json}"
if [[ ! -f "$ASSET" ]]; then
  echo "scripts/run.sh: no such file: $ASSET" >&2
  exit 2
fi
NAME="$(basename "$ASSET")"
NAME="${NAME%.*}"
LEVELS=2
BUILD_DIR="build"
JOBS="$(nproc 2>/dev/null || echo 2)"
CLI="$ROOT/$BUILD_DIR/bin/sculpt-cli"

stage() { printf '\n==== %s ====\n' "$*"; }

stage "1/4 dependencies (scripts/install-deps.sh)"
bash "$ROOT/scripts/install-deps.sh"

# Same configuration as scripts/test.sh, so that both share build/ without reconfiguring.
stage "2/4 configure (Release) into $BUILD_DIR/"
cmake -S "$ROOT" -B "$ROOT/$BUILD_DIR" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release \
  -DSCULPT_BUILD_TESTS=ON \
  -DSCULPT_WERROR=ON \
  -DSCULPT_SANITIZE="" \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache

stage "3/4 build sculpt and sculpt-cli with $JOBS jobs"
cmake --build "$ROOT/$BUILD_DIR" --parallel "$JOBS" --target sculpt-cli sculpt

stage "4/4 run on $ASSET (level $LEVELS)"
mkdir -p "$ROOT/out"
VTK="out/${NAME}_level${LEVELS}.vtk"
OBJ="out/${NAME}_level${LEVELS}_boundary.obj"
echo "\$ $BUILD_DIR/bin/sculpt-cli info $ASSET --levels $LEVELS"
"$CLI" info "$ASSET" --levels "$LEVELS"
echo
echo "\$ $BUILD_DIR/bin/sculpt-cli subdivide $ASSET --levels $LEVELS --out $VTK --boundary $OBJ"
"$CLI" subdivide "$ASSET" --levels "$LEVELS" --out "$VTK" --boundary "$OBJ"
echo
# One second of the solid sagging under gravity (y up), its lowest layer of control points held.
SIM="out/${NAME}_sag.vtk"
FIX="$(python3 -c 'import json,sys; y=min(v[1] for v in json.load(open(sys.argv[1]))["vertices"]); print(f"-1e9,{y-1e-6},-1e9,1e9,{y+1e-6},1e9")' "$ASSET")"
echo "\$ $BUILD_DIR/bin/sculpt-cli simulate $ASSET --levels $LEVELS --gravity --E 2e5 --fix=$FIX --dt 0.02 --steps 50 --out $SIM"
"$CLI" simulate "$ASSET" --levels "$LEVELS" --gravity --E 2e5 --fix="$FIX" --dt 0.02 --steps 50 --out "$SIM"
echo
# The boundary surface carried by the sagging control mesh as a cage (Phong deformation). Only
# meshes whose control cells are hexahedra or tetrahedra can serve as a cage.
REST="out/${NAME}_rest.vtk"
SURFACE="out/${NAME}_sag_surface.obj"
"$CLI" subdivide "$ASSET" --levels 0 --out "$REST" > /dev/null
echo "\$ $BUILD_DIR/bin/sculpt-cli deform --rest $REST --deformed $SIM --surface $OBJ --method phong --out $SURFACE"
if ! "$CLI" deform --rest "$REST" --deformed "$SIM" --surface "$OBJ" --method phong --out "$SURFACE"; then
  echo "(skipped: this control mesh has cells that are neither hexahedra nor tetrahedra)"
  SURFACE=""
fi
echo
echo "wrote:"
echo "  $ROOT/$VTK   (level-$LEVELS cell complex, legacy VTK: open it in ParaView)"
echo "  $ROOT/$OBJ   (its boundary surface, OBJ)"
echo "  $ROOT/$SIM   (the control mesh after 1 s under gravity, with its displacement field)"
[[ -n "$SURFACE" ]] && echo "  $ROOT/$SURFACE   (the boundary surface deformed with the control mesh, OBJ)"

SCULPT="$ROOT/$BUILD_DIR/bin/sculpt"
SHOT="out/sculpt_default.png"
if [[ -n "${DISPLAY:-}" ]]; then
  echo
  echo "\$ $BUILD_DIR/bin/sculpt   (the window; close it to finish)"
  "$SCULPT"
elif command -v xvfb-run >/dev/null 2>&1; then
  echo
  echo "no display: rendering the window headless under xvfb-run"
  xvfb-run -a -s "-screen 0 1280x1024x24" "$SCULPT" --headless --frames 60 --screenshot "$SHOT"
  echo "  $ROOT/$SHOT   (screenshot of the window: the default scene after 60 simulated frames)"
else
  echo "no display and no xvfb-run: the window was not started" >&2
fi
true
