#!/usr/bin/env bash
# The main job for a newcomer: install packages, build, solve the bundled example with its
# worked example, and render the default scene (frames, the before / at / after figure, data).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/cli/collide solve lessons/solve/rod-on-ground.toml
build/cli/collide render lessons/scenes/billiards-2d.toml -o out/billiards-2d --force
echo "Open out/billiards-2d/figure.png and out/billiards-2d/frames/."
