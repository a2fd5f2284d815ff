#include "raycast/isoparametric.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>

namespace cellproj {

int shape_functions(CellType type, const glm::dvec3& xi, double* w, glm::dvec3* dw) {
  const double r = xi.x, s = xi.y, t = xi.z, rm = 1 - r, sm = 1 - s, tm = 1 - t;
  switch (type) {
    case CellType::Hexahedron: {  // trilinear; vertices 0-3 the bottom quad, 4-7 the top
      const double a[8] = {rm * sm, r * sm, r * s, rm * s, rm * sm, r * sm, r * s, rm * s};
      for (int k = 0; k < 8; ++k) w[k] = a[k] * (k < 4 ? tm : t);
      if (dw) {
        const double dr[4] = {-sm, sm, s, -s}, ds[4] = {-rm, -r, r, rm};
        for (int k = 0; k < 8; ++k) {
          const double f = k < 4 ? tm : t;
          dw[k] = {dr[k % 4] * f, ds[k % 4] * f, k < 4 ? -a[k] : a[k]};
        }
      }
      return 8;
    }
    case CellType::Wedge: {  // linear triangle (r, s) times linear t
      const double a[3] = {1 - r - s, r, s};
      for (int k = 0; k < 6; ++k) w[k] = a[k % 3] * (k < 3 ? tm : t);
      if (dw) {
        const glm::dvec2 da[3] = {{-1, -1}, {1, 0}, {0, 1}};
        for (int k = 0; k < 6; ++k) {
          const double f = k < 3 ? tm : t;
          dw[k] = {da[k % 3].x * f, da[k % 3].y * f, k < 3 ? -a[k % 3] : a[k % 3]};
        }
      }
      return 6;
    }
    case CellType::Pyramid: {  // bilinear base (r, s) shrinking linearly to the apex at t = 1
      const double a[4] = {rm * sm, r * sm, r * s, rm * s};
      for (int k = 0; k < 4; ++k) w[k] = a[k] * tm;
      w[4] = t;
      if (dw) {
        const double dr[4] = {-sm, sm, s, -s}, ds[4] = {-rm, -r, r, rm};
        for (int k = 0; k < 4; ++k) dw[k] = {dr[k] * tm, ds[k] * tm, -a[k]};
        dw[4] = {0, 0, 1};
      }
      return 5;
    }
    default: return 0;
  }
}

IsoparametricField::IsoparametricField(const MeshView& mesh, const double* recentred_points)
    : points_(recentred_points), first_(static_cast<std::size_t>(mesh.n_cells), -1) {
  types_.assign(mesh.types, mesh.types + mesh.n_cells);
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) {
    if (mesh.type(c) == CellType::Tetra) continue;
    first_[c] = static_cast<std::int64_t>(ids_.size());
    if (mesh.type(c) == CellType::Voxel) {  // a voxel's vertices in hexahedron order
      constexpr int kHexOrder[8] = {0, 1, 3, 2, 4, 5, 7, 6};
      for (int k : kHexOrder) ids_.push_back(mesh.cell(c)[k]);
      types_[c] = static_cast<std::uint8_t>(CellType::Hexahedron);
      continue;
    }
    ids_.insert(ids_.end(), mesh.cell(c), mesh.cell(c) + mesh.cell_size(c));
  }
}

glm::dvec3 IsoparametricField::centre_guess(std::int64_t cell) const {
  switch (static_cast<CellType>(types_[cell])) {
    case CellType::Wedge: return {1.0 / 3, 1.0 / 3, 0.5};
    case CellType::Pyramid: return {0.5, 0.5, 0.2};
    default: return {0.5, 0.5, 0.5};
  }
}

bool IsoparametricField::value(const double* scalar, std::int64_t cell, const glm::dvec3& p, glm::dvec3& xi,
                               double& value) const {
  const CellType type = static_cast<CellType>(types_[cell]);
  const std::int64_t* id = ids_.data() + first_[cell];
  double w[8];
  glm::dvec3 dw[8];
  auto X = [&](int k) { return glm::dvec3(points_[3 * id[k]], points_[3 * id[k] + 1], points_[3 * id[k] + 2]); };
  // Newton on x(xi) = p. Once a step is below 1e-7 the next one would be below ~1e-14, so the value
  // is taken to first order at xi + step instead of iterating again.
  for (int iter = 0; iter < 40; ++iter) {
    const int n = shape_functions(type, xi, w, dw);
    glm::dvec3 x(0.0);
    glm::dmat3 jac(0.0);  // columns dx/dr, dx/ds, dx/dt
    for (int k = 0; k < n; ++k) {
      const glm::dvec3 xk = X(k);
      x += w[k] * xk;
      jac[0] += dw[k].x * xk, jac[1] += dw[k].y * xk, jac[2] += dw[k].z * xk;
    }
    const double det = glm::determinant(jac);
    if (!std::isfinite(det) || det == 0.0) return false;
    const glm::dvec3 step = glm::inverse(jac) * (p - x);
    xi += step;
    if (glm::length(step) < 1e-7) {
      value = 0.0;
      glm::dvec3 grad(0.0);
      for (int k = 0; k < n; ++k) value += w[k] * scalar[id[k]], grad += dw[k] * scalar[id[k]];
      value += glm::dot(grad, step);
      return std::isfinite(value);
    }
  }
  return false;
}

}  // namespace cellproj
