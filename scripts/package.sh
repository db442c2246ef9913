#!/usr/bin/env bash
# Builds the Debian packages (docs/install.md): installs what that needs
# (scripts/install-deps.sh --package), builds for /usr in ./build-deb without the tests and
# benchmarks, and runs cpack (packaging/CMakeLists.txt):
#   build-deb/collide_VERSION_amd64.deb          the command, its lessons, man page, completion
#   build-deb/collide-dev_VERSION_amd64.deb      headers, static libraries, find_package(Collide)
#   build-deb/python3-collide_VERSION_amd64.deb  the Python module (when pybind11 was found)
# Then: sudo apt install ./build-deb/collide_*.deb
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build-deb
scripts/install-deps.sh --package
scripts/build.sh -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
  -DCOLLIDE_BUILD_TESTS=OFF -DCOLLIDE_BUILD_BENCH=OFF
(cd "$dir" && cpack -G DEB)
ls -l "$dir"/*.deb
