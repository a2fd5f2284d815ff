#include "python/pictures.hpp"

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "base/error.hpp"
#include "media/exr.hpp"
#include "media/movie.hpp"
#include "scene/prepare.hpp"
#include "view/figure.hpp"

namespace cellproj::python {
namespace {

glm::dvec3 color3(const std::vector<double>& v, const char* what) {
  if (v.size() != 3) throw InputError(std::string(what) + ": expected 3 numbers (r, g, b) in [0, 1]");
  return {v[0], v[1], v[2]};
}

// The figure of a render: over `background` (None: transparent), a title above, the legend beside.
Figure figure_of(const std::optional<std::vector<double>>& background, int bits, const std::string& title,
                 const std::optional<Legend>& legend) {
  Figure figure;
  figure.page = background ? std::optional<glm::dvec3>(color3(*background, "background")) : std::nullopt;
  figure.bits = bits;
  const glm::dvec3 page = figure.page ? *figure.page : glm::dvec3(1.0);  // a transparent figure's slide
  figure.caption = {title, "", text_color_for(page), ""};
  if (legend) {
    const double lo = legend->log ? std::log10(legend->lo) : legend->lo;
    const double hi = legend->log ? std::log10(legend->hi) : legend->hi;
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi >= lo))
      throw InputError("Legend: range must be finite and increasing" +
                       std::string(legend->log ? ", above 0 on a log scale" : ""));
    figure.legend = color_bar(legend->tf, lo, hi, legend->log, legend_title(legend->title, legend->unit), page);
    figure.legend->horizontal = legend->horizontal;
  }
  return figure;
}

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

}  // namespace

py::array_t<float> to_numpy(Image&& image) {
  using Pixels = decltype(image.rgba);
  auto* owned = new Pixels(std::move(image.rgba));
  py::capsule free(owned, [](void* p) { delete static_cast<Pixels*>(p); });
  return py::array_t<float>({image.height, image.width, 4}, owned->data(), free);
}

Image from_numpy(const FloatArray& a) {
  if (a.ndim() != 3 || a.shape(2) != 4) throw InputError("image: expected a float (H, W, 4) array");
  Image img(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)));
  std::copy(a.data(), a.data() + a.size(), img.rgba.begin());
  return img;
}

void bind_pictures(py::module_& m) {
  py::class_<Legend>(m, "Legend", "A colour legend for write_png: a transfer function's colours over a field's range")
      .def(py::init([](const TransferFunction& tf, std::pair<double, double> range, const std::string& title, bool log,
                       bool horizontal, const std::string& unit) {
             return Legend{tf, range.first, range.second, title, log, horizontal, unit};
           }),
           py::arg("tf"), py::arg("range"), py::arg("title") = "", py::arg("log") = false,
           py::arg("horizontal") = false, py::arg("unit") = "",
           "range=(lo, hi) in the field's units (mesh.field(name).min(), .max()); log=True for a transfer function "
           "made for a log scale (labels the decades); unit='K' titles it 'title [K]'; horizontal=True puts the bar in "
           "a strip below the picture")
      .def_readwrite("title", &Legend::title, "The legend's title (the field's name unless given)")
      .def_readwrite("unit", &Legend::unit, "The unit printed after the title, in brackets")
      .def_readwrite("horizontal", &Legend::horizontal, "Across the bottom of the picture instead of at its right")
      .def_property_readonly(
          "range", [](const Legend& l) { return std::make_pair(l.lo, l.hi); },
          "(lo, hi): the field's values at the legend's ends, in the field's units")
      .def_readonly("log", &Legend::log, "Whether the legend's axis is a log scale");

  m.def(
      "write_png",
      [](const FloatArray& image, const std::string& path, std::optional<std::vector<double>> background, int bits,
         const std::string& title, std::optional<Legend> legend) {
        const Figure figure = figure_of(background, names_exr(path) ? 8 : bits, title, legend);
        if (names_exr(path)) {
          if (bits != 8) throw InputError(path + ": an EXR's samples are 32-bit floats; bits= is for PNGs");
          return write_exr(premultiplied(figure_pixels(from_numpy(image), figure)), path);
        }
        write_figure(from_numpy(image), figure, path);
      },
      py::arg("image"), py::arg("path"), py::arg("background") = std::vector<double>{0, 0, 0}, py::arg("bits") = 8,
      py::arg("title") = "", py::arg("legend") = py::none(),
      "Writes a render's array as a PNG (or, for a path ending in .exr, an OpenEXR of float RGBA, premultiplied): "
      "over the background colour, or with background=None transparent (straight alpha in a PNG); bits=8 or 16 a "
      "sample of a PNG; title= above the picture and legend=cellproj.Legend(tf, range, title) beside it, in strips of "
      "their own (never over the data), as the CLI's --title and --legend");

  m.def(
      "read_exr", [](const std::string& path) { return to_numpy(read_exr(path)); }, py::arg("path"),
      "An OpenEXR read back as a float32 (H, W, 4) array (R, G, B, A; premultiplied as cellproj writes them)");

  py::class_<MovieWriter>(m, "_MovieWriter")
      .def(py::init([](const std::string& path, double fps) {
             // FFmpeg's notes on each GIF palette are noise in a notebook: its log level (the
             // process's) is set to errors when a movie is made (docs/python.md).
             quiet_ffmpeg_messages();
             MovieOptions o;
             o.frames_per_second = fps;
             return std::make_unique<MovieWriter>(path, o);
           }),
           py::arg("path"), py::arg("fps") = 24.0)
      .def(
          "add",
          [](MovieWriter& movie, const FloatArray& image, std::vector<double> background, const std::string& title,
             std::optional<Legend> legend) {
            const Rgb8Image frame = figure_rgb8(from_numpy(image), figure_of(background, 8, title, legend));
            py::gil_scoped_release release;
            movie.add(frame);
          },
          py::arg("image"), py::arg("background"), py::arg("title"), py::arg("legend"))
      .def("finish", &MovieWriter::finish)
      .def_property_readonly("frames", &MovieWriter::frames);
}

}  // namespace cellproj::python
