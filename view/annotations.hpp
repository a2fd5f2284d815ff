#pragma once
// Where the picture is, drawn over it as ParaView draws it: the bounding box's outline (its twelve
// edges as lines) and an axes triad in the lower-left corner (x red, y green, z blue, each the
// direction its world axis takes in the picture).
#include <string>

#include <glm/vec3.hpp>

#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

struct Annotations {
  bool outline = false, axes = false;
  glm::dvec3 lo{0.0}, hi{0.0};  // the box outlined
  glm::dvec3 color{1.0};        // the outline's and the labels' colour
  std::string font;             // the axes' labels; empty: default_font()
  bool any() const { return outline || axes; }
};

// Draws them over a picture that `camera` rendered at the picture's size.
void draw_annotations(Rgb8Image& picture, const Camera& camera, const Annotations& annotations);
void draw_annotations(DisplayImage& picture, const Camera& camera, const Annotations& annotations);

}  // namespace cellproj
