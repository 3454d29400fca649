#!/usr/bin/env bash
# Gradescope autograder setup (runs once, when the image is built; Ubuntu).
# Zip this folder's files (setup.sh, run_autograder) with a `lightlab` binary built on
# the same Ubuntu release (`cargo build --release`, then copy target/release/lightlab here).
set -euo pipefail
apt-get update -qq
# Mesa llvmpipe, the OpenGL lightlab checks shaders on (headless, no GPU needed).
apt-get install -y -qq libegl1 libegl-mesa0 libgl1-mesa-dri
install -m 755 /autograder/source/lightlab /usr/local/bin/lightlab
