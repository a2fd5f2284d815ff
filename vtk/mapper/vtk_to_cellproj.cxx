#include "vtk_to_cellproj.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPoints.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/common.hpp>

#include "base/error.hpp"
#include "mesh/cell_data.hpp"

namespace cellproj::vtk {
namespace {

// A cell array's ids (32- or 64-bit storage) as int64.
std::vector<std::int64_t> ids_of(vtkDataArray* a) {
  const auto n = static_cast<std::size_t>(a->GetNumberOfTuples());
  if (auto* ids = vtkTypeInt64Array::FastDownCast(a)) return {ids->GetPointer(0), ids->GetPointer(0) + n};
  if (auto* ids = vtkTypeInt32Array::FastDownCast(a)) return {ids->GetPointer(0), ids->GetPointer(0) + n};
  std::vector<std::int64_t> out(n);
  for (std::size_t k = 0; k < n; ++k) out[k] = static_cast<std::int64_t>(a->GetComponent(static_cast<vtkIdType>(k), 0));
  return out;
}

// The tuple's value the mapper draws: a component, or the magnitude (component -1).
double value_of(vtkDataArray* array, vtkIdType tuple, int component) {
  const int n = array->GetNumberOfComponents();
  if (n == 1 || component >= 0) {
    return array->GetComponent(tuple, n == 1 ? 0 : component);
  }
  double sum = 0.0;
  for (int c = 0; c < n; ++c) {
    const double v = array->GetComponent(tuple, c);
    sum += v * v;
  }
  return std::sqrt(sum);
}

// The nodes of a colour function (x, r, g, b, midpoint, sharpness) or a piecewise one (x, y,
// midpoint, sharpness), each handed to f(x, midpoint, sharpness); none for a null function.
template <class F>
void each_node(vtkColorTransferFunction* c, F&& f) {
  for (int k = 0; c && k < c->GetSize(); ++k) {
    double node[6];
    c->GetNodeValue(k, node);
    f(node[0], node[4], node[5]);
  }
}
template <class F>
void each_node(vtkPiecewiseFunction* p, F&& f) {
  for (int k = 0; p && k < p->GetSize(); ++k) {
    double node[4];
    p->GetNodeValue(k, node);
    f(node[0], node[2], node[3]);
  }
}

// Whether the function is linear between its nodes (midpoint 0.5, sharpness 0 at every one).
template <class Function>
bool linear(Function* f) {
  bool linear = true;
  each_node(f,
            [&](double, double midpoint, double sharpness) { linear = linear && midpoint == 0.5 && sharpness == 0.0; });
  return linear;
}
bool rgb_linear(vtkColorTransferFunction* f) {
  return f->GetColorSpace() == VTK_CTF_RGB && f->GetScale() == VTK_CTF_LINEAR && linear(f);
}

// The scalars the functions change at, and with `sampled` 1024 more across their range.
std::vector<double> control_scalars(vtkColorTransferFunction* color, vtkPiecewiseFunction* grey,
                                    vtkPiecewiseFunction* opacity, bool sampled) {
  std::vector<double> s;
  const auto at = [&](double x, double, double) { s.push_back(x); };
  each_node(color, at), each_node(grey, at), each_node(opacity, at);
  std::sort(s.begin(), s.end());
  if (sampled && s.size() > 1 && s.back() > s.front()) {
    const double lo = s.front(), hi = s.back();
    constexpr int kSamples = 1024;
    for (int k = 0; k <= kSamples; ++k) {
      s.push_back(lo + (hi - lo) * k / kSamples);
    }
    std::sort(s.begin(), s.end());
  }
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

// The matrix's rotation-and-translation inverse applied to a point (w = 1) or direction (w = 0).
glm::dvec3 inverse_rigid(const vtkMatrix4x4* m, const glm::dvec3& p, double w) {
  glm::dvec3 out(0.0);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      out[r] += m->GetElement(c, r) * (p[c] - w * m->GetElement(c, 3));
    }
  }
  return out;
}

}  // namespace

