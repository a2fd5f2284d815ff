#!/usr/bin/env bash
# A prefix that ParaView 5.11's CMake package can be found in without python3-paraview installed
# (Debian: it conflicts with python3-vtk9, which libvtk9-dev needs). ParaView's CMake files check
# for its Python modules and read its wrapping hierarchy, both shipped by python3-paraview: the
# package is unpacked into PREFIX/pvpython (no root), and PREFIX/usr mirrors /usr with those
# files in place. ParaView's libraries and headers are the installed ones, through symlinks.
# usage: prefix.sh PREFIX      prints the CMake prefix path (PREFIX/usr); pvbatch's PYTHONPATH is
#                              PREFIX/pvpython/usr/lib/python3/dist-packages
set -eu
out=$1
triplet=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
usr=$out/usr; py=$out/pvpython
if [ ! -d "$py/usr/lib/python3/dist-packages/paraview" ]; then
  mkdir -p "$out/deb"
  deb=$(ls /var/cache/apt/archives/python3-paraview_*.deb 2>/dev/null | head -1 || true)
  if [ -z "$deb" ]; then
    (cd "$out/deb" && apt-get download python3-paraview >/dev/null 2>&1) || { echo "cannot download python3-paraview" >&2; exit 1; }
    deb=$(ls "$out"/deb/python3-paraview_*.deb | head -1)
  fi
  dpkg-deb -x "$deb" "$py"
fi
if [ ! -d "$usr/lib/$triplet/cmake/paraview-5.11" ]; then
  rm -rf "$usr"; mkdir -p "$usr/lib/$triplet/cmake" "$usr/lib/$triplet/vtk/hierarchy"
  for d in include share; do ln -s "/usr/$d" "$usr/$d"; done
  mkdir -p "$usr/bin"
  for f in /usr/bin/* "$py"/usr/bin/*; do ln -sf "$f" "$usr/bin/"; done
  ln -s "$py/usr/lib/python3" "$usr/lib/python3"
  for f in /usr/lib/"$triplet"/*; do
    case $(basename "$f") in cmake|vtk) ;; *) ln -s "$f" "$usr/lib/$triplet/" ;; esac
  done
  cp -r "/usr/lib/$triplet/cmake/paraview-5.11" "$usr/lib/$triplet/cmake/"  # a copy: CMake resolves symlinks
  ln -s "$py/usr/lib/$triplet/vtk/hierarchy/ParaView" "$usr/lib/$triplet/vtk/hierarchy/ParaView"
fi
echo "$usr"
