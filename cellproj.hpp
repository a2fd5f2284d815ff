#pragma once
// cellproj's public API in one include: the mesh model and readers, optics, camera and images, and
// the façade (render/): a Volume committed once, a Field per call, RenderSettings and a Renderer.
// Link cellproj::render; it brings the earlier stages.
#include "base/error.hpp"
#include "grid/mesh.hpp"
#include "grid/read_mesh.hpp"
#include "grid/validate.hpp"
#include "optics/transfer_function.hpp"
#include "render/renderer.hpp"
#include "render/volume.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"
