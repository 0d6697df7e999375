// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ExactPredicates.h"

#include <cmath>
#include <limits>
#include <mutex>

// From TetGen's predicates.cxx (libtet 1.5 exports them; tetgen.h declares
// only exactinit). exactinit sets the constants the adaptive stages use
// (machine epsilon, the splitter, their error bounds), the same on every
// call, TetGen's own included. Its static filter, which holds only for
// coordinates within the bounds passed, is not used here: the first stage
// below is Shewchuk's own dynamic filter, valid for any coordinates.
void exactinit(int verbose, int noexact, int nofilter, double maxx, double maxy, double maxz);
double orient3dadapt(double* pa, double* pb, double* pc, double* pd, double permanent);
double orient2dadapt(double* pa, double* pb, double* pc, double detsum);

namespace tetskin {
namespace {

// Half a unit in the last place of 1, Shewchuk's epsilon.
constexpr double kEpsilon = std::numeric_limits<double>::epsilon() / 2;
constexpr double kOrient3dBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;
constexpr double kOrient2dBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;

void initialize() {
  static std::once_flag once;
  std::call_once(once, [] { exactinit(0, 0, 1, 1, 1, 1); });  // (bounds of a filter not used)
}

int sign(double x) {
  return (x > 0) - (x < 0);
}

}  // namespace

int orientation3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d) {
  // Shewchuk's orient3d(a, b, c, d) is det[a - d, b - d, c - d], the
  // negative of the product above.
  const double adx = a.x() - d.x(), bdx = b.x() - d.x(), cdx = c.x() - d.x();
  const double ady = a.y() - d.y(), bdy = b.y() - d.y(), cdy = c.y() - d.y();
  const double adz = a.z() - d.z(), bdz = b.z() - d.z(), cdz = c.z() - d.z();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  if (std::abs(det) > kOrient3dBound * permanent) return -sign(det);
  initialize();
  double pa[3] = {a.x(), a.y(), a.z()}, pb[3] = {b.x(), b.y(), b.z()},
         pc[3] = {c.x(), c.y(), c.z()}, pd[3] = {d.x(), d.y(), d.z()};
  return -sign(orient3dadapt(pa, pb, pc, pd, permanent));
}

int orientation2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  // Shewchuk's orient2d(a, b, c): det[a - c, b - c], the same sign.
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  double detsum;
  if (left > 0) {
    if (right <= 0) return sign(det);
    detsum = left + right;
  } else if (left < 0) {
    if (right >= 0) return sign(det);
    detsum = -left - right;
  } else {
    return sign(det);
  }
  if (std::abs(det) >= kOrient2dBound * detsum) return sign(det);
  initialize();
  double pa[2] = {a.x(), a.y()}, pb[2] = {b.x(), b.y()}, pc[2] = {c.x(), c.y()};
  return sign(orient2dadapt(pa, pb, pc, detsum));
}

}  // namespace tetskin
