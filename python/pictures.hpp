#pragma once
// The Python module's pictures: a render's array and back, the legend a figure carries, and the
// bindings that write figures (PNG, EXR) and movies. Internal to the module.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "optics/transfer_function.hpp"
#include "view/image.hpp"

namespace cellproj::python {

namespace py = pybind11;

// A render as a float32 (H, W, 4) array owning its pixels, and an (H, W, 4) array as an Image
// (InputError for another shape).
py::array_t<float> to_numpy(Image&& image);
Image from_numpy(const py::array_t<float, py::array::c_style | py::array::forcecast>& a);

// What a figure's legend shows: `tf`'s colours over the field's range [lo, hi] (in the field's
// units, also on a log scale), titled, with its unit.
struct Legend {
  TransferFunction tf;
  double lo = 0, hi = 1;
  std::string title;
  bool log = false, horizontal = false;
  std::string unit;  // after the title, in brackets
};

// cellproj.Legend, write_png (PNG or EXR by the name) and the movie writer behind cellproj.Movie.
void bind_pictures(py::module_& m);

}  // namespace cellproj::python
