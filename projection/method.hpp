#pragma once
// The cell-projection methods: a ladder from fastest to exact (docs/methods.md measures each rung
// against the exact reference renderer). What a method does is decided by its traits alone: code
// asks traits(method), never which method it is (docs/architecture.md, "Adding a method").
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

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

// Where the projected triangles are rasterized and composited.
enum class ProjectionBackend {
  software,              // our rasterizer and a float framebuffer, every method (the default)
  opengl,                // OpenGL through OSMesa into a float framebuffer (pt-linear, pt-table)
  opengl_8bit,           // the same into 8-bit RGBA, as 1990s hardware
  opengl_8bit_dithered,  // 8-bit with alpha dithering (Williams, Frank and LaMar)
};
constexpr bool is_opengl(ProjectionBackend backend) { return backend != ProjectionBackend::software; }

// 1 - exp(-kappa l) tabulated on [0, kappa_max] x [0, l_max] at size x size nodes, read bilinearly:
// the paper's 2D alpha texture. Arguments beyond the table are clamped to its edge.
class OpacityTable {
 public:
  OpacityTable(int size, double kappa_max, double l_max);  // check_size(size) first
  static void check_size(int size);                        // InputError unless 2 <= size <= 8192
  // Where kappa and l fall between the nodes (fractional node index, clamped to the table).
  double kappa_index(double kappa) const { return std::min(kappa * kscale_, max_index_); }
  double length_index(double l) const { return std::min(l * lscale_, max_index_); }
  double operator()(double kappa, double l) const {
    const double u = kappa_index(kappa), v = length_index(l);
    const int i = std::min(static_cast<int>(u), size_ - 2), j = std::min(static_cast<int>(v), size_ - 2);
    const double fu = u - i, fv = v - j;
    const float* row = alpha_.data() + static_cast<std::size_t>(j) * size_ + i;
    return (1 - fv) * ((1 - fu) * row[0] + fu * row[1]) + fv * ((1 - fu) * row[size_] + fu * row[size_ + 1]);
  }
  int size() const { return size_; }
  const float* data() const { return alpha_.data(); }  // size x size, kappa fastest

 private:
  int size_;
  double kscale_, lscale_, max_index_;
  std::vector<float> alpha_;
};

}  // namespace cellproj