Mesh mesh_of(vtkUnstructuredGrid* grid, bool apart) {
  Mesh mesh;
  mesh.source = "the mapper's input";
  vtkPoints* points = grid->GetPoints();
  if (!points || grid->GetNumberOfCells() == 0) {
    throw InputError(mesh.source + ": no points or no cells");
  }
  mesh.points.resize(3 * static_cast<std::size_t>(points->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p) {
    points->GetPoint(p, &mesh.points[3 * static_cast<std::size_t>(p)]);
  }
  vtkCellArray* cells = grid->GetCells();
  mesh.offsets = ids_of(cells->GetOffsetsArray());
  mesh.connectivity = ids_of(cells->GetConnectivityArray());
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  mesh.types.assign(types->GetPointer(0), types->GetPointer(0) + types->GetNumberOfTuples());
  return apart ? cells_apart(mesh) : mesh;
}

std::vector<double> scalars_of(const Mesh& mesh, vtkDataArray* array, bool per_cell, int component) {
  const int n = array->GetNumberOfComponents();
  if (n > 1 && component >= n) {
    throw InputError(std::string("array '") + (array->GetName() ? array->GetName() : "") + "' has " +
                     std::to_string(n) + " components, not a component " + std::to_string(component));
  }
  const vtkIdType expected = per_cell ? mesh.n_cells() : mesh.n_points();
  if (array->GetNumberOfTuples() != expected) {
    throw InputError(std::string("array '") + (array->GetName() ? array->GetName() : "") + "' has " +
                     std::to_string(array->GetNumberOfTuples()) + " tuples for " + std::to_string(expected) +
                     (per_cell ? " cells" : " points"));
  }
  std::vector<double> values(static_cast<std::size_t>(mesh.n_points()));
  if (!per_cell) {
    for (vtkIdType p = 0; p < mesh.n_points(); ++p) {
      values[static_cast<std::size_t>(p)] = value_of(array, p, component);
    }
    return values;
  }
  for (std::int64_t c = 0; c < mesh.n_cells(); ++c) {
    const double v = value_of(array, c, component);
    for (std::int64_t k = mesh.offsets[c]; k < mesh.offsets[c + 1]; ++k) {
      values[static_cast<std::size_t>(mesh.connectivity[k])] = v;
    }
  }
  return values;
}

TransferFunction transfer_function_of(vtkVolumeProperty* property) {
  const bool rgb = property->GetColorChannels(0) == 3;
  vtkColorTransferFunction* color = rgb ? property->GetRGBTransferFunction(0) : nullptr;
  vtkPiecewiseFunction* grey = rgb ? nullptr : property->GetGrayTransferFunction(0);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const double unit = property->GetScalarOpacityUnitDistance(0);
  if (!(unit > 0.0) || !std::isfinite(unit)) {
    throw InputError("the volume property's ScalarOpacityUnitDistance is " + std::to_string(unit) +
                     ": it must be positive (an opacity o per unit distance u is the extinction o / u)");
  }
  const bool exact = (color ? rgb_linear(color) : linear(grey)) && linear(opacity);
  std::vector<ColorPoint> c;
  std::vector<ExtinctionPoint> e;
  for (const double s : control_scalars(color, grey, opacity, !exact)) {
    glm::dvec3 rgb_at(0.0);
    if (color) {
      color->GetColor(s, &rgb_at[0]);
    } else {
      rgb_at = glm::dvec3(grey->GetValue(s));
    }
    c.push_back({s, glm::clamp(rgb_at, 0.0, 1.0)});
    e.push_back({s, std::max(opacity->GetValue(s), 0.0) / unit});
  }
  return TransferFunction(c, e, "the volume property");
}

Camera camera_of(vtkCamera* camera, vtkVolume* volume, double aspect) {
  Camera c;
  c.eye = glm::dvec3(camera->GetPosition()[0], camera->GetPosition()[1], camera->GetPosition()[2]);
  c.target = glm::dvec3(camera->GetFocalPoint()[0], camera->GetFocalPoint()[1], camera->GetFocalPoint()[2]);
  c.up = glm::dvec3(camera->GetViewUp()[0], camera->GetViewUp()[1], camera->GetViewUp()[2]);
  if (camera->GetParallelProjection()) {
    c.projection = Projection::Orthographic;
    c.height = 2.0 * camera->GetParallelScale();
  } else {
    c.projection = Projection::Perspective;
    c.fov_y = camera->GetViewAngle();
    if (camera->GetUseHorizontalViewAngle()) {
      const double half = std::tan(c.fov_y * M_PI / 360.0) / aspect;
      c.fov_y = 360.0 / M_PI * std::atan(half);
    }
  }
  const double* centre = camera->GetWindowCenter();
  if (centre[0] != 0.0 || centre[1] != 0.0) {
    throw UnsupportedError(
        "the camera's window centre is shifted (an off-axis view): cellproj's "
        "cameras look through the image's centre");
  }
  vtkMatrix4x4* m = volume->GetMatrix();
  if (!m->IsIdentity()) {
    for (int r = 0; r < 3; ++r) {
      for (int s = 0; s < 3; ++s) {
        double dot = 0.0;
        for (int k = 0; k < 3; ++k) {
          dot += m->GetElement(k, r) * m->GetElement(k, s);
        }
        if (std::abs(dot - (r == s ? 1.0 : 0.0)) > 1e-9) {
          throw UnsupportedError(
              "the volume's matrix scales or shears it: cellproj draws a volume moved "
              "(rotated and translated) only, its lengths being the optical depths'");
        }
      }
    }
    c.eye = inverse_rigid(m, c.eye, 1.0);
    c.target = inverse_rigid(m, c.target, 1.0);
    c.up = inverse_rigid(m, c.up, 0.0);
  }
  check_camera(c, "the active camera");
  return c;
}

OpaqueDepth opaque_depth_of(const std::vector<float>& zbuffer, int width, int height, vtkCamera* camera) {
  double range[2];
  camera->GetClippingRange(range);
  const double n = range[0], f = range[1];
  const bool parallel = camera->GetParallelProjection() != 0;
  OpaqueDepth d{width, height, std::vector<float>(zbuffer.size())};
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double zb = zbuffer[static_cast<std::size_t>(height - 1 - j) * width + i];
      // OpenGL's window depth of view depth z between the clipping planes n and f, inverted.
      const double z = zb >= 1.0  ? std::numeric_limits<double>::infinity()
                       : parallel ? n + zb * (f - n)
                                  : n * f / (f - zb * (f - n));
      d.z[static_cast<std::size_t>(j) * width + i] = static_cast<float>(std::max(z, n));
    }
  }
  return d;
}

}  // namespace cellproj::vtk
