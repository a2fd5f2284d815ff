// VTK's objects as cellproj's: a grid's cells and scalars, a volume property's transfer function,
// a camera, a depth buffer. Free functions: the mapper keeps what they make between frames.
#ifndef vtk_to_cellproj_h
#define vtk_to_cellproj_h

#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "optics/transfer_function.hpp"
#include "view/camera.hpp"
#include "view/opaque_depth.hpp"

class vtkCamera;
class vtkDataArray;
class vtkUnstructuredGrid;
class vtkVolume;
class vtkVolumeProperty;

namespace cellproj::vtk {

// The points and cells of `grid`, copied (its cells' types are VTK's codes, which cellproj
// shares); with `apart`, each cell on its own copies of its points (mesh/cell_data.hpp), so that a
// cell's scalar is drawn constant over it.
Mesh mesh_of(vtkUnstructuredGrid* grid, bool apart);

// One scalar per point of `mesh` (mesh_of's) from `array`: one tuple per point of the grid, or per
// cell when `per_cell` (each cell's value at each of its own points: `mesh` has its cells apart).
// `component` -1 takes a tuple's magnitude. Non-finite values are kept: the volume refuses them.
std::vector<double> scalars_of(const Mesh& mesh, vtkDataArray* array, bool per_cell, int component);

// The transfer function of property's first component: its colour (RGB or grey) and its scalar
// opacity o per unit distance u as extinction o / u (bench/vtk_peer.py). Their control points
// when they are linear in RGB between them; else sampled at the points and 1024 more, as VTK's own
// mappers sample them into tables.
TransferFunction transfer_function_of(vtkVolumeProperty* property);

// The camera in the volume's own frame (its matrix inverted: a rotation and a translation only),
// a viewport of `aspect` (width / height) for a horizontal view angle.
Camera camera_of(vtkCamera* camera, vtkVolume* volume, double aspect);

// A window's depth buffer (rows from the bottom, values in [0, 1]) as the view depth of the
// nearest opaque surface per pixel (rows from the top), +infinity where the buffer is clear.
OpaqueDepth opaque_depth_of(const std::vector<float>& zbuffer, int width, int height, vtkCamera* camera);

}  // namespace cellproj::vtk

#endif
