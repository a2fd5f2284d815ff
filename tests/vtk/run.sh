#!/usr/bin/env bash
# The VTK mapper's tests in a real render window: under Xvfb (scripts/setup.sh installs it).
# usage: run.sh PYTHON TEST_DIR   (PYTHONPATH, CELLPROJ_EXE and CELLPROJ_SOURCE_DIR from ctest)
set -u
python=$1; dir=$2
command -v xvfb-run >/dev/null || { echo "no xvfb-run (Debian: xvfb): skipped"; exit 77; }
exec xvfb-run -a -s "-screen 0 1024x768x24" "$python" -m pytest -q -p no:cacheprovider "$dir"
