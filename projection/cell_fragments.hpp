#pragma once
// One cell to the pixel fragments it contributes: projection (projected_tet for tetrahedra,
// projected_cell's image-plane subdivision for the others), rasterization of its triangles with the
// shared coverage rule (view/raster.hpp), and per pixel the light of the ray segment through it by
// the chosen method. Fragments are composited in visibility order.
#include <cstdint>
#include <vector>

#include "base/huge_pages.hpp"
#include "composite/fragment.hpp"
#include "composite/gl_corner.hpp"
#include "composite/opaque_mask.hpp"
#include "mesh/tetrahedralize.hpp"
#include "optics/transfer_function.hpp"
#include "optics/two_fields.hpp"
#include "projection/method.hpp"
#include "projection/projected_cell.hpp"
#include "projection/projected_tet.hpp"
#include "projection/segment_batch.hpp"
#include "projection/tet_fan.hpp"
#include "view/depth_limit.hpp"
#include "view/image.hpp"
#include "view/raster.hpp"
#include "view/screen.hpp"

namespace cellproj {

struct ProjectionCounters {
  std::int64_t tets = 0;       // tetrahedra projected
  std::int64_t polyhedra = 0;  // other cells projected whole (image-plane subdivision)
  std::int64_t polygons = 0;   // their front ∩ back polygons (pt-linear and pt-table)
  std::int64_t layered = 0;    // polyhedra drawn as a front and a back layer instead (pt-analytic, pt-breakpoints)
  std::int64_t unmatched = 0;  // their front-layer pixel centres with no back (0 but for rounding)
  std::int64_t subdivisions_looked_up = 0;  // cells whose projection topology was known (the fast path)
  std::int64_t class1 = 0, class2 = 0;
  std::int64_t empty = 0;       // zero projected area (slivers seen edge-on, zero-volume cells)
  std::int64_t behind_eye = 0;  // a vertex at or behind the eye (or its plane): ray cast per pixel (GL, and whole
                                // cells other than tetrahedra: not drawn)
  std::int64_t fragments = 0;
  std::int64_t breakpoint_cells = 0;  // cells whose scalar range holds a breakpoint (cut by pt-breakpoints)
  std::int64_t direct_cells = 0;      // cells too large to buffer, drawn by the compositor itself
  // Early ray termination (front to back): cells not projected in the tile that counts them, every
  // pixel of theirs there opaque already; fragments dropped at opaque pixels.
  std::int64_t hidden_cells = 0, hidden_fragments = 0;
  // Among opaque geometry (view/opaque_depth.hpp): cells a surface cuts (ray cast up to it), and
  // cells wholly behind the surfaces under them (not drawn).
  std::int64_t depth_cut_cells = 0, depth_hidden_cells = 0;
  void add(const ProjectionCounters& o);
  // Only the per-pixel counts (fragments, unmatched, hidden fragments): a cell drawn tile by tile is
  // counted once, by its first tile, and its pixels by every tile.
  void add_pixels(const ProjectionCounters& o) {
    fragments += o.fragments, unmatched += o.unmatched, hidden_fragments += o.hidden_fragments;
  }
};
// Each counter the report shows, with its key (render/report.hpp): f(key, value).
template <class F>
void each_counter(const ProjectionCounters& c, F&& f) {
  f("polyhedra", c.polyhedra), f("polygons", c.polygons), f("layered_polyhedra", c.layered);
  f("layer_pixels_unmatched", c.unmatched), f("subdivisions_looked_up", c.subdivisions_looked_up);
  f("class1_tets", c.class1), f("class2_tets", c.class2), f("empty_tets", c.empty), f("behind_eye_tets", c.behind_eye);
  f("fragments", c.fragments), f("breakpoint_cells", c.breakpoint_cells), f("direct_cells", c.direct_cells);
  f("hidden_cells", c.hidden_cells), f("hidden_fragments", c.hidden_fragments);
  f("depth_cut_cells", c.depth_cut_cells), f("depth_hidden_cells", c.depth_hidden_cells);
}

// Extinction and colour at every point (the corners of the Gouraud-shaded methods), once per frame.
struct PointOptics {
  FrameBuffer<double> kappa;
  FrameBuffer<glm::dvec3> color;
};
// Parallel over points (oneTBB, in the caller's task arena); a null scalar reads as 0 everywhere.
PointOptics point_optics(const double* scalar, std::int64_t n_points, const TransferFunction& tf);

// Colour by another field than the extinction's (optics/two_fields.hpp): the colour field's values
// per point and the transfer function's halves apart. The screen points' scalar is then the
// opacity field.
struct ColorField {
  const double* values = nullptr;
  TwoFieldTransfer tf;
};

// A corner of a Gouraud-shaded triangle (pt-linear, pt-table; MWSC section 2): opacity (pt-linear)
// or kappa_avg (pt-table), thickness, colour.
struct GouraudCorner {
  double a = 0, l = 0;
  glm::dvec3 c{0.0};
};

// A cell's image as triangles with their thick-vertex values, and (pt-linear, pt-table) their
// Gouraud corners: one per worker, so the hot loop allocates nothing once warm.
struct CellScratch {
  std::vector<ProjectedTriangle> tri;
  std::vector<GouraudCorner> corner;  // 3 per triangle
  double smin = 0, smax = 0;          // the cell's scalar range
  SubdivisionCache subdivisions;      // projection topologies met by this worker
  std::vector<double> back;           // a whole cell's back layer: 2 per pixel of its box (project_layers)
  SegmentBatch segments;              // pt-analytic's and pt-breakpoints' fragments of the cell
  ProjectedTet tet;                   // a tetrahedron's projection (tet_triangles)
  GouraudCorner tet_corner[5];        // and its corners (Gouraud methods): thick vertex, then the outline's
  FanPixels fan;                      // its fan over its pixel box (project_fan)
};

// The frame's fixed inputs; project() is const and may run on many threads at once.
class CellFragments {
 public:
  // `table` is needed by pt_table only, `optics` by pt_linear and pt_table. All referenced objects
  // must outlive this.
  // `points` (the recentred points the screen positions came from) serves the cells that reach
  // behind the eye (or the orthographic eye plane), which are ray cast instead of projected.
  // `rays` is the frame's PixelRays on the recentred camera, the one `screen` was made with.
  CellFragments(const ScreenPoints& screen, const PixelRays& rays, const RecentredPoints& points,
                const TransferFunction& tf, ProjectionMethod method, const OpacityTable* table,
                const PointOptics* optics, WholeCells whole_cells = WholeCells::automatic,
                const ColorField* color = nullptr, const DepthLimit* limit = nullptr);
  // Appends the fragments of the cell (point ids `ids`, of `type`) to out.
  void project(const std::int64_t* ids, CellType type, FragmentBands& out, CellScratch& scratch,
               ProjectionCounters& counters) const;
  // Composites the cell's fragments onto image at once ("over"); for cells covering so many pixels
  // that their fragments are not worth storing. In visibility order, from one thread.
  void project(const std::int64_t* ids, CellType type, Image& image, CellScratch& scratch,
               ProjectionCounters& counters) const;
  // The same over image rows `rows` only: a tile's share of the cell, composited by the thread that
  // owns the tile, in visibility order (the pixels outside are left alone).
  void project(const std::int64_t* ids, CellType type, Image& image, RowRange rows, CellScratch& scratch,
               ProjectionCounters& counters) const;
  // A hint for a compositor's look-ahead: starts loading what drawing the cell will read of its n
  // points (their screen positions, and point optics where the method uses them).
  void prefetch_points(const std::int64_t* ids, int n) const;
  // The same front to back ("under"), for early ray termination: fragments at pixels `opaque`
  // holds are dropped, and the pixels they make opaque are added to it.
  void project_under(const std::int64_t* ids, CellType type, Image& image, RowRange rows, OpaqueMask& opaque,
                     CellScratch& scratch, ProjectionCounters& counters) const;
  // Whether every pixel centre of rows `rows` the cell's vertices' box holds is opaque: then
  // nothing of it shows there. False for a cell reaching behind the eye (ray cast) or whose box
  // there holds no centre.
  bool hidden_by(const std::int64_t* ids, CellType type, RowRange rows, const OpaqueMask& opaque) const;
  // Appends the cell's triangles (3 corners each) for the OpenGL back end (pt-linear, pt-table),
  // with texture coordinates on the opacity table's texel centres. `cell` picks the cell's shift of
  // the dither noise, so a pixel's layers get independent noise.
  void triangles(const std::int64_t* ids, CellType type, std::int64_t cell, std::vector<GLCorner>& out,
                 CellScratch& scratch, ProjectionCounters& counters) const;

