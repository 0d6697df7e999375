// SPDX-License-Identifier: AGPL-3.0-or-later
// The filters in a distributed pipeline (ParaView's pvserver, pvbatch under
// MPI; the multi-rank runs are tests/paraview/check_distributed.py): the
// output asked for one piece of several, the surface input is asked for that
// piece and the control mesh whole, and an empty piece of the surface gives
// an empty output with the arrays the other pieces have.
#include <gtest/gtest.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkPointData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnstructuredGridAlgorithm.h>

#include "FilterTestData.h"
#include "tetskin/filters/vtkTetSkinBindSurface.h"
#include "tetskin/filters/vtkTetSkinDeformSurface.h"
#include "tetskin/vtkio/VtkErrorCapture.h"

namespace tetskin::test {
namespace {

// A source as VTK's reader of a serial file is: asked for piece 0 of any
// count it gives the whole data, for the others nothing. It records the
// piece it was last asked for.
template <typename Algorithm, typename Data>
class SerialFileSource : public Algorithm {
 public:
  static SerialFileSource* New() {
    auto* source = new SerialFileSource;
    source->InitializeObjectBase();
    return source;
  }
  vtkSmartPointer<Data> whole;
  int piece = -1, pieces = -1;

 protected:
  SerialFileSource() { this->SetNumberOfInputPorts(0); }
  int RequestInformation(vtkInformation*, vtkInformationVector**,
                         vtkInformationVector* outputs) override {
    // (Else the executive asks for piece 0 of 1 and leaves the others empty.)
    outputs->GetInformationObject(0)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) override {
    vtkInformation* info = outputs->GetInformationObject(0);
    piece = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
    pieces = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
    if (piece == 0) Data::GetData(outputs)->DeepCopy(whole);
    return 1;
  }
};
using SurfaceSource = SerialFileSource<vtkPolyDataAlgorithm, vtkPolyData>;
using ControlSource = SerialFileSource<vtkUnstructuredGridAlgorithm, vtkUnstructuredGrid>;

TEST(FilterPieces, TheSurfaceComesInTheAskedPieceTheControlMeshWhole) {
  vtkNew<SurfaceSource> surface;
  surface->whole = toVtkPolyData(bunnySurface());
  vtkNew<ControlSource> control;
  control->whole = controlLevelGrid();
  vtkNew<vtkTetSkinBindSurface> bind;
  bind->SetInputConnection(surface->GetOutputPort());
  bind->SetControlMeshConnection(control->GetOutputPort());
  vtkNew<vtkTetSkinDeformSurface> deform;
  deform->SetInputConnection(bind->GetOutputPort());
  deform->SetControlMeshConnection(control->GetOutputPort());
  const VtkErrorCapture bindErrors(bind), deformErrors(deform);

  // Rank 1 of 3: an empty piece of the surface, the whole control mesh.
  ASSERT_TRUE(deform->UpdatePiece(1, 3, 0));
  EXPECT_FALSE(bindErrors.failed()) << bindErrors.message();
  EXPECT_FALSE(deformErrors.failed()) << deformErrors.message();
  EXPECT_EQ(surface->piece, 1);
  EXPECT_EQ(surface->pieces, 3);
  EXPECT_EQ(control->piece, 0);
  EXPECT_EQ(control->pieces, 1);
  vtkNew<vtkPolyData> empty;
  empty->DeepCopy(deform->GetOutput());
  EXPECT_EQ(empty->GetNumberOfPoints(), 0);

  // Rank 0 of 3: the whole surface; its arrays are the empty piece's.
  ASSERT_TRUE(deform->UpdatePiece(0, 3, 0));
  EXPECT_EQ(surface->piece, 0);
  EXPECT_EQ(control->pieces, 1);
  vtkPolyData* full = deform->GetOutput();
  EXPECT_EQ(full->GetNumberOfPoints(), bunnySurface().vertexCount());
  vtkPointData* fullArrays = full->GetPointData();
  vtkPointData* emptyArrays = empty->GetPointData();
  ASSERT_GT(fullArrays->GetNumberOfArrays(), 5);
  EXPECT_EQ(emptyArrays->GetNumberOfArrays(), fullArrays->GetNumberOfArrays());
  for (int i = 0; i < fullArrays->GetNumberOfArrays(); ++i) {
    const char* name = fullArrays->GetArrayName(i);
    SCOPED_TRACE(name);
    vtkAbstractArray* array = emptyArrays->GetAbstractArray(name);
    ASSERT_NE(array, nullptr);
    EXPECT_EQ(array->GetNumberOfComponents(),
              fullArrays->GetAbstractArray(i)->GetNumberOfComponents());
    EXPECT_EQ(array->GetNumberOfTuples(), 0);
  }
}

}  // namespace
}  // namespace tetskin::test
