/**
 * @class   vtkCellprojVolumeMapper
 * @brief   cellproj's cell projection of unstructured grids, drawn into a VTK render window
 *
 * Renders tetrahedra, hexahedra, wedges, pyramids and voxels directly (no resampling), on the
 * CPU, by cellproj's methods: "pt-breakpoints" (the default: exact for the field linear over each
 * canonical tetrahedron), "pt-linear" (fast), "exact" (the reference ray integrator), and the
 * others of docs/methods.md. It reads what VTK's own unstructured-grid mappers read: the volume
 * property's colour and scalar opacity (an opacity o per ScalarOpacityUnitDistance u is the
 * extinction o / u), the point or cell scalars by scalar mode and array, the active camera and the
 * viewport's size. Opaque geometry already drawn (the window's depth buffer) hides what lies behind
 * it: each ray is integrated only up to it. The mesh's preparation is kept across frames while the
 * input's points and cells are unchanged. docs/vtk.md.
 */
#ifndef vtkCellprojVolumeMapper_h
#define vtkCellprojVolumeMapper_h

#include "vtkCellprojVolumeMapperModule.h"  // For export macro
#include "vtkUnstructuredGridVolumeMapper.h"

class VTKCELLPROJVOLUMEMAPPER_EXPORT vtkCellprojVolumeMapper : public vtkUnstructuredGridVolumeMapper {
 public:
  static vtkCellprojVolumeMapper* New();
  vtkTypeMacro(vtkCellprojVolumeMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * cellproj's method by name: "pt-breakpoints" (default), "pt-linear", "pt-analytic",
   * "pt-table", "exact", "slicing", ... (`cellproj render --help`).
   */
  vtkSetStringMacro(Method);
  vtkGetStringMacro(Method);

  /**
   * Worker threads; 0 (the default) uses every core.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);

  /**
   * Integrate each ray only up to the opaque geometry drawn before the volume (the window's depth
   * buffer). On by default.
   */
  vtkSetMacro(IntermixOpaqueGeometry, vtkTypeBool);
  vtkGetMacro(IntermixOpaqueGeometry, vtkTypeBool);
  vtkBooleanMacro(IntermixOpaqueGeometry, vtkTypeBool);

  /**
   * For an array of several components: -1 (the default) draws its magnitude, 0, 1, ... that
   * component.
   */
  vtkSetClampMacro(VectorComponent, int, -1, 63);
  vtkGetMacro(VectorComponent, int);

  /**
   * Any other render setting by its name, as `cellproj render` takes it without the dashes
   * ("tile-orders", "on"); an empty value removes it. A bad name or value is reported at the next
   * render (GetLastError).
   */
  void SetRenderSetting(const char* name, const char* value);
  void ClearRenderSettings();

  /**
   * The last frame: its wall time (seconds), the times the mesh was prepared so far, and why
   * nothing was drawn (empty when the frame was drawn).
   */
  double GetLastRenderSeconds();
  int GetNumberOfPreparations();
  const char* GetLastError();

  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

 protected:
  vtkCellprojVolumeMapper();
  ~vtkCellprojVolumeMapper() override;

  char* Method = nullptr;
  int NumberOfThreads = 0;
  vtkTypeBool IntermixOpaqueGeometry = 1;
  int VectorComponent = -1;

 private:
  vtkCellprojVolumeMapper(const vtkCellprojVolumeMapper&) = delete;
  void operator=(const vtkCellprojVolumeMapper&) = delete;

  struct Internals;
  Internals* Internal;
};

#endif
