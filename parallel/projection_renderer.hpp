#pragma once
// Cell projection end to end (MWSC sections 2, 3 and 7): the cells in visibility order feed
// batches to projection workers (oneTBB pipeline), and one compositor blends their fragments in
// order, so 1 and N threads give the same image bit for bit.
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "grid/mesh.hpp"
#include "grid/topology.hpp"
#include "optics/transfer_function.hpp"
#include "projection/method.hpp"
#include "projection/tet_fragments.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"
#include "visibility/sort.hpp"

namespace cellproj {

struct ProjectionOptions {
  ProjectionMethod method = ProjectionMethod::pt_breakpoints;
  ProjectionBackend backend = ProjectionBackend::software;  // the OpenGL ones draw pt-linear and pt-table
  SortMethod sort = SortMethod::automatic;
  int table_size = 256;      // pt-table: nodes per axis of the opacity table
  int batch_cells = 0;       // cells per pipeline token; 0: about 16 tokens per thread, 64 to 2048
};

struct ProjectionStats {
  ProjectionCounters counters;
  SortStats sort;
  std::int64_t tets = 0;               // tetrahedra projected per frame (after the canonical split)
  std::int64_t cells_split = 0;        // mesh cells that are not tetrahedra, split once per mesh
  std::vector<std::pair<std::string, double>> phase_seconds;  // project points, sort, project+composite
  std::string gl_renderer;             // the OpenGL back ends: GL_RENDERER
  double seconds = 0.0;
};

class ProjectionRenderer {
 public:
  // Prepared once per mesh and field (the mesh's arrays must outlive the renderer): cells other
  // than tetrahedra are split canonically (grid/tetrahedralize), then face topology, convexity of
  // the boundary and the visibility sorter of the tetrahedra.
  explicit ProjectionRenderer(const MeshView& mesh);
  ~ProjectionRenderer();

  // Threads: those of the task arena it is called from.
  Image render(const TransferFunction& tf, const Camera& camera, int width, int height,
               const ProjectionOptions& options = {}, ProjectionStats* stats = nullptr) const;

  std::int64_t tets() const { return tets_.n_cells; }
  std::int64_t cells_split() const { return cells_split_; }
  bool convex_boundary() const;

 private:
  // The OpenGL back ends: triangles made by parallel workers, drawn in visibility order.
  Image render_gl(const TetFragments& project, const std::vector<std::int64_t>& order, const OpacityTable* table,
                  int width, int height, const ProjectionOptions& options, ProjectionStats& st) const;

  Tet tet(std::int64_t c) const {
    const std::int64_t* id = tets_.cell(c);
    return {id[0], id[1], id[2], id[3]};
  }

  std::optional<Mesh> split_;   // the canonical tetrahedra, when the mesh had other cells
  MeshView tets_;
  std::int64_t cells_split_ = 0;
  FaceTopology topology_;
  HullReport hull_;
  std::unique_ptr<VisibilitySorter> sorter_;
  RecentredPoints points_;
  double max_edge_ = 0.0;       // longest tetrahedron edge: no ray segment in a cell is longer
};

}  // namespace cellproj
