// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Image-baseline comparison shared by the rendering and GUI suites.

#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>

class vtkImageData;

namespace tetskin::test {

// Share of pixels whose largest channel difference exceeds 24 of 255
// (vtkImageDifference's default tolerance would pass very different images).
double differingPixelShare(vtkImageData* a, vtkImageData* b);

// The mean over all pixels of the largest channel difference, in 255ths:
// for differences too faint for differingPixelShare() to count, such as
// shading that shows a mesh's facets.
double meanPixelDifference(vtkImageData* a, vtkImageData* b);

// Writes `image` to actualDir/name and compares it with baselineDir/name
// (fails the test above `tolerance`); TETSKIN_UPDATE_BASELINES=1 rewrites the baseline.
void expectMatchesBaseline(vtkImageData* image, const std::filesystem::path& baselineDir,
                           const std::filesystem::path& actualDir, const std::string& name,
                           double tolerance = 0.002);

}  // namespace tetskin::test
