#pragma once
// cellproj's render stack in one include: the mesh model, optics, camera and images, and the
// façade (render/): a Volume committed once, a Field per call, RenderSettings and a Renderer.
// Link cellproj::render; it brings the earlier stages and no file-format library. Reading files is
// io/ (io/read_mesh.hpp, cellproj::io: VTK, netCDF, CGNS, TetGen).
#include "base/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/validate.hpp"
#include "optics/transfer_function.hpp"
#include "render/renderer.hpp"
#include "render/volume.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"
