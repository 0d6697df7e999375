// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The bundled sample data (data/) and its dataset, loaded once per test
// program: the suites only read it. Header-only: it needs
// TETSKIN_SOURCE_DIR (every tetskin_add_test target defines it) and
// TetSkin::io.

#include <string>

#include "tetskin/io/Dataset.h"

namespace tetskin::test {

inline const std::string kSampleData = std::string(TETSKIN_SOURCE_DIR) + "/data/";

// data/bunny.json: three levels of 598, 2926 and 12713 tetrahedra.
inline const Dataset& sampleDataset() {
  static const Dataset dataset = loadDataset(kSampleData + "bunny.json");
  return dataset;
}

}  // namespace tetskin::test
