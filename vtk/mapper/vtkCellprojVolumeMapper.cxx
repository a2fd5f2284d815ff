#include "vtkCellprojVolumeMapper.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "base/error.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "vtk_to_cellproj.h"
#include "window_image.h"

vtkStandardNewMacro(vtkCellprojVolumeMapper);

// What the mapper keeps between frames: the mesh and its Volume (with its preparations) while the
// input's points and cells are unchanged, the renderer while the settings are.
struct vtkCellprojVolumeMapper::Internals {
  vtkUnstructuredGrid* grid = nullptr;  // the input the volume was made of (compared, not used)
  vtkMTimeType geometry_time = 0;
  bool apart = false;  // cells on their own points (cell scalars)
  std::unique_ptr<cellproj::Mesh> mesh;
  std::unique_ptr<cellproj::Volume> volume;
  int mesh_made = 0;                     // how many meshes volume_of made: the scalars are read again for a new one
  std::vector<double> scalars, opacity;  // the field drawn, and the extinction's when it has its own
  std::string scalars_key;               // what they were read from (array, its MTime, the choice)

  std::map<std::string, std::string> settings;  // SetRenderSetting's, by name
  std::string renderer_key;
  std::unique_ptr<cellproj::Renderer> renderer;

  cellproj::vtk::WindowImage display;
  std::vector<float> zbuffer;
  double seconds = 0.0;
  std::string error;

  // The volume of `grid`, made again when its points, cells or the scalars' association changed.
  const cellproj::Volume& volume_of(vtkUnstructuredGrid* g, bool cell_scalars) {
    vtkMTimeType t = std::max(g->GetPoints() ? g->GetPoints()->GetMTime() : 0, g->GetCells()->GetMTime());
    t = std::max(t, g->GetCellTypesArray() ? g->GetCellTypesArray()->GetMTime() : 0);
    if (!volume || g != grid || t != geometry_time || cell_scalars != apart) {
      volume.reset();
      mesh = std::make_unique<cellproj::Mesh>(cellproj::vtk::mesh_of(g, cell_scalars));
      volume = std::make_unique<cellproj::Volume>(mesh->view());
      grid = g, geometry_time = t, apart = cell_scalars, ++mesh_made;
    }
    return *volume;
  }

  // The field of `array` over the mesh, read again only when the array, its values, the mesh or
  // the choice changed. Two dependent components (IndependentComponents off; ParaView's separate
  // opacity array): the first coloured by the colour function, the second opaque by the opacity
  // function (VTK's rule).
  cellproj::Field field_of(vtkDataArray* array, bool per_cell, bool two, int component) {
    const std::string name = array->GetName() ? array->GetName() : "scalars";
    const std::string key = std::to_string(reinterpret_cast<std::uintptr_t>(array)) + " " +
                            std::to_string(array->GetMTime()) + " " + std::to_string(mesh_made) + " " +
                            std::to_string(two) + " " + std::to_string(component);
    if (key != scalars_key) {
      scalars_key.clear();  // (a throw below leaves nothing cached)
      scalars = cellproj::vtk::scalars_of(*mesh, array, per_cell, two ? 0 : component);
      opacity = two ? cellproj::vtk::scalars_of(*mesh, array, per_cell, 1) : std::vector<double>();
      scalars_key = key;
    }
    cellproj::Field field{scalars.data(), mesh->n_points(), name};
    if (two) field.opacity = opacity.data(), field.opacity_name = name + " (its second component)";
    return field;
  }

  // The renderer of the method and settings, made again when they changed.
  const cellproj::Renderer& renderer_of(const char* method) {
    cellproj::RenderOptions options;
    std::string key;
    cellproj::set_option(options, "method", method ? method : "pt-breakpoints");
    for (const auto& [name, value] : settings) {
      cellproj::set_option(options, name, value);
    }
    for (const auto& [name, value] : options.words) {
      key += name + "=" + value + ";";
    }
    if (!renderer || key != renderer_key) {
      const cellproj::RenderSettings s = cellproj::settings_from(options);
      cellproj::refuse_unused(s, options.given);
      renderer = cellproj::make_renderer(s);
      renderer_key = key;
    }
    return *renderer;
  }
};

vtkCellprojVolumeMapper::vtkCellprojVolumeMapper() : Internal(new Internals) { this->SetMethod("pt-breakpoints"); }

vtkCellprojVolumeMapper::~vtkCellprojVolumeMapper() {
  this->SetMethod(nullptr);
  delete this->Internal;
}

