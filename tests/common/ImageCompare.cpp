// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ImageCompare.h"

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::test {

namespace {

// Calls visit(d) with each pixel's largest channel difference d; false
// (after a test failure) when the images differ in size.
template <typename Visit>
bool forEachPixelDifference(vtkImageData* a, vtkImageData* b, Visit&& visit) {
  EXPECT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints()) return false;
  vtkDataArray* pa = a->GetPointData()->GetScalars();
  vtkDataArray* pb = b->GetPointData()->GetScalars();
  const int channels = std::min({3, pa->GetNumberOfComponents(), pb->GetNumberOfComponents()});
  for (vtkIdType i = 0; i < pa->GetNumberOfTuples(); ++i) {
    double largest = 0;
    for (int c = 0; c < channels; ++c)
      largest = std::max(largest, std::abs(pa->GetComponent(i, c) - pb->GetComponent(i, c)));
    visit(largest);
  }
  return true;
}

}  // namespace

double differingPixelShare(vtkImageData* a, vtkImageData* b) {
  vtkIdType differing = 0;
  if (!forEachPixelDifference(a, b, [&](double d) { differing += d > 24 ? 1 : 0; })) return 1.0;
  return static_cast<double>(differing) / static_cast<double>(a->GetNumberOfPoints());
}

double meanPixelDifference(vtkImageData* a, vtkImageData* b) {
  double sum = 0;
  if (!forEachPixelDifference(a, b, [&](double d) { sum += d; })) return 255.0;
  return sum / static_cast<double>(a->GetNumberOfPoints());
}

void expectMatchesBaseline(vtkImageData* image, const std::filesystem::path& baselineDir,
                           const std::filesystem::path& actualDir, const std::string& name,
                           double tolerance) {
  const std::filesystem::path baseline = baselineDir / name;
  const std::filesystem::path actual = actualDir / name;
  writePng(actual, image);
  if (std::getenv("TETSKIN_UPDATE_BASELINES")) writePng(baseline, image);
  ASSERT_TRUE(std::filesystem::exists(baseline))
      << "no baseline " << baseline << "; the rendered image is " << actual
      << " (TETSKIN_UPDATE_BASELINES=1 makes it the baseline)";
  const double error = differingPixelShare(image, readPng(baseline));
  EXPECT_LT(error, tolerance) << name << " differs from its baseline in " << 100 * error
                              << "% of the pixels; see " << actual;
}

}  // namespace tetskin::test
