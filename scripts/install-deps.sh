#!/usr/bin/env bash
# Installs every Debian 12 package the build needs. Idempotent; run as root (or with sudo).
# The list grows with the project: see ../shared/STACK.md for how each is found from CMake.
# Usage: scripts/install-deps.sh              everything: build, tests, benchmarks, CI
#        scripts/install-deps.sh --demo       only what scripts/demo.sh needs: the command, the
#                                             WebAssembly module and the site's videos (no test
#                                             tools, no Python module)
#        scripts/install-deps.sh --package    only what building the Debian packages needs
#                                             (scripts/package.sh)
set -euo pipefail

# Building the command, its libraries and the Python module, and packaging them.
build=(
  cmake g++ make pkg-config         # toolchain
  libeigen3-dev                     # linear algebra (double precision)
  libtomlplusplus-dev               # input files
  nlohmann-json3-dev                # JSON output
  libcli11-dev                      # command line
  libosmesa6-dev                    # renderer: offscreen OpenGL (render/context)
  libegl-dev                        # renderer: the second context, EGL surfaceless (--backend egl)
  libpng-dev                        # renderer: PNG frames
  libimgui-dev                      # renderer: overlays and labels (Dear ImGui 1.86)
  libfreetype-dev                   # renderer: font rasterisation beside ImGui
  fonts-dejavu-core                 # renderer: the label font (DejaVu Sans, Greek, sub/superscripts)
  libbox2d-dev                      # Box2D 2.4.1: the 2D reference of `collide compare`
  libglfw3-dev                      # collide gui: its window (optional for the build)
  python3-dev pybind11-dev python3-numpy  # the Python module collide (optional for the build)
  help2man                          # the man page, from the --help texts (optional for the build)
  dpkg-dev file                     # cpack -G DEB: dpkg-shlibdeps computes the packages' Depends
  libjs-three                       # three.js: collide material copies it beside the pages for the 3D
                                    # lessons' Try-it panels (with the WebAssembly module)
)
# The tests, benchmarks and CI besides.
develop=(
  libgtest-dev                      # tests
  libbenchmark-dev                  # collide-bench
  ffmpeg                            # collide render --format mp4|gif (optional for the build)
  libbullet-dev                     # Bullet 3.24: collide-bench's 3D peer (optional for the build)
  xvfb xauth                        # collide gui's tests: a screen without a display (xvfb-run)
  clang libclang-rt-14-dev          # scripts/test-sanitize.sh: clang 14, its sanitizers and libFuzzer
  clang-format                      # scripts/format.sh and the test style.format (clang-format 14)
  llvm-14                           # llvm-symbolizer: file and line in sanitizer reports
  python3-pytest                    # the Python module's tests (tests/python)
  jupyter-nbconvert python3-ipykernel python3-matplotlib  # the example notebook, run in the tests
  emscripten node-acorn             # the WebAssembly module collide-engine.js (wasm/; acorn for em++'s optimizer)
  nodejs chromium                   # its tests: under Node and in headless Chromium (tests/wasm)
  npm                               # the QTI reader of the qti tests (scripts/install-qti-reader.sh)
)

# The demo (scripts/demo.sh): the build without the Python module's packages, and the site's
# WebAssembly module (emscripten) and videos (ffmpeg).
demo=()
for p in "${build[@]}"; do
  case $p in python3-dev | pybind11-dev | python3-numpy) ;; *) demo+=("$p") ;; esac
done
demo+=(ffmpeg emscripten node-acorn nodejs)

case ${1:-} in
  "") packages=("${build[@]}" "${develop[@]}") ;;
  --demo) packages=("${demo[@]}") ;;
  --package) packages=("${build[@]}") ;;
  *) echo "usage: $0 [--demo | --package]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  # npm: a nodejs of NodeSource's brings its own (and conflicts with Debian's package)
  if [[ $p == npm ]] && command -v npm >/dev/null; then continue; fi
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root (missing: ${missing[*]})" >&2; exit 1; }
  sudo=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
