#pragma once
// cellproj's public API in one include: the mesh model and readers, optics, camera and images, and
// the renderers. Link cellproj::parallel (cell projection) and/or cellproj::raycast (the exact
// reference renderer); each brings the earlier stages.
#include "grid/error.hpp"
#include "grid/mesh.hpp"
#include "grid/read_mesh.hpp"
#include "grid/topology.hpp"
#include "grid/validate.hpp"
#include "optics/linear_segment.hpp"
#include "optics/segment_integral.hpp"
#include "parallel/projection_renderer.hpp"
#include "optics/transfer_function.hpp"
#include "raycast/reference_renderer.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"
