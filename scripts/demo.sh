#!/usr/bin/env bash
# The main job for a newcomer: install packages, build, solve the bundled example with its
# worked example, and render every lesson into the teaching site out/site/ (frames, the before
# / at / after figures, worked examples, plots, questions with answers, and on each lesson page
# a Try-it panel run by the engine compiled to WebAssembly, which the build makes in
# build/wasm/; open out/site/index.html in a browser).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/cli/collide solve lessons/solve/rod-on-ground.toml
build/cli/collide lessons
build/cli/collide material -o out/site --force
echo "Open out/site/index.html (each lesson's files are in out/site/ID/)."
