// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Model generation (report section 2) as one call: repair every input level of
// detail, tetrahedralize each at every quality in isolated worker processes,
// clean and measure the candidates, choose the levels, assemble the dataset.

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/UpAxis.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/meshing/AlphaWrap.h"
#include "tetskin/meshing/MeshQuality.h"
#include "tetskin/meshing/SurfaceRepair.h"

namespace tetskin {

enum class MesherKind { TetGen, Netgen };
// "tetgen" or "netgen": in the config, the build options and messages.
template <>
struct EnumSchema<MesherKind> {
  static constexpr const char* what = "mesher";
  static constexpr EnumValue<MesherKind> values[] = {{MesherKind::TetGen, "tetgen", ""},
                                                     {MesherKind::Netgen, "netgen", ""}};
};

// Why `box` is not the bounding box of a level of detail of the object whose
// finest level (`finestName`) spans `finest`: levels of one object share
// most of the volume their boxes span together (at least half). Empty when
// it is. Levels of another object, or of this one elsewhere or in other
// units, make a dataset whose levels the multigrid and bindings cannot
// relate. (build's inputs, and convert's imported meshes.)
std::string levelOfDetailMismatch(const BoundingBox& finest, const BoundingBox& box,
                                  const std::string& finestName);

// How a candidate (and the level made from it) is named in reports: the
// TetGen quality "q1.4" or the Netgen preset "moderate", and a size bound
// after it: "q1.2 a0.0017" (volume), "moderate h0.15" (edge).
std::string meshingLabel(MesherKind mesher, double quality, double sizeBound = 0.0);

struct SurfaceInput {
  std::string name;  // in messages: the path as the user gave it
  SurfaceMesh mesh;
  std::string file;  // in the dataset config: the path relative to it (default: name)
};

// The build's options (OptionSchema.h), read by BuildOptions' defaults,
// `build`'s flags, the Build dialog and tetskin.build.
namespace build_option {
inline constexpr NumberOption kLevels{
    "levels",       "--levels", "", "the number of levels", "number of output levels L",
    between(1, 16), 3};
inline constexpr NumberOption kMinElements{"min_elements",
                                           "--min-elements",
                                           "",
                                           "the coarsest level's elements",
                                           "elements of the coarsest level (its target)",
                                           between(1, 1e8),
                                           600};
inline constexpr NumberOption kMaxElements{"max_elements",
                                           "--max-elements",
                                           "",
                                           "the finest level's elements",
                                           "elements of the finest level (its target)",
                                           between(1, 1e8),
                                           12000};
inline constexpr ListOption kQualities{
    "qualities", "--qualities", "the TetGen qualities",
    "TetGen radius-edge bounds (-q), each > 1.0; closer to 1 is finer"};
inline constexpr NumberOption kJobs{"jobs",
                                    "--jobs",
                                    "",
                                    "the mesher processes",
                                    "mesher processes at once (default: all cores)",
                                    between(1, 256),
                                    1};
inline constexpr NumberOption kTimeout{
    "timeout", "--timeout", "", "the mesher's time limit", "seconds before a mesher run is stopped",
    above(0),  600};
inline constexpr EnumOption<MesherKind> kMesher{"mesher", "--mesher", "the mesher"};
}  // namespace build_option

struct BuildOptions {
  int levels = static_cast<int>(build_option::kLevels.defaultValue);
  Index minElements = static_cast<Index>(build_option::kMinElements.defaultValue);
  Index maxElements = static_cast<Index>(build_option::kMaxElements.defaultValue);
  MesherKind mesher = MesherKind::TetGen;
  // TetGen radius-edge ratios, any order (searched best first); for Netgen the
  // five presets are used.
  std::vector<double> qualities = {2.0, 1.8, 1.6, 1.4, 1.2};
  bool decimate = false;  // add coarser input levels derived from the finest input
  // For each level target that no quality candidate meets within 10%, also
  // mesh under element size bounds aimed at it (TargetSizing.h): TetGen's
  // volume bound at the best quality, Netgen's edge bound with the moderate
  // preset. For shapes whose surface needs few elements, such as a box.
  bool sizeToTargets = false;
  int jobs = static_cast<int>(build_option::kJobs.defaultValue);  // mesher processes at once
  double timeoutSeconds = build_option::kTimeout.defaultValue;
  RepairOptions repair;
  // Alpha wrapping (AlphaWrap.h) of the inputs repair cannot close, that no
  // mesher run accepts (auto), or all (always). A wrapped input is meshed in
  // place of the input; the input stays the dataset's default surface.
  WrapOptions wrap;
  UpAxis up = UpAxis::Y;  // recorded in the config (`up`) for simulation and viewing
  // Candidates beyond their fidelity bound (LevelFidelity.h) are never
  // chosen while a faithful one is near the level's target; when none is,
  // build throws Error naming the level, unless this accepts the nearest
  // (its config then records faithful: false).
  bool acceptUnfaithful = false;
};

struct CandidateReport {
  std::string input;
  std::string mesher;
  double quality = 0;    // TetGen ratio, or Netgen preset index
  std::string label;     // e.g. "q1.4", "moderate", or with a size bound "q1.2 a0.0017"
  double sizeBound = 0;  // TetGen volume bound (-a) or Netgen edge bound (maxh); 0: none
  // When `input` was alpha-wrapped first: the wrap's parameters and its
  // distances to the input (those of the decimated wrap, for a derived one).
  std::optional<LevelWrap> wrap;
  bool ok = false;
  std::string error;
  Index nodes = 0, elements = 0;
  Index unreferencedNodesRemoved = 0;
  TetQuality statistics;
  // Its boundary against the object's finest input as read, with the
  // bound for its element size (LevelFidelity.h); set when ok.
  std::optional<LevelFidelity> fidelity;
  double seconds = 0;
};

struct BuildEvents {
  std::function<void(const std::string&)> log;  // one line of report
  std::function<void(const std::string& stage, std::size_t done, std::size_t total)> progress;
  // Polled between stages and while meshing; true stops the build with
  // Cancelled (IsolatedJobs.h), killing the running mesher processes.
  std::function<bool()> cancelled;
};

struct BuildResult {
  Dataset dataset;                          // config paths not yet set (see saveDataset)
  std::vector<CandidateReport> candidates;  // in search order
  std::vector<int> chosen;                  // candidate index per level, coarsest first
  // Candidates left unmeshed: finer than one already above the largest
  // target (see meshCandidates in Candidates.h).
  std::size_t skippedCandidates = 0;
  double meshingSeconds = 0;
  // Wall time of each stage, in order: repair, meshing, cleanup (unreferenced
  // nodes, validation, quality), selection (and assembly).
  std::vector<std::pair<std::string, double>> stageSeconds;
};

// Throws Error when no input survives repair or no candidate can be meshed,
// Cancelled when events.cancelled says so.
BuildResult buildDataset(std::vector<SurfaceInput> inputs, const BuildOptions& options,
                         const BuildEvents& events = {});

}  // namespace tetskin
