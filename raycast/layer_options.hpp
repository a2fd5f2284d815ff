#pragma once
// What --method layers draws (raycast/iso_layers.hpp): which crossings of which iso-value, their
// weights, their colour and the silhouettes.
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

namespace cellproj {

enum class Silhouettes {
  none,
  visible,  // where the view grazes the front layer (layer 1)
  hidden,   // where it grazes a layer behind it (2, 3, ... up to the deepest selected layer)
  both,
};

struct LayerOptions {
  double iso = 0.0;                 // the iso-value V
  std::vector<int> layers{1};       // which crossings of V, 1 the nearest; increasing
  std::vector<double> weights;      // one per layer, >= 0; empty: equal (Nagy and Klein's equal ratios)
  std::optional<glm::dvec3> color;  // of every layer; absent: the transfer function's colour at V
  Silhouettes silhouettes = Silhouettes::none;
  double silhouette_epsilon = 0.2;  // a silhouette where |view . normal| < this (unit vectors)
};

// InputError naming the option for layers that are not increasing from 1, weights that do not
// match them or are negative or all zero, an epsilon outside (0, 1], a non-finite iso-value.
void check(const LayerOptions& options);

}  // namespace cellproj
