# Sourced by the benchmarks: the meshes of ../shared/data they run on (each where it is present).
shared_data=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/../shared/data
# shared_meshes [--non-convex]: their paths, one a line; --non-convex leaves out the two whose
# boundary is convex (hexa, tetramesh).
shared_meshes() {
  local f
  for f in vtkdata_post_tets/post_tets.vtu cgns_static_mixer/static_mixer.vtu cgns_heating_coil/heating_coil_fluid.vtu \
           cgns_heating_coil/heating_coil_solid.vtu exodus_disk_out_ref/disk_out_ref.ex2 nasa_bluntfin/bluntfin_tets.vtu \
           nasa_bluntfin/bluntfin.vts nasa_combustion_chamber/comb_tets.vtu nasa_combustion_chamber/comb.vts \
           vtkdata_angular_sector/angular_sector.vtu vtkdata_can/can.vtu vtkdata_hexa/hexa.vtu \
           vtkdata_notch_stress/notch_stress.vtu vtkdata_tetramesh/tetramesh.vtu vtk_small_cell_samples/elements.vtu; do
    if [ "${1:-}" = --non-convex ] && { [[ $f == */hexa.vtu ]] || [[ $f == */tetramesh.vtu ]]; }; then continue; fi
    if [ -f "$shared_data/$f" ]; then echo "$shared_data/$f"; fi
  done
}
