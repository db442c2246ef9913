#!/usr/bin/env bash
# The main job for a newcomer: install packages, build, solve the bundled example with its
# worked example, and render the first lesson (frames, the before / at / after figure, data,
# the lesson with its answers).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/cli/collide solve lessons/solve/rod-on-ground.toml
build/cli/collide lessons
build/cli/collide render catch-up -o out/catch-up --force
echo "Open out/catch-up/figure.png, out/catch-up/lesson.md and out/catch-up/frames/."