 private:
  // The tetrahedron in the image (counted): projected into pt, reaching behind the eye, or of zero
  // projected area.
  enum class Seen { projected, behind_eye, empty };
  Seen classify(const Tet& tet, ScreenVertex v[4], ProjectedTet& pt, ProjectionCounters& counters) const;
  // A cell ray cast instead of projected (not counted here): a tetrahedron reaching behind the eye
  // (pt-breakpoints' integral whatever the method), a cell coloured by color_ (pt-analytic and
  // pt-breakpoints), or one the opaque depth cuts. Every pixel's ray clipped against its canonical
  // tetrahedra (the exact renderer's) and cut at the depth, the fields linear over each, the
  // segments integrated in closed form front to back into one fragment.
  template <class Emit>
  void ray_cast_cell(const std::int64_t* ids, CellType type, RowRange rows, Emit& emit,
                     ProjectionCounters& counters) const;
  // Where the cell lies against the opaque depth under its pixels of rows `rows` (limit_ set).
  DepthSide depth_side(const std::int64_t* ids, CellType type, RowRange rows) const;
  // The pixels of rows `rows` a ray cast cell of n vertices may cover: those under its image, one
  // pixel wider, unless in perspective a vertex is behind the eye (then every one).
  PixelBox cast_box(const std::int64_t* ids, int n, RowRange rows) const;
  // project()'s body; emit(i, j, rgb, alpha) stores or composites a fragment, true if it did.
  template <class Emit>
  void project_with(const std::int64_t* ids, CellType type, RowRange rows, Emit& emit, CellScratch& p,
                    ProjectionCounters& counters) const;
  // A tetrahedron (p.tet, and p.tet_corner for the Gouraud methods) drawn as one fan over its pixel
  // box, its quantities in SIMD lanes (tet_fan.hpp); false (nothing drawn) for a box of more than
  // kFanUpToPixels, or a face seen edge-on (there the outline is thick, and a centre on it must go
  // to one tetrahedron by view/raster.hpp's rule, which the triangles keep).
  template <class Emit>
  bool project_fan(RowRange rows, Emit& emit, CellScratch& p, ProjectionCounters& counters) const;
  // Whether a cell other than a tetrahedron is drawn by its layers (else by its subdivision's
  // polygons): the same answer in every tile of the image.
  bool by_layers(const std::int64_t* ids, CellType type) const;
  // A cell other than a tetrahedron by its layers (every method but the Gouraud ones' polygons):
  // its back face triangles rasterized into a buffer over its pixels, then its front ones, each
  // pixel meeting its back.
  template <class Emit>
  void project_layers(const std::int64_t* ids, CellType type, RowRange rows, Emit& emit, CellScratch& p,
                      ProjectionCounters& counters) const;
  // A cell's screen vertices into v and its scalar range into p; false (counted) if one reaches
  // behind the eye.
  bool load_cell(const std::int64_t* ids, CellType type, ScreenVertex* v, CellScratch& p,
                 ProjectionCounters& counters) const;
  // The tetrahedron's or cell's triangles into p (counted); the tetrahedra and cells not projected
  // say why.
  // A cell's corners (Gouraud methods) are shaded with its triangles when shade_cells, else left
  // to shade_corners() as each triangle is drawn (a tetrahedron's always are).
  Seen triangles_of(const std::int64_t* ids, CellType type, CellScratch& p, ProjectionCounters& counters,
                    bool shade_cells) const;
  // A tetrahedron's projection and corners into p.tet and p.tet_corner, and with `triangles` its
  // fan as p.tri and p.corner (fan_triangles).
  Seen tet_triangles(const Tet& tet, CellScratch& p, ProjectionCounters& counters, bool triangles = true) const;
  void fan_triangles(CellScratch& p) const;
  Seen cell_triangles(const std::int64_t* ids, CellType type, CellScratch& p, ProjectionCounters& counters,
                      bool shade) const;
  // The corner of a Gouraud-shaded method from a thick vertex's segment (MWSC section 2).
  GouraudCorner shade(const ThickVertex& t) const;
  // Triangle t's three corners into p.corner, each copied from triangle `reuse`'s (when reuse < t)
  // where that has the same thick vertex, bit for bit: a polygon's fan triangles share two.
  void shade_corners(CellScratch& p, std::size_t t, std::size_t reuse) const;

  const ScreenPoints& screen_;
  const PixelRays& rays_;
  const RecentredPoints& points_;
  const TransferFunction& tf_;
  MethodTraits method_;
  const OpacityTable* table_;
  const PointOptics* optics_;
  int front_sign_;  // exact_sign of a face turned towards the eye
  WholeCells whole_cells_;
  const ColorField* color_;  // null: colour and extinction from the one field
  const DepthLimit* limit_;  // null: no opaque geometry
};

}  // namespace cellproj
