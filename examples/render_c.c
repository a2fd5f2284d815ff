/* A solver in C: a unit cube of five tetrahedra with a linear field, rendered through the C API
 * with the exact reference and with cell projection; the two must agree (pt-breakpoints is exact
 * for tetrahedra), and bad input must come back as a status with a message.
 * usage: render_c OUT.png  (exit 0 when everything holds) */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <cellproj.h>

#define CHECK(call)                                                         \
  do {                                                                      \
    if ((call) != CP_OK) {                                                  \
      fprintf(stderr, "render_c: %s failed: %s\n", #call, cp_last_error()); \
      return 1;                                                             \
    }                                                                       \
  } while (0)

int main(int argc, char** argv) {
  const char* out = argc > 1 ? argv[1] : "render_c.png";
  const double points[8 * 3] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  const int32_t connectivity[5 * 4] = {0, 1, 3, 4, 1, 2, 3, 6, 1, 4, 5, 6, 3, 4, 6, 7, 1, 3, 4, 6};
  const int32_t offsets[6] = {0, 4, 8, 12, 16, 20};
  const uint8_t types[5] = {10, 10, 10, 10, 10};
  double temperature[8], density[8];
  for (int p = 0; p < 8; ++p)
    temperature[p] = points[3 * p] + 0.5 * points[3 * p + 2], density[p] = 0.2 + points[3 * p + 1] * points[3 * p + 2];

  cp_mesh* mesh = NULL;
  CHECK(cp_mesh_create_int32(points, 8, connectivity, offsets, types, 5, &mesh));
  CHECK(cp_mesh_set_field(mesh, "temperature", temperature, 8));
  const double extinction[2 * 2] = {0.0, 0.5, 1.5, 4.0};
  cp_transfer_function* tf = NULL;
  CHECK(cp_transfer_function_create_colormap("viridis", 0.0, 1.5, extinction, 2, &tf));
  cp_camera* camera = NULL;
  CHECK(cp_camera_frame(mesh, "iso", 1.0, &camera));
  CHECK(cp_camera_move(camera, "azimuth", "20")); /* ParaView's camera moves, by name */
  CHECK(cp_camera_move(camera, "zoom", "1.2"));

  cp_renderer *exact = NULL, *projection = NULL;
  CHECK(cp_renderer_create("exact", &exact));
  CHECK(cp_renderer_create("pt-breakpoints", &projection));
  CHECK(cp_renderer_set(projection, "sort", "mpvo"));
  CHECK(cp_renderer_set_threads(projection, 2));
  cp_image *reference = NULL, *image = NULL;
  CHECK(cp_render(exact, mesh, "temperature", tf, camera, 96, 96, &reference));
  CHECK(cp_render(projection, mesh, NULL, tf, camera, 96, 96, &image));

  const float *a = cp_image_rgba(reference), *b = cp_image_rgba(image);
  double max_diff = 0.0, alpha_sum = 0.0;
  for (int i = 0; i < 96 * 96 * 4; ++i) {
    const double d = fabs((double)a[i] - b[i]);
    if (d > max_diff) max_diff = d;
    if (i % 4 == 3) alpha_sum += a[i];
  }
  printf("render_c: exact vs pt-breakpoints max |difference| %.2e, mean opacity %.3f\n", max_diff,
         alpha_sum / (96 * 96));
  const double white[3] = {1, 1, 1};
  CHECK(cp_image_write_png(image, out, white));
  cp_image_release(image); /* the calls below that fail set it to NULL */
  image = NULL;

  /* Colour by temperature, extinction by density: pt-breakpoints is exact for two fields too. */
  CHECK(cp_mesh_set_field(mesh, "density", density, 8));
  cp_image *reference2 = NULL, *image2 = NULL;
  CHECK(cp_render_two_fields(exact, mesh, "temperature", "density", tf, camera, 96, 96, &reference2));
  CHECK(cp_render_two_fields(projection, mesh, "temperature", "density", tf, camera, 96, 96, &image2));
  double max_diff2 = 0.0;
  for (int i = 0; i < 96 * 96 * 4; ++i) {
    const double d = fabs((double)cp_image_rgba(reference2)[i] - cp_image_rgba(image2)[i]);
    if (d > max_diff2) max_diff2 = d;
  }
  printf("render_c: two fields, exact vs pt-breakpoints max |difference| %.2e\n", max_diff2);
  cp_image_release(reference2);
  cp_image_release(image2);
  if (max_diff2 > 1e-5) max_diff = max_diff2;

  /* Bad input: a status and a message naming what is wrong, never a crash. */
  int failures = 0;
  const int32_t bad[4] = {0, 1, 2, 9};
  cp_mesh* broken = NULL;
  if (cp_mesh_create_int32(points, 8, bad, offsets, types, 1, &broken) != CP_ERROR_INPUT || broken ||
      !strstr(cp_last_error(), "out of range"))
    ++failures, fprintf(stderr, "render_c: an out-of-range id gave '%s'\n", cp_last_error());
  if (cp_renderer_set(exact, "sort", "mpvo") != CP_ERROR_INPUT || !strstr(cp_last_error(), "does not apply"))
    ++failures, fprintf(stderr, "render_c: an unused option gave '%s'\n", cp_last_error());
  if (cp_renderer_set_threads(projection, 1000000000) != CP_ERROR_INPUT ||
      !strstr(cp_last_error(), "setting 'threads'"))
    ++failures, fprintf(stderr, "render_c: a billion threads gave '%s'\n", cp_last_error());
  if (cp_camera_move(camera, "zoom", "-2") != CP_ERROR_INPUT || !strstr(cp_last_error(), "setting 'zoom'"))
    ++failures, fprintf(stderr, "render_c: a negative zoom gave '%s'\n", cp_last_error());
  if (cp_mesh_set_field(mesh, "short", temperature, 7) != CP_ERROR_INPUT)
    ++failures, fprintf(stderr, "render_c: a short field was taken\n");
  if (cp_render(projection, mesh, "pressure", tf, camera, 8, 8, &image) != CP_ERROR_INPUT ||
      !strstr(cp_last_error(), "no point field named 'pressure'"))
    ++failures, fprintf(stderr, "render_c: a missing field gave '%s'\n", cp_last_error());
  cp_renderer* linear = NULL;
  CHECK(cp_renderer_create("pt-linear", &linear));
  if (cp_render_two_fields(linear, mesh, "temperature", "density", tf, camera, 8, 8, &image) != CP_ERROR_INPUT ||
      !strstr(cp_last_error(), "setting 'opacity-field'"))
    ++failures, fprintf(stderr, "render_c: two fields in pt-linear gave '%s'\n", cp_last_error());
  cp_renderer_release(linear);
  if (cp_render(projection, NULL, NULL, tf, camera, 8, 8, &image) != CP_ERROR_NULL)
    ++failures, fprintf(stderr, "render_c: a NULL mesh was not refused\n");

  cp_image_release(image);
  cp_image_release(reference);
  cp_renderer_release(projection);
  cp_renderer_release(exact);
  cp_camera_release(camera);
  cp_transfer_function_release(tf);
  cp_mesh_release(mesh);
  if (max_diff > 1e-5 || alpha_sum / (96 * 96) < 0.05) ++failures, fprintf(stderr, "render_c: pictures disagree\n");
  if (failures == 0) printf("render_c: wrote %s; all checks hold\n", out);
  return failures ? 1 : 0;
}
