// SPDX-License-Identifier: AGPL-3.0-or-later
#include "Wrapping.h"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "tetskin/core/Error.h"
#include "tetskin/meshing/IsolatedJobs.h"
#include "tetskin/spatial/SurfaceDistance.h"

namespace tetskin {
namespace {

// A wrap whose mean thickness is under this many offsets encloses no
// volume of its input's own: it is a shell around a sheet, about 2 offsets
// thick (a closed input's wrap is as thick as the object).
constexpr double kShellThicknessOffsets = 4.0;

}  // namespace

LevelWrap measureWrap(const SurfaceMesh& input, const SurfaceMesh& surface, double alpha,
                      double offset) {
  const WrapFidelity f = wrapFidelity(input, surface);
  LevelWrap w;
  w.alpha = alpha;
  w.offset = offset;
  w.diagonal = f.diagonal;
  w.inputToWrapMax = f.inputToWrap.max;
  w.inputToWrapMean = f.inputToWrap.mean;
  w.wrapToInputMax = f.wrapToInput.max;
  w.wrapToInputMean = f.wrapToInput.mean;
  return w;
}

std::vector<RepairedInput> wrapInputs(std::vector<WrapRequest> requests,
                                      const BuildOptions& options, const BuildEvents& events,
                                      std::string& firstFailure) {
  std::vector<RepairedInput> wrapped;
  if (requests.empty()) return wrapped;
  std::vector<double> alphas, offsets;
  std::vector<SurfaceMesh> prepared;
  std::vector<SurfaceJob> jobs;
  prepared.reserve(requests.size());
  for (const WrapRequest& r : requests) {
    const double diagonal = boundingBox(r.surface).diagonal();
    alphas.push_back(r.alpha > 0 ? r.alpha : options.wrap.alpha * diagonal);
    offsets.push_back(r.offset > 0 ? r.offset : options.wrap.offset * diagonal);
    Index holesClosed = 0;
    const SurfaceMesh* ready = r.ready.get();
    if (!ready) {
      prepared.push_back(wrapReady(r.surface, options.repair, &holesClosed));
      ready = &prepared.back();
    }
    jobs.push_back([surface = ready, name = r.name, alpha = alphas.back(),
                    offset = offsets.back()] { return alphaWrap(*surface, alpha, offset, name); });
    std::string closed;
    if (holesClosed > 0) closed = "; " + std::to_string(holesClosed) + " hole(s) closed first";
    if (!(r.alpha > 0))
      say(events, "wrapping " + r.name + " (alpha " + formatNumber(alphas.back()) + ", offset " +
                      formatNumber(offsets.back()) + closed + "): " + r.reason);
  }
  std::size_t done = 0;
  if (events.progress) events.progress("wrap", 0, jobs.size());
  const std::vector<IsolatedSurface> wraps = runIsolated(
      jobs, options.jobs, options.timeoutSeconds,
      [&](std::size_t, const IsolatedSurface&) {
        if (events.progress) events.progress("wrap", ++done, jobs.size());
      },
      events.cancelled);
  for (std::size_t i = 0; i < requests.size(); ++i) {
    WrapRequest& request = requests[i];
    if (!wraps[i].ok) {
      // (alphaWrap's own errors name the input already.)
      const std::string failure = wraps[i].error.rfind(request.name + ":", 0) == 0
                                      ? wraps[i].error
                                      : request.name + ": the wrap failed: " + wraps[i].error;
      say(events, "skipping input: " + failure);
      if (firstFailure.empty()) firstFailure = failure;
      continue;
    }
    RepairedInput r;
    const bool rewrap = request.alpha > 0;
    r.name = request.name + (rewrap ? "" : " (wrapped)");
    r.file = request.file;
    r.derived = rewrap;
    r.mesh = wraps[i].mesh;
    try {
      r.repair = repairSurface(r.mesh, r.name, options.repair);
    } catch (const Error& e) {
      say(events, std::string("skipping input: ") + e.what());
      if (firstFailure.empty()) firstFailure = e.what();
      continue;
    }
    r.wrap = measureWrap(request.surface, r.mesh, alphas[i], offsets[i]);
    if (rewrap ? request.sheet
               : !boundaryLoops(request.surface).empty() &&
                     meanThickness(r.mesh) < kShellThicknessOffsets * offsets[i])
      r.wrap->shellThickness = meanThickness(r.mesh);
    r.wrapReason = std::move(request.reason);
    r.original = std::move(request.surface);
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.2f", wraps[i].seconds);
    say(events, std::string(rewrap ? "derived " : "wrapped ") + request.name + ": " +
                    std::to_string(r.mesh.triangleCount()) + " triangles in " + seconds + " s; " +
                    describe(*r.wrap));
    if (r.wrap->shellThickness > 0 && !rewrap)
      say(events, "warning: " + request.name +
                      " is an open sheet, not a closed surface: it became a shell body about " +
                      formatNumber(r.wrap->shellThickness) +
                      " thick (twice the wrap's offset; --wrap-offset sets it)");
    wrapped.push_back(std::move(r));
  }
  return wrapped;
}

SurfaceMesh outerSurface(const SurfaceMesh& input, const SurfaceMesh& wrap, const LevelWrap& how) {
  const std::vector<double> distance = distancesToSurface(input.positions, wrap);
  const double within = how.alpha + how.offset;
  std::vector<Index> kept;
  for (Index t = 0; t < input.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      if (distance[static_cast<std::size_t>(input.triangles(t, k))] <= within) {
        kept.push_back(t);
        break;
      }
  if (static_cast<Index>(kept.size()) == input.triangleCount() || kept.empty()) return input;
  SurfaceMesh outer;
  outer.positions = input.positions;
  outer.triangles.resize(static_cast<Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i)
    outer.triangles.row(static_cast<Index>(i)) = input.triangles.row(kept[i]);
  return outer;
}

std::vector<RepairedInput> rewrappedInputs(const RepairedInput& finest, const BuildOptions& options,
                                           const BuildEvents& events) {
  const LevelWrap& base = *finest.wrap;
  const bool sheet = base.shellThickness > 0;
  const auto ready =
      std::make_shared<const SurfaceMesh>(wrapReady(finest.original, options.repair));
  std::vector<WrapRequest> requests;
  // Around a sheet the finest alpha is wrapped anew too: the finest wrap's
  // shell is as thin as the user's offset, which only a level of that
  // element size meshes well.
  double alpha = sheet ? base.alpha : base.alpha * kRewrapAlphaFactor;
  const double largest =
      (sheet ? kRewrapLargestSheetAlpha : kRewrapLargestBodyAlpha) * base.diagonal;
  for (; alpha <= largest; alpha *= kRewrapAlphaFactor) {
    const double offset =
        sheet ? kSheetOffsetShare * alpha : std::max(base.offset, kBodyOffsetShare * alpha);
    char suffix[96];
    std::snprintf(suffix, sizeof suffix, " (wrapped at alpha %.3g%%, offset %.3g%%)",
                  100 * alpha / base.diagonal, 100 * offset / base.diagonal);
    WrapRequest r;
    r.name = finest.name.substr(0, finest.name.rfind(" (wrapped)")) + suffix;
    r.file = finest.file + suffix;
    r.surface = finest.original;
    r.reason = "a coarser input";
    r.alpha = alpha;
    r.offset = offset;
    r.ready = ready;
    r.sheet = sheet;
    requests.push_back(std::move(r));
  }
  std::string firstFailure;
  return wrapInputs(std::move(requests), options, events, firstFailure);
}

}  // namespace tetskin
