// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The filters' control-mesh inputs under distributed execution (ParaView's
// pvserver, pvbatch under MPI): the control mesh is small beside the
// surface, so every rank asks for all of it, piece 0 of 1 without ghost
// levels, while the surface on input 0 arrives in the rank's own piece
// (the executive's default request). A reader then reads it whole on each
// rank; nothing crosses between ranks.

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkStreamingDemandDrivenPipeline.h>

namespace tetskin::filters {

inline void requestWholeInput(vtkInformationVector* input) {
  for (int i = 0; i < input->GetNumberOfInformationObjects(); ++i) {
    vtkInformation* info = input->GetInformationObject(i);
    info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
}

}  // namespace tetskin::filters
