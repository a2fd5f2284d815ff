#pragma once
// The exact renderer's one choice, as an enum a settings struct can hold (its names: scene/names.hpp).

namespace cellproj {

// How the field varies inside hexahedra, wedges and pyramids (tetrahedra are always linear).
enum class CellInterpolation {
  isoparametric,   // the cell's shape functions, followed along the ray by a polynomial to 1e-9 of the field's range
  canonical_tets,  // linear in each tetrahedron of the canonical split (what projection assumes)
};

}  // namespace cellproj
