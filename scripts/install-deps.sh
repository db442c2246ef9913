#!/usr/bin/env bash
# Installs every Debian 12 package the build needs. Idempotent; run as root (or with sudo).
# The list grows with the project: see ../shared/STACK.md for how each is found from CMake.
set -euo pipefail

packages=(
  cmake g++ make pkg-config         # toolchain
  libeigen3-dev                     # linear algebra (double precision)
  libtomlplusplus-dev               # input files
  nlohmann-json3-dev                # JSON output
  libcli11-dev                      # command line
  libgtest-dev                      # tests
  libbenchmark-dev                  # collide-bench
  libosmesa6-dev                    # renderer: offscreen OpenGL (render/context)
  libegl-dev                        # renderer: the second context, EGL surfaceless (--backend egl)
  libpng-dev                        # renderer: PNG frames
  libimgui-dev                      # renderer: overlays and labels (Dear ImGui 1.86)
  libfreetype-dev                   # renderer: font rasterisation beside ImGui
  fonts-dejavu-core                 # renderer: the label font (DejaVu Sans, Greek, sub/superscripts)
  ffmpeg                            # collide render --format mp4|gif (optional for the build)
  libbox2d-dev                      # Box2D 2.4.1: the 2D reference of `collide compare`
  libbullet-dev                     # Bullet 3.24: collide-bench's 3D peer (optional for the build)
  libglfw3-dev                      # collide gui: its window (optional for the build)
  xvfb xauth                        # collide gui's tests: a screen without a display (xvfb-run)
  clang libclang-rt-14-dev          # scripts/test-sanitize.sh: clang 14, its sanitizers and libFuzzer
  llvm-14                           # llvm-symbolizer: file and line in sanitizer reports
)

missing=()
for p in "${packages[@]}"; do
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
