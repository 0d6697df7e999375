// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A closed surface around any triangle soup: CGAL's 3D Alpha Wrapping
// (Portaneri et al., "Alpha Wrapping with an Offset", SIGGRAPH 2022). Holes,
// self-intersections, overlapping parts, non-manifold edges and
// inconsistent orientation all come out as one closed, 2-manifold surface
// without self-intersections that encloses the input at a distance of about
// `offset` everywhere. `alpha` bounds the detail: no cavity or gap narrower
// than about alpha is followed, so a hole smaller than alpha is closed and
// the wrap's triangles have edges of about alpha. For what build does with
// it, see ModelBuilder.h (BuildOptions::wrap).

#include <optional>
#include <string>
#include <string_view>

#include "tetskin/core/OptionSchema.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/meshing/SurfaceRepair.h"
#include "tetskin/spatial/SurfaceDistance.h"

namespace tetskin {

// `build --wrap`: never (an input repair cannot close is skipped), auto
// (wrap only the inputs repair cannot close, or that no mesher run
// accepts), always (wrap every input).
enum class WrapMode { Never, Auto, Always };
template <>
struct EnumSchema<WrapMode> {
  static constexpr const char* what = "wrap mode";
  static constexpr EnumValue<WrapMode> values[] = {
      {WrapMode::Auto, "auto",
       "those that repair cannot close or that no mesher accepts: holes, open sheets, "
       "overlapping parts"},
      {WrapMode::Always, "always", ""},
      {WrapMode::Never, "never", ""}};
};

// Alpha and offset as fractions of the input's bounding-box diagonal. The
// defaults were measured on the bundled bunny cut open and on scans (see
// doc/user/model-generation.md): fine enough for a control mesh of 12000
// elements, a second or two for 100k triangles.
// The wrap's number options (OptionSchema.h), read by WrapOptions'
// defaults, `build`'s flags, the Build dialog and tetskin.build.
namespace wrap_option {
inline constexpr NumberOption kAlpha{
    "wrap_alpha",
    "--wrap-alpha",
    "",
    "the wrap's alpha",
    "the wrap's alpha, a fraction of the input's bounding-box diagonal: gaps and cavities "
    "narrower than it are closed, and its triangles are about this size",
    between(0, 1, false, true),
    1.0 / 50};
inline constexpr NumberOption kOffset{
    "wrap_offset",
    "--wrap-offset",
    "",
    "the wrap's offset",
    "how far the wrap lies outside the input, a fraction of the diagonal",
    between(0, 1, false, true),
    1.0 / 500};
inline constexpr EnumOption<WrapMode> kMode{"wrap", "--wrap", "the wrapping",
                                            "alpha-wrap inputs in a closed surface first: "};
}  // namespace wrap_option

struct WrapOptions {
  WrapMode mode = WrapMode::Auto;
  double alpha = wrap_option::kAlpha.defaultValue;
  double offset = wrap_option::kOffset.defaultValue;
};

// Whether any triangle of `mesh` has an area: a wrap of nothing is nothing.
bool hasArea(const SurfaceMesh& mesh);

// The wrap, with `alpha` and `offset` absolute (in the input's units),
// wound outward. Throws Error naming `name` when the input has no triangle
// of positive area, alpha or offset is not positive, or the wrap is empty.
// Can take long on fine inputs with small alpha: run it through
// runIsolated (IsolatedJobs.h) where it must be cancellable.
SurfaceMesh alphaWrap(const SurfaceMesh& input, double alpha, double offset,
                      const std::string& name);

// What build wraps: `input` welded and its T-junctions split as repair
// does (an STL's corners are separate vertices, a CAD seam's sides split
// differently), without flaps (removeFlaps: stray sheets on a seam), and
// with each hole closed (fillHoles) whose patch covers at most a quarter of
// the surface's area: a scan's missing base, an occlusion. A wrap whose
// alpha is smaller than a hole would enter it and coat the inside too (the
// bunny cut open at its base came out a hollow skin two offsets thick). A
// wider hole is the rim of an open sheet (a face, a mask), which the wrap
// makes a shell. `holesClosed`, if given, gets how many were closed.
SurfaceMesh wrapReady(const SurfaceMesh& input, const RepairOptions& repair = {},
                      Index* holesClosed = nullptr);

// How far a wrap (or a surface derived from it) lies from the input it was
// made of, both ways, in the input's units: input -> wrap is about the
// offset where the wrap hugs the input and larger in the cavities it
// bridges; wrap -> input is large where the wrap closes a hole.
struct WrapFidelity {
  OneSidedDistance inputToWrap;
  OneSidedDistance wrapToInput;
  double diagonal = 0;  // of the input's bounding box: the scale of the fractions
};
WrapFidelity wrapFidelity(const SurfaceMesh& input, const SurfaceMesh& wrap);

// The mean thickness of the body a closed surface encloses: twice its
// volume over its area. A sheet wrapped at `offset` gives about 2 offset.
double meanThickness(const SurfaceMesh& closed);

}  // namespace tetskin
