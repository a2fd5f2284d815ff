#!/usr/bin/env bash
# The pictures of docs/cli.md ("Every option, as a picture"): one small render for each option of
# `cellproj render`, from the built-in default scene (scenes/default.vtu) or meshes cellproj
# generates, so that they reproduce in any clone.
# usage: scripts/cli_pictures.sh [CELLPROJ] [OUT]   (default build/bin/cellproj, docs/images/cli)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$root/build/bin/cellproj}; out=${2:-$root/docs/images/cli}
mkdir -p "$out"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mesh=$root/scenes/default.vtu
"$exe" generate mixed -n 8 -o "$tmp/mixed.vtu" >/dev/null
"$exe" generate mixed -n 8 --cell-data -o "$tmp/mixed_cells.vtu" >/dev/null
"$exe" generate shells -n 12 -o "$tmp/shells.vtu" >/dev/null
"$exe" generate graded -n 6 -o "$tmp/graded.vtu" >/dev/null
"$exe" generate swirl -n 6 --steps 4 -o "$tmp/series.pvd" >/dev/null

# picture NAME MESH OPTIONS...: a render, 200x150 unless the options give a --size.
picture() {
  local name=$1 input=$2 size=(--size 200x150); shift 2
  [[ " $* " == *" --size "* ]] && size=()
  "$exe" render "$input" "${size[@]}" -o "$out/$name.png" "$@" >/dev/null
  echo "$name: cellproj render $(basename "$input") ${size[*]} $*"
}
picture default "$mesh"
picture view_+z "$mesh" --view +z
picture azimuth "$mesh" --azimuth 60
picture elevation "$mesh" --elevation 60
picture roll "$mesh" --roll 30
picture zoom "$mesh" --zoom 2
picture dolly "$mesh" --perspective --dolly 1.6
picture perspective "$mesh" --perspective 60
picture focus "$mesh" --focus 0.5,0.5,0 --zoom 1.5
picture colormap "$mesh" --colormap viridis
picture range "$mesh" --range 0.3,0.8 --legend
picture opacity_sigmoid "$mesh" --opacity sigmoid
picture depth "$mesh" --depth 60
picture background_white "$mesh" --background white
picture background_none "$mesh" --background none
picture legend "$mesh" --legend
picture legend_horizontal "$mesh" --legend-orientation horizontal
picture legend_title "$mesh" --legend-title Temperature --legend-unit K
picture title "$mesh" --title "A swirl"
picture outline "$mesh" --outline
picture axes "$mesh" --axes
picture clip "$mesh" --clip 0,0,0,1,0,0
picture log "$mesh" --log --log-floor 0.01 --legend
picture field_cells "$tmp/mixed_cells.vtu" --cell-data cells
picture field_points "$tmp/mixed_cells.vtu" --cell-data points
picture time_label "$tmp/series.pvd" --time 1.5 --time-label
picture method_exact "$mesh" --method exact
picture method_pt-linear "$mesh" --method pt-linear
picture method_slicing "$mesh" --method slicing
picture method_mip "$mesh" --method mip --legend
picture iso "$tmp/shells.vtu" --method exact --iso 0.5 --iso -0.5:0.2,0.5,1,0.4 --legend
picture layers "$tmp/shells.vtu" --method layers --iso 0.5 --view +x
picture small_cells_draw "$tmp/graded.vtu" --small-cells draw
picture small_cells_splat "$tmp/graded.vtu" --small-cells splat
picture ssaa_1 "$mesh" --size 100x75
picture ssaa_4 "$mesh" --size 100x75 --ssaa 4
# A movie of a turntable: a looping GIF.
"$exe" render "$mesh" --size 160x120 --frames 24 --orbit 360 --fps 12 -o "$out/orbit.gif" >/dev/null
echo "orbit.gif: cellproj render default.vtu --size 160x120 --frames 24 --orbit 360 --fps 12 -o orbit.gif"
