#include "frame/gl_frame.hpp"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "base/error.hpp"
#include "composite/ordered_pipeline.hpp"
#ifdef CELLPROJ_HAVE_OPENGL
#include "composite/gl_compositor.hpp"
#endif

namespace cellproj {

#ifndef CELLPROJ_HAVE_OPENGL
Image draw_with_opengl(const CellFragments&, const MeshView&, const std::vector<std::int64_t>&, const OpacityTable*,
                       int, int, const ProjectionOptions&, ProjectionStats&) {
  throw ResourceError("this cellproj was built without the OpenGL back ends (OSMesa was not found)");
}
#else
Image draw_with_opengl(const CellFragments& project, const MeshView& cells, const std::vector<std::int64_t>& order,
                       const OpacityTable* table, int width, int height, const ProjectionOptions& options,
                       ProjectionStats& st) {
  const GLTarget target = gl_target(options.backend);
  GLCompositor gl(width, height, target);  // its calls stay on this thread; workers only make triangles
  st.gl_renderer = gl.renderer();
  gl.begin(table);
  const std::size_t batch = batch_size(static_cast<std::size_t>(std::max(options.batch_cells, 0)), order.size());
  const std::size_t window = 64;  // batches made at once, then drawn in order
  std::vector<std::vector<GLCorner> > corners(window);
  std::vector<ProjectionCounters> counters(window);
  std::vector<CellScratch> scratch(window);
  for (std::size_t first = 0; first < order.size(); first += window * batch) {
    const std::size_t n = std::min(window, (order.size() - first + batch - 1) / batch);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t b) {
      corners[b].clear();
      counters[b] = {};
      const std::size_t end = std::min(order.size(), first + (b + 1) * batch);
      for (std::size_t k = first + b * batch; k < end; ++k) {
        const std::int64_t c = order[k];
        project.triangles(cells.cell(c), cells.type(c), c, corners[b], scratch[b], counters[b]);
      }
    });
    for (std::size_t b = 0; b < n; ++b) gl.draw(corners[b]), st.counters.add(counters[b]);
  }
  return gl.finish();
}

#endif

}  // namespace cellproj
