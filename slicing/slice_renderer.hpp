#pragma once
// Plane slicing end to end (MWSC section 5; Yagel et al. 1996): cells are cut into convex polygons
// on a family of parallel planes, the polygons of a plane are scan converted into that slice's
// scalar image, and the slices are composited back to front along the normal. No cell sort: the
// planes are the order. The mesh's decomposition is prepared once; the field comes with each frame.
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/cell_order.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh.hpp"
#include "optics/transfer_function.hpp"
#include "slicing/boundary_crossings.hpp"
#include "slicing/slice_cells.hpp"
#include "slicing/slicing_options.hpp"
#include "splat/small_cells.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

struct SlicingStats {
  SliceAxis axis = SliceAxis::z;           // the family that was used
  double spacing = 0.0;                    // between neighbouring planes, world units
  std::int64_t slices = 0;                 // planes in front of the eye, cut and composited
  std::int64_t planes_behind_eye = 0;      // perspective: planes at or behind the eye, not drawn
  std::int64_t planes_reused = 0;          // progressive: planes whose polygons the previous level made
  std::int64_t polygons = 0;               // section polygons scan converted
  std::int64_t clipped_polygons = 0;       // perspective: polygons clipped at the near plane
  std::int64_t fragments = 0;              // pixel samples the slices wrote
  std::int64_t overlapping_fragments = 0;  // samples a slice wrote twice (overlapping cells)
  std::int64_t cells_between_planes = 0;   // slice cells no plane crosses: thinner than the spacing, they add nothing
  std::int64_t rays_along_planes = 0;      // pixels whose ray runs along the planes or away from them (axis
                                           // stacks in perspective): their slices come in a wrong order
  std::int64_t table_layers = 0;           // preintegrated: segment lengths tabulated (1 orthographic)
  SplatCounters splat;                     // the small cells and their splats
  SmallCells small_cells = SmallCells::draw;                  // the mode that ran
  double splat_threshold = 0.0;                               // of a cell's volume over the spacing cubed
  std::string gl_renderer;                                    // the OpenGL back ends: GL_RENDERER
  std::vector<std::pair<std::string, double>> phase_seconds;  // table, cut, scan convert, composite
  double seconds = 0.0;
};
// Each value of a slicing frame the report shows, with its key (render/report.hpp): f(key, value).
template <class F>
void each_counter(const SlicingStats& s, F&& f) {
  f("slice_axis", s.axis), f("spacing", s.spacing), f("slices", s.slices), f("planes_behind_eye", s.planes_behind_eye);
  f("planes_reused", s.planes_reused), f("polygons", s.polygons), f("clipped_polygons", s.clipped_polygons);
  f("fragments", s.fragments), f("overlapping_fragments", s.overlapping_fragments);
  f("cells_between_planes", s.cells_between_planes), f("rays_along_planes", s.rays_along_planes);
  f("table_layers", s.table_layers);
}

// One level of progressive refinement, as soon as it is composited: its index in the list, its
// plane count, the image (the callee's to keep) and its stats.
using SliceLevelDone = std::function<void(std::size_t level, int slices, Image&&, const SlicingStats&)>;

class SliceRenderer {
 public:
  // Prepared once per mesh (its arrays must outlive the renderer): the points recentred, each cell
  // to be cut whole or as its canonical tetrahedra as `mode` says (slicing/slice_cells), the
  // boundary faces.
  explicit SliceRenderer(const MeshView& mesh, Tetrahedralize mode = Tetrahedralize::problem);

  // One frame of the point field `scalar` (n_points values). Threads: those of the calling task
  // arena; the same image from 1 and N threads, bit for bit.
  Image render(const double* scalar, const TransferFunction& tf, const Camera& camera, int width, int height,
               const SlicingOptions& options, SlicingStats* stats = nullptr) const;

  // Progressive refinement: the frame at each plane count of `levels` (increasing), each handed to
  // `done` when it completes. A level reuses the polygons of the previous level's planes that
  // coincide with its own (every plane when the counts divide), within a memory budget.
  void render_levels(const double* scalar, const TransferFunction& tf, const Camera& camera, int width, int height,
                     const SlicingOptions& options, const std::vector<int>& levels, const SliceLevelDone& done) const;

  const SliceCells& cells() const { return cells_; }

  const LocalCells& local_cells() const { return local_; }  // the cells sliced, renumbered or as given

 private:
  LocalCells local_;  // renumbered along a Z-order curve where the mesh's numbering scatters them
  MeshView mesh_;     // local_'s view
  RecentredPoints points_;
  SliceCells cells_;
  std::vector<double> volume_;              // of each slice cell, for the small cells' rule
  std::vector<BoundaryTriangle> boundary_;  // the mesh's boundary faces as triangles
};

}  // namespace cellproj
