/* cellproj's C API: volume rendering of a solver's unstructured mesh from C or Fortran (through
 * ISO_C_BINDING). Opaque handles, functions returning a status, and a message per thread for the
 * last failure. No C++ type crosses this header. Link cellproj::capi. docs/c_api.md.
 *
 *   cp_mesh* mesh; cp_mesh_create(points, n_points, connectivity, offsets, types, n_cells, &mesh);
 *   cp_mesh_set_field(mesh, "T", values, n_points);
 *   ... cp_render(renderer, mesh, "T", tf, camera, 512, 512, &image);
 *   if (status != CP_OK) fprintf(stderr, "%s\n", cp_last_error());
 */
#ifndef CELLPROJ_H
#define CELLPROJ_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cp_status {
  CP_OK = 0,
  CP_ERROR_INPUT = 1,    /* bad input: a mesh, field, transfer function, camera or option */
  CP_ERROR_RESOURCE = 2, /* a resource the machine lacks (memory, an OpenGL context) */
  CP_ERROR_INTERNAL = 3, /* a bug in cellproj */
  CP_ERROR_NULL = 4      /* a required pointer argument was NULL */
} cp_status;

typedef struct cp_mesh cp_mesh;
typedef struct cp_transfer_function cp_transfer_function;
typedef struct cp_camera cp_camera;
typedef struct cp_renderer cp_renderer;
typedef struct cp_image cp_image;

/* The message of this thread's last failed call ("" when none failed): valid until its next call. */
const char* cp_last_error(void);

/* A mesh over the caller's arrays, in VTK's layout: points x y z per point (doubles);
 * cell c is connectivity[offsets[c] .. offsets[c+1]) with VTK type types[c] (10 tetra, 11 voxel,
 * 12 hexahedron, 13 wedge, 14 pyramid); offsets has n_cells + 1 entries. Validated now; the arrays
 * are not copied (32-bit ids are widened once) and must outlive the mesh. */
cp_status cp_mesh_create(const double* points, int64_t n_points, const int64_t* connectivity, const int64_t* offsets,
                         const uint8_t* types, int64_t n_cells, cp_mesh** mesh);
cp_status cp_mesh_create_int32(const double* points, int64_t n_points, const int32_t* connectivity,
                               const int32_t* offsets, const uint8_t* types, int64_t n_cells, cp_mesh** mesh);
/* Reads and validates a mesh file (any format `cellproj info` reads); the mesh owns its arrays. */
cp_status cp_mesh_read(const char* path, cp_mesh** mesh);
/* A point field: one finite value per point, not copied (must outlive its renders). A field of the
 * same name is replaced; a read mesh's fields are there already. */
cp_status cp_mesh_set_field(cp_mesh* mesh, const char* name, const double* values, int64_t n_values);
/* A vector or tensor field: n_components (1 to 9) finite values per point, interleaved (x y z x y
 * z ...), not copied. cp_render picks a scalar of it by name: "V:x", "V_X", "V:magnitude", "V:2",
 * "S:von_mises" for a 6- or 9-component tensor, or "V" alone for its magnitude. */
cp_status cp_mesh_set_vector_field(cp_mesh* mesh, const char* name, const double* values, int64_t n_points,
                                   int n_components);
int64_t cp_mesh_cells(const cp_mesh* mesh);
void cp_mesh_release(cp_mesh* mesh);

/* color: n_color rows of (s, r, g, b); extinction: n_extinction rows of (s, kappa), s increasing. */
cp_status cp_transfer_function_create(const double* color, int n_color, const double* extinction, int n_extinction,
                                      cp_transfer_function** tf);
/* The same with a built-in colour map ("viridis", "Cool to Warm", ...) stretched over [lo, hi]. */
cp_status cp_transfer_function_create_colormap(const char* colormap, double lo, double hi, const double* extinction,
                                               int n_extinction, cp_transfer_function** tf);
void cp_transfer_function_release(cp_transfer_function* tf);

/* perspective != 0: fov_y is the full vertical angle in degrees (size_or_fov); else the
 * orthographic view's world height. */
cp_status cp_camera_create(const double eye[3], const double target[3], const double up[3], int perspective,
                           double size_or_fov, cp_camera** camera);
/* An orthographic camera framing the mesh from a named view: "+x", "-x", "+y", "-y", "+z", "-z",
 * "iso", or "" (the scene files' default); aspect = width / height. */
cp_status cp_camera_frame(const cp_mesh* mesh, const char* view, double aspect, cp_camera** camera);
/* Moves the camera as ParaView moves it, by the move's name: "azimuth", "elevation", "roll"
   (degrees), "zoom", "dolly" (factors), "focus" ("x,y,z"), "perspective" ("" or an angle),
   "parallel" (""); the same names and meanings as cellproj render's options. */
cp_status cp_camera_move(cp_camera* camera, const char* move, const char* value);
void cp_camera_release(cp_camera* camera);

/* A renderer for a method of the command line ("pt-breakpoints", "pt-linear", "exact", "slicing"). */
cp_status cp_renderer_create(const char* method, cp_renderer** renderer);
/* An option by its command-line name and text: "sort" "mpvo", "slices" "128", "table-size" "64". */
cp_status cp_renderer_set(cp_renderer* renderer, const char* option, const char* value);
/* Worker threads for its renders; 0 (the default): all cores. */
cp_status cp_renderer_set_threads(cp_renderer* renderer, int threads);
void cp_renderer_release(cp_renderer* renderer);

/* One picture of `field` ("" or NULL: the mesh's only field; a vector's component as
 * cp_mesh_set_vector_field says). */
cp_status cp_render(const cp_renderer* renderer, const cp_mesh* mesh, const char* field, const cp_transfer_function* tf,
                    const cp_camera* camera, int width, int height, cp_image** image);

/* The same coloured by `field` and opaque by `opacity_field` (ParaView's separate opacity array):
 * the transfer function's colour over the one's values, its extinction over the other's. Drawn by
 * the methods "exact", "pt-breakpoints" (exact too) and "pt-analytic"; the others refuse it. */
cp_status cp_render_two_fields(const cp_renderer* renderer, const cp_mesh* mesh, const char* field,
                               const char* opacity_field, const cp_transfer_function* tf, const cp_camera* camera,
                               int width, int height, cp_image** image);

int cp_image_width(const cp_image* image);
int cp_image_height(const cp_image* image);
/* Premultiplied RGBA floats, 4 per pixel, row-major from the top row. */
const float* cp_image_rgba(const cp_image* image);
/* An 8-bit PNG over the background colour (r, g, b in [0, 1]; NULL: black). */
cp_status cp_image_write_png(const cp_image* image, const char* path, const double background[3]);
void cp_image_release(cp_image* image);

#ifdef __cplusplus
}
#endif

#endif /* CELLPROJ_H */
