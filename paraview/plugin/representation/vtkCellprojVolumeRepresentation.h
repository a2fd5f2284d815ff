/**
 * @class   vtkCellprojVolumeRepresentation
 * @brief   ParaView's volume representation of unstructured grids, drawn by cellproj
 *
 * The unstructured-grid volume representation with cellproj's mappers added to its modes
 * ("cellproj exact": pt-breakpoints, the exact integral over each canonical tetrahedron;
 * "cellproj fast": pt-linear; "cellproj reference": the exact ray integrator) besides ParaView's
 * own, and the cells given to them whole: hexahedra, wedges and pyramids are not split into
 * tetrahedra first (ParaView splits them for its own mappers), so cellproj's canonical split and
 * isoparametric fields apply, as on the command line.
 */
#ifndef vtkCellprojVolumeRepresentation_h
#define vtkCellprojVolumeRepresentation_h

#include "vtkCellprojParaViewRepresentationModule.h"  // For export macro
#include "vtkSmartPointer.h"                          // For the mappers
#include "vtkUnstructuredGridVolumeRepresentation.h"

class vtkCellprojVolumeMapper;

class VTKCELLPROJPARAVIEWREPRESENTATION_EXPORT vtkCellprojVolumeRepresentation
    : public vtkUnstructuredGridVolumeRepresentation {
 public:
  static vtkCellprojVolumeRepresentation* New();
  vtkTypeMacro(vtkCellprojVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Worker threads of every cellproj mode; 0 (the default) uses every core.
   */
  void SetNumberOfThreads(int threads);

 protected:
  vtkCellprojVolumeRepresentation();
  ~vtkCellprojVolumeRepresentation() override;

 private:
  vtkCellprojVolumeRepresentation(const vtkCellprojVolumeRepresentation&) = delete;
  void operator=(const vtkCellprojVolumeRepresentation&) = delete;

  vtkSmartPointer<vtkCellprojVolumeMapper> Mappers[3];  // one per mode
};

#endif
