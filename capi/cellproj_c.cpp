// The C API (capi/cellproj.h) over the façade: each handle holds the C++ object, each call turns
// exceptions into a status and this thread's message, the C analogue of errno.
#include "cellproj.h"

#include <map>
#include <memory>
#include <new>
#include <optional>
#include <string>

#include <tbb/task_arena.h>

#include "base/error.hpp"
#include "optics/colormaps.hpp"
#include "render/field_set.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "scene/prepare.hpp"
#include "scene/quick_scene.hpp"
#include "view/camera_moves.hpp"

using namespace cellproj;

struct cp_mesh {
  std::shared_ptr<const Mesh> read;  // a reader's mesh, or null
  std::optional<Volume> volume;      // committed once
  FieldSet fields;                   // the caller's values (or the read mesh's), by name
};
struct cp_transfer_function {
  TransferFunction tf;
};
struct cp_camera {
  Camera camera;
};
struct cp_renderer {
  RenderOptions options;
  int threads = 0;
};
struct cp_image {
  Image image;
};

namespace {

thread_local std::string last_error;

// Runs f, returning CP_OK, or the status of what it threw with its message kept for cp_last_error.
template <class F>
cp_status guarded(F&& f) {
  last_error.clear();
  try {
    f();
    return CP_OK;
  } catch (const InputError& e) {
    last_error = e.what();
    return CP_ERROR_INPUT;
  } catch (const ResourceError& e) {
    last_error = e.what();
    return CP_ERROR_RESOURCE;
  } catch (const std::bad_alloc&) {
    last_error = "out of memory";
    return CP_ERROR_RESOURCE;
  } catch (const std::exception& e) {
    last_error = std::string("internal error: ") + e.what();
    return CP_ERROR_INTERNAL;
  }
}

cp_status null_argument(const char* function, const char* argument) {
  last_error = std::string(function) + ": " + argument + " is NULL";
  return CP_ERROR_NULL;
}

#define CP_NEED(function, argument) \
  if (!(argument)) return null_argument(function, #argument)

cp_status create_mesh(const double* points, int64_t n_points, const void* connectivity, const void* offsets,
                      const uint8_t* types, int64_t n_cells, bool ids_32bit, cp_mesh** mesh) {
  CP_NEED("cp_mesh_create", points);
  CP_NEED("cp_mesh_create", connectivity);
  CP_NEED("cp_mesh_create", offsets);
  CP_NEED("cp_mesh_create", types);
  CP_NEED("cp_mesh_create", mesh);
  *mesh = nullptr;
  return guarded([&] {
    auto m = std::make_unique<cp_mesh>();
    CellArrays cells{connectivity, offsets, types, n_cells, ids_32bit, -1};
    m->volume.emplace(PointArray(points), n_points, cells, "C arrays");
    *mesh = m.release();
  });
}

}  // namespace

extern "C" {

const char* cp_last_error(void) { return last_error.c_str(); }

cp_status cp_mesh_create(const double* points, int64_t n_points, const int64_t* connectivity, const int64_t* offsets,
                         const uint8_t* types, int64_t n_cells, cp_mesh** mesh) {
  return create_mesh(points, n_points, connectivity, offsets, types, n_cells, false, mesh);
}

cp_status cp_mesh_create_int32(const double* points, int64_t n_points, const int32_t* connectivity,
                               const int32_t* offsets, const uint8_t* types, int64_t n_cells, cp_mesh** mesh) {
  return create_mesh(points, n_points, connectivity, offsets, types, n_cells, true, mesh);
}

cp_status cp_mesh_read(const char* path, cp_mesh** mesh) {
  CP_NEED("cp_mesh_read", path);
  CP_NEED("cp_mesh_read", mesh);
  *mesh = nullptr;
  return guarded([&] {
    auto m = std::make_unique<cp_mesh>();
    m->read = std::make_shared<const Mesh>(load_mesh(path).mesh);
    m->volume.emplace(m->read->view(), VolumeOptions{/*trusted: load_mesh validated it*/ true});
    m->fields.add(*m->volume, *m->read);
    *mesh = m.release();
  });
}

cp_status cp_mesh_set_field(cp_mesh* mesh, const char* name, const double* values, int64_t n_values) {
  CP_NEED("cp_mesh_set_field", mesh);
  CP_NEED("cp_mesh_set_field", name);
  CP_NEED("cp_mesh_set_field", values);
  return guarded([&] { mesh->fields.set(*mesh->volume, name, values, n_values); });
}

cp_status cp_mesh_set_vector_field(cp_mesh* mesh, const char* name, const double* values, int64_t n_points,
                                   int n_components) {
  CP_NEED("cp_mesh_set_vector_field", mesh);
  CP_NEED("cp_mesh_set_vector_field", name);
  CP_NEED("cp_mesh_set_vector_field", values);
  return guarded([&] {
    if (n_components < 1 || n_components > 9)
      throw InputError(std::string("cp_mesh_set_vector_field: field '") + name +
                       "': n_components must be 1 to 9, got " + std::to_string(n_components));
    mesh->fields.set(*mesh->volume, name, values, n_points * n_components, n_components);
  });
}

int64_t cp_mesh_cells(const cp_mesh* mesh) { return mesh ? mesh->volume->mesh().n_cells : 0; }
void cp_mesh_release(cp_mesh* mesh) { delete mesh; }

cp_status cp_transfer_function_create(const double* color, int n_color, const double* extinction, int n_extinction,
                                      cp_transfer_function** tf) {
  CP_NEED("cp_transfer_function_create", color);
  CP_NEED("cp_transfer_function_create", extinction);
  CP_NEED("cp_transfer_function_create", tf);
  *tf = nullptr;
  return guarded([&] {
    std::vector<ColorPoint> c;
    for (int i = 0; i < n_color; ++i)
      c.push_back({color[4 * i], {color[4 * i + 1], color[4 * i + 2], color[4 * i + 3]}});
    std::vector<ExtinctionPoint> e;
    for (int i = 0; i < n_extinction; ++i) e.push_back({extinction[2 * i], extinction[2 * i + 1]});
    *tf = new cp_transfer_function{TransferFunction(std::move(c), std::move(e), "cp_transfer_function_create")};
  });
}

cp_status cp_transfer_function_create_colormap(const char* colormap_name, double lo, double hi,
                                               const double* extinction, int n_extinction, cp_transfer_function** tf) {
  CP_NEED("cp_transfer_function_create_colormap", colormap_name);
  CP_NEED("cp_transfer_function_create_colormap", extinction);
  CP_NEED("cp_transfer_function_create_colormap", tf);
  *tf = nullptr;
  return guarded([&] {
    std::vector<ExtinctionPoint> e;
    for (int i = 0; i < n_extinction; ++i) e.push_back({extinction[2 * i], extinction[2 * i + 1]});
    *tf = new cp_transfer_function{
        TransferFunction(colormap(colormap_name, lo, hi), std::move(e), "cp_transfer_function_create_colormap")};
  });
}

void cp_transfer_function_release(cp_transfer_function* tf) { delete tf; }

cp_status cp_camera_create(const double eye[3], const double target[3], const double up[3], int perspective,
                           double size_or_fov, cp_camera** camera) {
  CP_NEED("cp_camera_create", eye);
  CP_NEED("cp_camera_create", target);
  CP_NEED("cp_camera_create", up);
  CP_NEED("cp_camera_create", camera);
  *camera = nullptr;
  return guarded([&] {
    Camera c;
    c.projection = perspective ? Projection::Perspective : Projection::Orthographic;
    c.eye = {eye[0], eye[1], eye[2]};
    c.target = {target[0], target[1], target[2]};
    c.up = {up[0], up[1], up[2]};
    (perspective ? c.fov_y : c.height) = size_or_fov;
    check_camera(c, "cp_camera_create");
    *camera = new cp_camera{c};
  });
}

cp_status cp_camera_move(cp_camera* camera, const char* move, const char* value) {
  CP_NEED("cp_camera_move", camera);
  CP_NEED("cp_camera_move", move);
  CP_NEED("cp_camera_move", value);
  return guarded([&] {
    CameraMoves m;
    set_camera_move(m, move, value);
    camera->camera = moved(camera->camera, m);  // kept only when the moved camera is valid
  });
}

cp_status cp_camera_frame(const cp_mesh* mesh, const char* view, double aspect, cp_camera** camera) {
  CP_NEED("cp_camera_frame", mesh);
  CP_NEED("cp_camera_frame", camera);
  *camera = nullptr;
  return guarded([&] {
    if (!(aspect > 0)) throw InputError("cp_camera_frame: aspect must be positive, got " + std::to_string(aspect));
    const auto [lo, hi] = bounds(mesh->volume->mesh());
    *camera = new cp_camera{view_camera(view ? view : "", lo, hi, aspect)};
  });
}

void cp_camera_release(cp_camera* camera) { delete camera; }

cp_status cp_renderer_create(const char* method, cp_renderer** renderer) {
  CP_NEED("cp_renderer_create", method);
  CP_NEED("cp_renderer_create", renderer);
  *renderer = nullptr;
  return guarded([&] {
    auto r = std::make_unique<cp_renderer>();
    set_option(r->options, "method", method);
    make_renderer(settings_from(r->options));  // the method checked now
    *renderer = r.release();
  });
}

cp_status cp_renderer_set(cp_renderer* renderer, const char* option, const char* value) {
  CP_NEED("cp_renderer_set", renderer);
  CP_NEED("cp_renderer_set", option);
  CP_NEED("cp_renderer_set", value);
  return guarded([&] {
    RenderOptions o = renderer->options;
    set_option(o, option, value);
    const RenderSettings settings = settings_from(o);
    make_renderer(settings);  // checked now, kept only when good
    refuse_unused(settings, o.given);
    renderer->options = std::move(o);
  });
}

cp_status cp_renderer_set_threads(cp_renderer* renderer, int threads) {
  CP_NEED("cp_renderer_set_threads", renderer);
  return guarded([&] {
    worker_threads(threads);  // checked now
    renderer->threads = threads;
  });
}

void cp_renderer_release(cp_renderer* renderer) { delete renderer; }

cp_status cp_render(const cp_renderer* renderer, const cp_mesh* mesh, const char* field, const cp_transfer_function* tf,
                    const cp_camera* camera, int width, int height, cp_image** image) {
  return cp_render_two_fields(renderer, mesh, field, nullptr, tf, camera, width, height, image);
}

cp_status cp_render_two_fields(const cp_renderer* renderer, const cp_mesh* mesh, const char* field,
                               const char* opacity_field, const cp_transfer_function* tf, const cp_camera* camera,
                               int width, int height, cp_image** image) {
  CP_NEED("cp_render", renderer);
  CP_NEED("cp_render", mesh);
  CP_NEED("cp_render", tf);
  CP_NEED("cp_render", camera);
  CP_NEED("cp_render", image);
  *image = nullptr;
  return guarded([&] {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
      throw InputError("cp_render: image size must be 1 to 16384 pixels a side, got " + std::to_string(width) + "x" +
                       std::to_string(height));
    if (mesh->fields.empty()) throw InputError("cp_render: the mesh has no fields (cp_mesh_set_field)");
    Field values = mesh->fields.scalar(field ? field : "", "cp_render");
    if (opacity_field) {
      const Field opacity = mesh->fields.scalar(opacity_field, "cp_render");
      values.opacity = opacity.values, values.opacity_name = opacity.name;
    }
    const std::unique_ptr<Renderer> r = make_renderer(settings_from(renderer->options));
    tbb::task_arena arena(worker_threads(renderer->threads));
    Image img = arena.execute([&] {
      return r->render(*mesh->volume, values, tf->tf, camera->camera, {width, height});
    });
    *image = new cp_image{std::move(img)};
  });
}

int cp_image_width(const cp_image* image) { return image ? image->image.width : 0; }
int cp_image_height(const cp_image* image) { return image ? image->image.height : 0; }
const float* cp_image_rgba(const cp_image* image) { return image ? image->image.rgba.data() : nullptr; }

cp_status cp_image_write_png(const cp_image* image, const char* path, const double background[3]) {
  CP_NEED("cp_image_write_png", image);
  CP_NEED("cp_image_write_png", path);
  return guarded([&] {
    const glm::dvec3 bg = background ? glm::dvec3(background[0], background[1], background[2]) : glm::dvec3(0.0);
    write_png(image->image, bg, path);
  });
}

void cp_image_release(cp_image* image) { delete image; }

}  // extern "C"
