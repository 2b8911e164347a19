#!/usr/bin/env bash
# Installs the Debian packages this project needs to build, test and run.
#
# Idempotent: every package is checked with dpkg-query first and only the missing ones are
# installed ("apt-get update" runs once, and only when something is missing). Uses sudo when not
# run as root. Tested on Debian 12 (bookworm).
#
# This is the ONE list of packages of the project; later issues append to it.
set -euo pipefail

PACKAGES=(
  # Libraries of the design card.
  libeigen3-dev      # Eigen: dense and sparse linear algebra (core)
  libglfw3-dev       # windows and input (app)
  libx11-dev         # Xlib: the app's handler for a lost display (GLFW's own backend)
  libimgui-dev       # Dear ImGui panels (app)
  libglm-dev         # GL maths (render)
  libgl1-mesa-dev    # OpenGL headers and libGL (render)
  libosmesa6-dev     # off-screen Mesa for headless rendering tests
  libosd-dev         # OpenSubdiv: Catmull-Clark oracle for the boundary surface
  libhidapi-dev      # haptic devices over HID
  libtinygltf-dev    # glTF import and export
  libstb-dev         # stb_image_write: PNG figures and screenshots
  nlohmann-json3-dev # JSON control meshes and scripts
  libsuitesparse-dev # CHOLMOD: the implicit solver's supernodal Cholesky preconditioner (core)
  libopenblas0-pthread # an optimised BLAS behind libblas.so.3 for CHOLMOD's dense blocks
  # Tool chain.
  cmake
  g++
  ninja-build
  ccache
  pkg-config
  python3            # scripts/make_assets.py
  # Tests and benchmarks.
  libgtest-dev
  libbenchmark-dev
  calculix-ccx       # ccx: independent FEM reference for the FEM tests (C3D8, C3D20R)
  tetgen             # irregular tetrahedral meshes for the Phong deformation tests
  xvfb               # xvfb-run: window tests without a display
  xauth              # needed by xvfb-run
  ffmpeg             # sculpt --record-out NAME.mp4 (H.264); ffprobe checks it in the GUI tests
  blender            # Blender 3.4 imports the recorded .glb in the tests (tests/anim)
  python3-numpy      # Blender's glTF importer needs numpy
  # Fuzzing (scripts/fuzz.sh, docs/fuzzing.md).
  clang-14           # libFuzzer builds need clang; the normal build stays on g++
  libclang-rt-14-dev # libFuzzer and the clang sanitizer runtimes
)
# The glTF validator (scripts/install-gltf-validator.sh) runs on node and installs with npm; a
# machine that already has them (e.g. from NodeSource) keeps its own.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  PACKAGES+=(nodejs npm)
fi

log() { printf '[install-deps] %s\n' "$*"; }

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  log "error: dpkg-query/apt-get not found; this script supports Debian 12 (and Debian-like) systems." >&2
  log "Install these packages by other means: ${PACKAGES[*]}" >&2
  exit 1
fi

missing=()
for pkg in "${PACKAGES[@]}"; do
  status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
  if [[ "$status" != "install ok installed" ]]; then
    missing+=("$pkg")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  log "all ${#PACKAGES[@]} packages are already installed; nothing to do."
  exit 0
fi

SUDO=()
if [[ "$(id -u)" -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=(sudo)
  else
    log "error: ${#missing[@]} package(s) missing (${missing[*]}), not running as root and sudo is not available." >&2
    log "Run this script as root, or install them with: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi

log "missing ${#missing[@]} of ${#PACKAGES[@]} package(s): ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
log "running apt-get update ..."
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
log "installing: ${missing[*]}"
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"

# Check that everything really is installed now.
still_missing=()
for pkg in "${missing[@]}"; do
  status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
  [[ "$status" == "install ok installed" ]] || still_missing+=("$pkg")
done
if [[ ${#still_missing[@]} -ne 0 ]]; then
  log "error: still missing after installation: ${still_missing[*]}" >&2
  exit 1
fi
log "installed ${#missing[@]} package(s); all ${#PACKAGES[@]} packages are present."
