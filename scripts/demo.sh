#!/usr/bin/env bash
# The main job for a newcomer: install packages, build, and solve the bundled example with
# its worked example. (Later: render the default lesson.)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/cli/collide solve lessons/solve/rod-on-ground.toml
