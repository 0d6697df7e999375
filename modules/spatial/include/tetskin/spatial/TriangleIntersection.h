// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Whether two triangles of one surface intersect improperly, i.e. other than
// along the vertices and edges they share. This is what makes TetGen reject a
// surface ("self-intersecting facets").

#include <Eigen/Core>

namespace tetskin {

// Triangles are given by their corner positions and vertex ids; shared ids
// tell which contacts are proper (a shared vertex or edge).
bool trianglesIntersect(const Eigen::Vector3d (&p)[3], const int (&pid)[3],
                        const Eigen::Vector3d (&q)[3], const int (&qid)[3]);

}  // namespace tetskin
