#!/usr/bin/env bash
# The ParaView plugin built as a user builds it (against an installed cellproj and ParaView's own
# VTK) and tested in pvbatch under Xvfb: loading it must not bring Debian's VTK into ParaView, and
# its screenshot must be the CLI's picture (tests/paraview/pvbatch_plugin.py).
# usage: run.sh BUILD_DIR SOURCE_DIR CELLPROJ_EXE
set -eu
build=$1; src=$2; exe=$3
for tool in pvbatch xvfb-run dpkg-deb; do
  command -v $tool >/dev/null || { echo "no $tool (scripts/setup.sh installs ParaView and Xvfb): skipped"; exit 77; }
done
scene=$src/bench/scenes/post_tets.json
[ -f "$src/../shared/data/vtkdata_post_tets/post_tets.vtu" ] || { echo "no ../shared/data: skipped"; exit 77; }
work=$build/test-paraview
rm -rf "$work/install" "$work/build"; mkdir -p "$work"
cmake --install "$build" --prefix "$work/install" >/dev/null
pv=$(bash "$src/tests/paraview/prefix.sh" "$work/pv")
cmake -S "$src/paraview" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/install;$pv" -DCMAKE_BUILD_TYPE=Release \
  >"$work/configure.log" 2>&1 || { tail -30 "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j2 >"$work/build.log" 2>&1 || { grep -B2 -A6 -m3 error "$work/build.log"; exit 1; }
plugin=$work/build/lib/paraview-plugins/Cellproj/Cellproj.so
debian_vtk=$(ldd "$plugin" | grep -E 'libvtk[A-Za-z0-9]+-9\.1\.so' || true)
[ -z "$debian_vtk" ] || { echo "the plugin loads Debian's VTK 9.1 into ParaView:"; echo "$debian_vtk"; exit 1; }
PYTHONPATH=$work/pv/pvpython/usr/lib/python3/dist-packages \
  xvfb-run -a -s "-screen 0 1024x768x24" pvbatch "$src/tests/paraview/pvbatch_plugin.py" "$plugin" "$scene" "$exe" "$work" \
  2>"$work/pvbatch.log" || { grep -v '^ *[0-9]* *0x' "$work/pvbatch.log" | tail -20; exit 1; }
