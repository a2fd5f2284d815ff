#pragma once
// The OpenGL back ends' frame: triangles made by parallel workers, drawn in visibility order by the
// one thread that owns the context (composite/gl_compositor).
#include <cstdint>
#include <vector>

#include "frame/projection_renderer.hpp"
#include "mesh/mesh.hpp"

namespace cellproj {

// Counts into st.counters and names the GL renderer in st.gl_renderer.
Image draw_with_opengl(const CellFragments& project, const MeshView& cells, const std::vector<std::int64_t>& order,
                       const OpacityTable* table, int width, int height, const ProjectionOptions& options,
                       ProjectionStats& st);

}  // namespace cellproj
