#include "vtkCellprojVolumeRepresentation.h"

#include <iterator>
#include "vtkCellprojVolumeMapper.h"

#include "vtkObjectFactory.h"
#include "vtkVolumeRepresentationPreprocessor.h"

vtkStandardNewMacro(vtkCellprojVolumeRepresentation);

namespace {
// The modes the representation offers, by the names of its "Volume Rendering Mode" drop-down.
struct Mode {
  const char* name;
  const char* method;
};
constexpr Mode kModes[] = {
    {"cellproj exact", "pt-breakpoints"}, {"cellproj fast", "pt-linear"}, {"cellproj reference", "exact"}};
}  // namespace

vtkCellprojVolumeRepresentation::vtkCellprojVolumeRepresentation() {
  this->Preprocessor->SetTetrahedraOnly(0);  // cellproj draws every cell type whole
  static_assert(std::size(kModes) == sizeof(Mappers) / sizeof(Mappers[0]), "one mapper per mode");
  for (std::size_t k = 0; k < std::size(kModes); ++k) {
    this->Mappers[k] = vtkSmartPointer<vtkCellprojVolumeMapper>::New();
    this->Mappers[k]->SetMethod(kModes[k].method);
    this->AddVolumeMapper(kModes[k].name, this->Mappers[k]);
  }
  this->SetActiveVolumeMapper(kModes[0].name);
}

vtkCellprojVolumeRepresentation::~vtkCellprojVolumeRepresentation() = default;

void vtkCellprojVolumeRepresentation::SetNumberOfThreads(int threads) {
  for (const auto& mapper : this->Mappers) mapper->SetNumberOfThreads(threads);
  this->Modified();
}

void vtkCellprojVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
}
