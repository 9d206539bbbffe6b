#!/usr/bin/env bash
# Gradescope builds the autograder's image with this (Ubuntu, as root): springscene and
# pytest in a virtual environment, OSMesa (off-screen OpenGL, for videos) and bubblewrap
# (the sandbox each student's program runs in).
set -euo pipefail
apt-get update
apt-get install -y --no-install-recommends python3 python3-venv libosmesa6 bubblewrap
python3 -m venv /opt/springscene
/opt/springscene/bin/pip install --no-cache-dir "springscene==0.1.0" "pytest>=8,<10"
ln -sf /opt/springscene/bin/springscene /usr/local/bin/springscene
