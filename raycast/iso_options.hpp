#pragma once
// Semi-transparent iso-surfaces drawn with the volume (raycast/iso_surfaces.hpp): which surfaces,
// how their opacity depends on the view, and how they are composited (libMini's modes, Roettger
// section 4, against the exact visibility order).
#include <vector>

#include <glm/vec3.hpp>

namespace cellproj {

struct IsoSurface {
  double value = 0.0;
  glm::dvec3 color{1.0};
  double opacity = 1.0;     // seen head-on (the view along the surface's normal)
  bool color_given = true;  // false: the transfer function's colour at `value`
};

enum class IsoMode {
  ordered,  // surfaces and volume slabs composited in exact order along each ray: the reference
  blend2,   // the volume first, then the surfaces blended over it in submission (cell) order: the baseline
  oit3,     // libMini's 3 passes: opaque part, times the surfaces' attenuations, plus their emissions
  oit4,     // as oit3, with emissions only from surfaces at or before the front-most back face
};

enum class IsoOpacity {
  constant,      // every view
  spectrum,      // a thin layer seen at angle t: 1 - exp(-c d / |cos t|), c d from the head-on opacity
  spectrum_fit,  // libMini's cheaper cosine-power fit of it: 1 - (1 - opacity) |cos t|^p
};

struct IsoOptions {
  std::vector<IsoSurface> surfaces;
  bool volume = true;  // the transfer function's volume between the surfaces
  IsoMode mode = IsoMode::ordered;
  IsoOpacity opacity = IsoOpacity::constant;
};

// InputError naming the option for a non-finite value, a colour or opacity outside [0, 1].
void check(const IsoOptions& options);

// The opacity of a surface of head-on opacity `a` seen at |cos t| = c (0 < c <= 1) under `model`;
// spectrum_fit takes the exponent spectrum_fit_exponent(a) gave (fitted once per surface).
double iso_opacity(IsoOpacity model, double a, double c, double fit_exponent = 0.0);
// The exponent p of the cosine-power fit for head-on opacity a: the least-squares fit of
// 1 - (1 - a) c^p to 1 - (1 - a)^(1/c) over c in (0, 1]; and the largest difference it leaves.
double spectrum_fit_exponent(double a, double* max_error = nullptr);

}  // namespace cellproj
