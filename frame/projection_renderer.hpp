#pragma once
// Cell projection end to end (MWSC sections 2, 3 and 7): the cells in visibility order feed the
// ordered batch pipeline (composite/), whose workers project them into fragments while one
// compositor blends them in order, so 1 and N threads give the same image bit for bit. The mesh's
// geometry is prepared once; the field comes with each frame.
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "frame/projection_options.hpp"
#include "mesh/cell_order.hpp"
#include "mesh/mesh.hpp"
#include "optics/transfer_function.hpp"
#include "projection/cell_fragments.hpp"
#include "projection/method.hpp"
#include "splat/small_cells.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"
#include "view/opaque_depth.hpp"
#include "visibility/sort.hpp"
#include "visibility/split_sorter.hpp"

namespace cellproj {

class CellRayTracer;

struct ProjectionStats {
  ProjectionCounters counters;
  SplatCounters splat;
  SmallCells small_cells = SmallCells::draw;  // the mode that ran
  double splat_threshold = 0.0;               // pixel centres: cells covering fewer are small
  std::int64_t splat_stencil_tiles = 0;       // image tiles whose rays the splats' stencil traced
  SortStats sort;
  Tetrahedralize tetrahedralize = Tetrahedralize::problem;  // the mode that ran (none for a mesh of tetrahedra)
  std::int64_t cells = 0;                                   // cells sorted and projected this frame (after splitting)
  std::int64_t tets = 0;                                    // of which tetrahedra
  std::int64_t problem_cells = 0;       // mesh cells with a face folded in this view (problem and none modes)
  std::int64_t cells_split = 0;         // mesh cells split into tetrahedra for this frame
  std::int64_t cycle_splits = 0;        // of which split because they were in a visibility cycle
  std::int64_t culled_transparent = 0;  // cells not drawn: extinction 0 over their scalar range
  std::vector<std::pair<std::string, double>> phase_seconds;  // project points, sort, project and composite
  double blend_seconds = 0.0;    // of project and composite: the ordered blend stage (software back end, stream)
  int tiles = 0;                 // the image tiles composited by (software back end, tiles; 0: the stream)
  std::int64_t tile_visits = 0;  // cells drawn by tile: cells plus the repeats of those straddling tiles
  bool tile_orders = false;      // each tile ordered its own cells (ProjectionOptions::tile_orders), no global order
  double cell_numbering_spread = 0.0;  // the mesh's numbering_spread (mesh/cell_order.hpp)
  bool cells_renumbered = false;       // whether the renderer's copy of the cells is renumbered for locality
  std::string gl_renderer;             // the OpenGL back ends: GL_RENDERER
  double seconds = 0.0;
};
// Each value of a projection frame the report shows, with its key (render/report.hpp), the
// sort's and the projection's counters among them: f(key, value).
template <class F>
void each_counter(const ProjectionStats& p, F&& f) {
  f("sort", p.sort.method), f("tetrahedralize", p.tetrahedralize);
  f("cells_projected", p.cells), f("tets", p.tets), f("problem_cells", p.problem_cells);
  f("cells_split", p.cells_split), f("cycle_splits", p.cycle_splits),
      f("cells_culled_transparent", p.culled_transparent);
  each_counter(p.counters, f);
  each_counter(p.sort, f);
  f("compositing", std::string(p.tiles > 0 ? "tiles" : "stream")), f("tiles", std::int64_t{p.tiles});
  f("tile_visits", p.tile_visits), f("visibility_order", std::string(p.tile_orders ? "per tile" : "global"));
}

class ProjectionRenderer {
 public:
  // Prepared once per mesh (its arrays must outlive the renderer): face topology, boundary hull,
  // the sorter's planes; the cells renumbered along a Z-order curve where the mesh's numbering
  // scatters them (LocalCells: the same picture, faster). Cells other than tetrahedra are
  // projected whole, except those `mode` splits into their canonical tetrahedra
  // (mesh/face_split): per view the ones a ray may cross more than twice (problem), all of them
  // once (all), or none.
  explicit ProjectionRenderer(const MeshView& mesh, Tetrahedralize mode = Tetrahedralize::problem);
  ~ProjectionRenderer();

  // One frame of the point field `scalar` (n_points values). Threads: those of the task arena it
  // is called from. With `opacity` (n_points values) the colour comes from `scalar` and the
  // extinction from `opacity` (optics/two_fields.hpp): each cell is then ray cast over its
  // canonical tetrahedra by pt-analytic or pt-breakpoints in software; UnsupportedError for the
  // other methods, the OpenGL back ends and splats.
  Image render(const double* scalar, const TransferFunction& tf, const Camera& camera, int width, int height,
               const ProjectionOptions& options = {}, ProjectionStats* stats = nullptr, const double* opacity = nullptr,
               const OpaqueDepth* opaque = nullptr) const;

  bool convex_boundary() const;
  Tetrahedralize mode() const { return sorter_.mode(); }

 private:
  // The exact traversal of the splats' stencil (frame/splat_stencil.hpp), made on first use.
  const CellRayTracer& tracer() const;

  LocalCells local_;  // the cells, renumbered or as given: mesh_ views them
  MeshView mesh_;
  SplittingSorter sorter_;
  mutable std::mutex tracer_mutex_;
  mutable std::unique_ptr<CellRayTracer> tracer_;
  double max_diameter_ =
      0.0;  // the longest distance between two vertices of a cell: no ray segment in a cell is longer
};

}  // namespace cellproj