void vtkCellprojVolumeMapper::SetRenderSetting(const char* name, const char* value) {
  if (!name) {
    return;
  }
  if (!value || !*value) {
    this->Internal->settings.erase(name);
  } else {
    this->Internal->settings[name] = value;
  }
  this->Modified();
}

void vtkCellprojVolumeMapper::ClearRenderSettings() {
  this->Internal->settings.clear();
  this->Modified();
}

double vtkCellprojVolumeMapper::GetLastRenderSeconds() { return this->Internal->seconds; }

int vtkCellprojVolumeMapper::GetNumberOfPreparations() {
  return this->Internal->volume ? this->Internal->volume->preparations() : 0;
}

const char* vtkCellprojVolumeMapper::GetLastError() { return this->Internal->error.c_str(); }

void vtkCellprojVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol) {
  Internals& in = *this->Internal;
  const auto start = std::chrono::steady_clock::now();
  in.error.clear();
  bool among = false;  // drawn among opaque geometry
  try {
    if (vtkAlgorithm* producer = this->GetInputAlgorithm()) {
      producer->Update();
    }
    auto* grid = vtkUnstructuredGrid::SafeDownCast(this->GetInput());
    if (!grid) {
      throw cellproj::InputError("the input is not a vtkUnstructuredGrid");
    }
    int cell_flag = 0;
    vtkDataArray* array = vtkAbstractMapper::GetScalars(grid, this->ScalarMode, this->ArrayAccessMode, this->ArrayId,
                                                        this->ArrayName, cell_flag);
    if (!array || cell_flag == 2) {
      throw cellproj::InputError(std::string("no point or cell scalars to draw") +
                                 (this->ArrayName ? std::string(" (array '") + this->ArrayName + "')" : std::string()));
    }
    const cellproj::Volume& volume = in.volume_of(grid, cell_flag == 1);
    const bool two = array->GetNumberOfComponents() == 2 && !vol->GetProperty()->GetIndependentComponents();
    const cellproj::Field field = in.field_of(array, cell_flag == 1, two, this->VectorComponent);
    const cellproj::TransferFunction tf = cellproj::vtk::transfer_function_of(vol->GetProperty());
    const int* size = ren->GetSize();
    const int* origin = ren->GetOrigin();
    const int width = size[0], height = size[1];
    if (width < 1 || height < 1) {
      return;
    }
    const cellproj::Camera camera = cellproj::vtk::camera_of(ren->GetActiveCamera(), vol, double(width) / height);
    const cellproj::Renderer& renderer = in.renderer_of(this->Method);

    // The opaque geometry drawn before the volume, when there is any.
    cellproj::OpaqueDepth depth;
    if (this->IntermixOpaqueGeometry && ren->GetNumberOfPropsRendered() > 0) {
      in.zbuffer.resize(static_cast<std::size_t>(width) * height);
      ren->GetRenderWindow()->GetZbufferData(origin[0], origin[1], origin[0] + width - 1, origin[1] + height - 1,
                                             in.zbuffer.data());
      depth = cellproj::vtk::opaque_depth_of(in.zbuffer, width, height, ren->GetActiveCamera());
      for (const float z : depth.z) {
        among = among || std::isfinite(z);
      }
    }
    tbb::task_arena arena(cellproj::worker_threads(this->NumberOfThreads));
    const cellproj::Image image = arena.execute([&] {
      return among ? renderer.render(volume, field, tf, camera, {width, height}, depth)
                   : renderer.render(volume, field, tf, camera, {width, height});
    });

    in.display.Draw(ren, image);
  } catch (const cellproj::Error& e) {
    in.error = e.what();
    if (among && dynamic_cast<const cellproj::UnsupportedError*>(&e))
      in.error += " (IntermixOpaqueGeometryOff() draws the volume over the opaque geometry instead)";
    vtkErrorMacro(<< "cellproj: " << in.error);
  }
  in.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void vtkCellprojVolumeMapper::ReleaseGraphicsResources(vtkWindow* window) {
  this->Internal->display.ReleaseGraphicsResources(window);
}

void vtkCellprojVolumeMapper::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << (this->Method ? this->Method : "(none)") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "IntermixOpaqueGeometry: " << this->IntermixOpaqueGeometry << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  for (const auto& [name, value] : this->Internal->settings) {
    os << indent << "RenderSetting " << name << ": " << value << "\n";
  }
}
