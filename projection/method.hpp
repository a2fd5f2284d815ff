#pragma once
// The cell-projection methods: a ladder from fastest to exact (docs/methods.md measures each rung
// against the exact reference renderer). What a method does is decided by its traits alone: code
// asks traits(method), never which method it is (docs/architecture.md, "Adding a method").
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "composite/backend.hpp"
#include "optics/opacity_table.hpp"

namespace cellproj {

enum class ProjectionMethod {
  pt_linear,       // Shirley-Tuchman as published: opacity and colour interpolated across the triangles
  pt_table,        // (kappa_avg, l) interpolated, opacity from a 2D table of 1 - exp(-kappa l) (MWSC sec. 2)
  pt_analytic,     // per pixel, the exact integral for kappa and colour linear along the segment
  pt_breakpoints,  // pt_analytic, the segment cut at the transfer function's breakpoints: exact
};

// The closed set of what distinguishes the methods.
struct MethodTraits {
  ProjectionMethod method;
  const char* name;          // on the command line, in files and messages
  bool gouraud;              // corner values Gouraud-interpolated across each triangle (MWSC sec. 2);
                             // otherwise each pixel's segment is integrated in closed form
  bool opacity_table;        // opacity read from the 2D alpha texture (OpacityTable) at (kappa_avg, l)
  bool point_optics;         // kappa and colour evaluated once per point and frame (PointOptics)
  bool cuts_at_breakpoints;  // per pixel: the segment cut at the transfer function's breakpoints
  bool opengl;               // the OpenGL back ends can draw it (Gouraud triangles, the alpha texture)
};
inline constexpr MethodTraits kProjectionMethods[] = {
    {ProjectionMethod::pt_linear, "pt-linear", true, false, true, false, true},
    {ProjectionMethod::pt_table, "pt-table", true, true, true, false, true},
    {ProjectionMethod::pt_analytic, "pt-analytic", false, false, false, false, false},
    {ProjectionMethod::pt_breakpoints, "pt-breakpoints", false, false, false, true, false},
};
constexpr const MethodTraits& traits(ProjectionMethod method) { return kProjectionMethods[static_cast<int>(method)]; }
constexpr const char* name_of(ProjectionMethod method) { return traits(method).name; }

// How pt-linear and pt-table draw a whole cell (hexahedron, wedge, pyramid) in software: by its
// front and back layers, the thick-vertex formula at every pixel's own segment, or by the polygons
// of its image-plane subdivision, Gouraud-shaded (MWSC section 4; what the OpenGL back ends draw);
// automatic: layers for a cell whose image spans few pixels (kLayersUpToPixels), where its
// subdivision would cost more than its pixels, polygons otherwise. pt-analytic and pt-breakpoints
// always use the layers.
enum class WholeCells { automatic, layers, polygons };
inline constexpr double kLayersUpToPixels = 256;  // the area of the cell's image box, in pixels
// A tetrahedron is drawn as one fan over its pixel box (tet_fan.hpp) when the box (within the
// image) has at most this many pixels; a larger one triangle by triangle, row by row. (pt-linear
// composited by tiles draws every tetrahedron as a fan: it fills no buffer the size of the box.)
inline constexpr std::int64_t kFanUpToPixels = 1024;

}  // namespace cellproj
