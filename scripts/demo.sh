#!/usr/bin/env bash
# The main job for a newcomer: install packages, build, solve the bundled example with its
# worked example, and render every lesson into the teaching site out/site/ (frames, the before
# / at / after figures, worked examples, plots, questions with answers, and on each lesson page
# a Try-it panel run by the engine compiled to WebAssembly, which the build makes in
# build/wasm/; open out/site/index.html in a browser).
# Only what that needs is installed and built: the tests' tools, collide-bench and the Python
# module come with scripts/test.sh (or scripts/install-deps.sh and scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
# Each stage's time is printed as it ends (a newcomer sees where the minutes go).
stage() { echo "demo: $1 in $((SECONDS - start)) s (${SECONDS} s in all)" >&2; start=$SECONDS; }
start=$SECONDS
scripts/install-deps.sh --demo
stage "packages installed"
scripts/build.sh -DCOLLIDE_BUILD_TESTS=OFF -DCOLLIDE_BUILD_BENCH=OFF -DCOLLIDE_PYTHON=OFF
stage "built (the command and the WebAssembly module)"
build/cli/collide solve lessons/solve/rod-on-ground.toml
build/cli/collide lessons
build/cli/collide material -o out/site --force
stage "site written"
echo "Open out/site/index.html (each lesson's files are in out/site/ID/)."
