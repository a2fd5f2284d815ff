#pragma once
// The one value per ray of --method mip, minip, average (raycast/ray_reduction.hpp).
namespace cellproj {

enum class RayReduction {
  maximum,  // MIP: the largest value along the ray
  minimum,  // MinIP: the smallest
  average,  // the mean over the length of the ray inside the mesh
};

}  // namespace cellproj
