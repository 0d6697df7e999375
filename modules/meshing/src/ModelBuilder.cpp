// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/ModelBuilder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "Candidates.h"
#include "FaithfulSelection.h"
#include "Wrapping.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/meshing/Decimation.h"
#include "tetskin/meshing/IsolatedJobs.h"
#include "tetskin/meshing/LevelFidelity.h"
#include "tetskin/meshing/LevelSelection.h"
#include "tetskin/meshing/Meshers.h"

namespace tetskin {
namespace {

// The least share of their bounding boxes' union (boxOverlap) that an input
// shares with the finest one.
constexpr double kLevelOfDetailOverlap = 0.5;

// Says the collapse's warning for a repaired input, if it has one.
void sayCollapseWarning(const BuildEvents& events, const RepairReport& report,
                        const std::string& name) {
  if (const std::string warning = collapseWarning(report, name); !warning.empty())
    say(events, "warning: " + warning + ", or wrap them in one (--wrap always)");
}

// Finest first: the search order of the level selection starts there.
void sortFinestFirst(std::vector<RepairedInput>& inputs) {
  std::stable_sort(inputs.begin(), inputs.end(),
                   [](const RepairedInput& a, const RepairedInput& b) {
                     return a.mesh.triangleCount() > b.mesh.triangleCount();
                   });
}

// What --wrap never says of an input repair cannot close.
std::string wrapHint(const BuildOptions& options) {
  return options.wrap.mode == WrapMode::Never
             ? " (--wrap auto wraps such inputs in a closed surface)"
             : "";
}

constexpr double kWrapDecimationFactor = 0.7;

// Coarser inputs derived from the finest one (--decimate): decimated, and
// for a wrap also wrapped anew at coarser scales (rewrappedInputs). A
// shell around a sheet only wrapped anew: decimated it collapses where it
// is thin, and its thickness must grow with the element size. A wrapped
// body gets both; the fidelity bound rejects the decimations that
// collapse (a part pinched off, a spike) and the selection takes what is
// left.
std::vector<RepairedInput> decimatedInputs(const RepairedInput& finest, const BuildOptions& options,
                                           const BuildEvents& events) {
  std::vector<RepairedInput> derived;
  if (finest.wrap) {
    derived = rewrappedInputs(finest, options, events);
    if (finest.wrap->shellThickness > 0) return derived;
  }
  // A wrap's decimations in finer steps: the bound rejects some (a
  // decimation collapsed, parts pinched together), and the others must
  // still come near every target.
  for (SurfaceMesh& coarse :
       decimatedSeries(finest.mesh, finest.wrap ? kWrapDecimationFactor : 0.5)) {
    const std::string suffix =
        " (decimated to " + std::to_string(coarse.triangleCount()) + " triangles)";
    const std::string name = finest.name + suffix;
    RepairedInput r{name, finest.file + suffix, std::move(coarse), {}, true, {}, {}, {}};
    try {
      r.repair = repairSurface(r.mesh, r.name, options.repair);
      if (finest.wrap) {
        r.wrap = measureWrap(finest.original, r.mesh, finest.wrap->alpha, finest.wrap->offset);
      }
      say(events, "derived " + name);
      sayCollapseWarning(events, r.repair, name);
      derived.push_back(std::move(r));
    } catch (const Error& e) {
      say(events, std::string("skipping derived input: ") + e.what());
    }
  }
  return derived;
}

// The inputs repaired (or wrapped), finest first, with the coarser ones
// --decimate derives; `reference` gets the finest input as read, what every
// candidate is measured against (LevelFidelity.h), and `referenceFile` its
// name in the config.
std::vector<RepairedInput> prepareInputs(std::vector<SurfaceInput> inputs,
                                         const BuildOptions& options, const BuildEvents& events,
                                         SurfaceMesh& reference, std::string& referenceFile) {
  if (inputs.empty()) throw Error("no input surface given");
  // The same surface twice (one file named twice, or a copy) would only be
  // meshed twice: most likely a slip of the command line.
  auto sameSurface = [](const SurfaceMesh& a, const SurfaceMesh& b) {
    return a.positions.rows() == b.positions.rows() && a.triangles.rows() == b.triangles.rows() &&
           a.positions == b.positions && a.triangles == b.triangles;
  };
  for (std::size_t j = 1; j < inputs.size(); ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (sameSurface(inputs[i].mesh, inputs[j].mesh))
        throw Error(inputs[j].name, 0,
                    "is the same surface as the input " + inputs[i].name +
                        "; each input is a level of detail of its own");
  // Finest input first: the search order of the level selection starts there.
  std::stable_sort(inputs.begin(), inputs.end(), [](const SurfaceInput& a, const SurfaceInput& b) {
    return a.mesh.triangleCount() > b.mesh.triangleCount();
  });
  reference = inputs.front().mesh;
  referenceFile = inputs.front().file.empty() ? inputs.front().name : inputs.front().file;
  // Levels of another object are refused (levelOfDetailMismatch).
  const BoundingBox finestBox = boundingBox(inputs.front().mesh);
  for (std::size_t j = 1; j < inputs.size(); ++j)
    if (const std::string mismatch =
            levelOfDetailMismatch(finestBox, boundingBox(inputs[j].mesh), inputs.front().name);
        !mismatch.empty())
      throw Error(inputs[j].name, 0, mismatch);
  std::vector<RepairedInput> prepared;
  std::vector<WrapRequest> toWrap;
  std::string firstFailure;
  for (SurfaceInput& input : inputs) {
    const std::string file = input.file.empty() ? input.name : input.file;
    if (options.wrap.mode == WrapMode::Always) {
      validateSurface(input.mesh, input.name);
      if (hasArea(input.mesh)) {
        toWrap.push_back({input.name, file, std::move(input.mesh), "--wrap always"});
      } else {
        const std::string failure =
            input.name + ": every triangle has zero area, so the surface encloses nothing to wrap";
        say(events, "skipping input: " + failure);
        if (firstFailure.empty()) firstFailure = failure;
      }
      continue;
    }
    // Auto keeps the input as read: a wrap takes it, not repair's remains,
    // here or when no mesher accepts the repaired surface (wrapRefused).
    SurfaceMesh asRead = options.wrap.mode == WrapMode::Auto ? input.mesh : SurfaceMesh{};
    RepairedInput r{input.name, file, std::move(input.mesh), {}, false, {}, {}, {}};
    try {
      r.repair = repairSurface(r.mesh, r.name, options.repair);
      r.original = std::move(asRead);
    } catch (const Error& e) {
      // An input without area is refused: there is nothing to wrap.
      if (options.wrap.mode == WrapMode::Auto && hasArea(asRead)) {
        toWrap.push_back({input.name, file, std::move(asRead), e.what()});
        continue;
      }
      say(events, std::string("skipping input: ") + e.what() + wrapHint(options));
      if (firstFailure.empty()) firstFailure = e.what() + wrapHint(options);
      continue;
    }
    std::string line = "repaired " + r.name + ":";
    for (const auto& [key, count] : r.repair.counts())
      if (count != 0) line += " " + key + "=" + std::to_string(count);
    say(events, line);
    sayCollapseWarning(events, r.repair, r.name);
    prepared.push_back(std::move(r));
  }
  for (RepairedInput& r : wrapInputs(std::move(toWrap), options, events, firstFailure))
    prepared.push_back(std::move(r));
  if (prepared.empty())
    throw Error(inputs.size() == 1
                    ? firstFailure
                    : "no input surface could be repaired; the first: " + firstFailure);
  sortFinestFirst(prepared);
  if (options.decimate) {
    // Originals are finer than their decimations: the order stays.
    for (RepairedInput& r : decimatedInputs(prepared.front(), options, events))
      prepared.push_back(std::move(r));
    sortFinestFirst(prepared);
  }
  return prepared;
}

// Once the finest input is wrapped (`reference` still as read), its levels
// are measured against its outer surface (outerSurface), not its insides.
// Returns whether it was.
bool trimReference(SurfaceMesh& reference, const std::string& finestFile,
                   const std::vector<RepairedInput>& prepared) {
  for (const RepairedInput& r : prepared)
    if (!r.derived && r.wrap && r.file == finestFile) {
      reference = outerSurface(reference, r.mesh, *r.wrap);
      return true;
    }
  return false;
}

// --wrap auto's second chance: each original input that repair closed but
// whose every candidate the meshers refused (none skipped) is wrapped and
// appended to `prepared`. Returns whether any was.
bool wrapRefusedInputs(std::vector<RepairedInput>& prepared,
                       const std::vector<CandidateSpec>& specs, const Candidates& found,
                       const BuildOptions& options, const BuildEvents& events) {
  std::vector<WrapRequest> requests;
  for (std::size_t i = 0; i < prepared.size(); ++i) {
    RepairedInput& input = prepared[i];
    if (input.derived || input.wrap || input.original.triangleCount() == 0) continue;
    std::size_t made = 0, accepted = 0, asked = 0;
    std::string firstError;
    for (const CandidateSpec& spec : specs) asked += spec.input == i ? 1 : 0;
    for (const CandidateReport& c : found.reports) {
      if (c.input != input.file) continue;
      ++made;
      accepted += c.ok ? 1 : 0;
      if (!c.ok && firstError.empty()) firstError = c.label + ": " + c.error;
    }
    if (asked == 0 || made != asked || accepted > 0) continue;
    requests.push_back({input.name, input.file, std::move(input.original),
                        "no mesher run accepted the repaired surface (" + firstError + ")"});
  }
  if (requests.empty()) return false;
  std::string firstFailure;
  std::vector<RepairedInput> wrapped =
      wrapInputs(std::move(requests), options, events, firstFailure);
  // With --decimate and nothing meshed at all, the coarser inputs come from
  // the finest wrap, as when repair refuses the finest input.
  const bool nothingMeshed =
      std::none_of(found.counts.begin(), found.counts.end(), [](Index c) { return c >= 0; });
  if (options.decimate && nothingMeshed && !wrapped.empty()) {
    sortFinestFirst(wrapped);
    std::vector<RepairedInput> derived = decimatedInputs(wrapped.front(), options, events);
    for (RepairedInput& r : derived) wrapped.push_back(std::move(r));
  }
  sortFinestFirst(wrapped);
  for (RepairedInput& r : wrapped) prepared.push_back(std::move(r));
  return !wrapped.empty();
}

// The quality candidates of inputs[first..]: every input at every quality,
// in the selection's search order.
std::vector<CandidateSpec> candidateSpecs(const std::vector<RepairedInput>& inputs,
                                          const BuildOptions& options, std::size_t first = 0) {
  std::vector<CandidateSpec> specs;
  for (std::size_t i = first; i < inputs.size(); ++i) {
    if (options.mesher == MesherKind::TetGen) {
      for (double quality : distinctQualities(options))
        specs.push_back({i, quality, meshingLabel(MesherKind::TetGen, quality)});
    } else {
      for (int preset = 4; preset >= 0; --preset)  // very fine (best) first
        specs.push_back({i, static_cast<double>(preset),
                         meshingLabel(MesherKind::Netgen, static_cast<double>(preset))});
    }
  }
  return specs;
}

nlohmann::json repairJson(const RepairReport& report) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, count] : report.counts()) j[key] = count;
  if (report.intersectingPairs > 0) {
    j["volume_before_collapse"] = report.volumeBeforeCollapse;
    j["volume_after_collapse"] = report.volumeAfterCollapse;
  }
  return j;
}

// Elements per input triangle beyond which the shape, not the surface's
// resolution, sets the candidates' sizes (each of the bunny's inputs, 114
// to 3674 triangles, gives 5 to 8 elements per triangle at q2).
constexpr Index kShapeRefinementRatio = 50;

// What to change when the selection is off its targets: the range the
// candidates cover, and the options that give other candidates.
std::string selectionHint(const std::vector<Index>& counts, const std::vector<double>& targets,
                          const BuildOptions& options, const std::vector<RepairedInput>& inputs) {
  Index fewest = std::numeric_limits<Index>::max(), most = 0, made = 0;
  for (Index c : counts)
    if (c >= 0) {
      fewest = std::min(fewest, c);
      most = std::max(most, c);
      ++made;
    }
  std::string hint;
  if (made == 1)
    hint = "hint: the only candidate has " + std::to_string(most) +
           " elements; choose --min-elements and --max-elements near it";
  else if (fewest == most)
    hint = "hint: the " + std::to_string(made) + " candidates all have " + std::to_string(most) +
           " elements; choose --min-elements and --max-elements near that";
  else
    hint = "hint: the " + std::to_string(made) + " candidates have " + std::to_string(fewest) +
           " to " + std::to_string(most) +
           " elements; choose --min-elements and --max-elements in that range";
  Index inputTriangles = 0;
  for (const RepairedInput& input : inputs)
    inputTriangles = std::max(inputTriangles, input.mesh.triangleCount());
  // Coarser inputs give fewer elements where the surface's triangles set
  // the elements' size; far more elements than triangles come from the
  // shape (TetGen's -q refines a thin plate's faces down to its thickness:
  // 128105 elements from 12 triangles at every quality up to 16, where
  // Netgen gives 682 to 2433).
  if (options.mesher == MesherKind::TetGen &&
      fewest > kShapeRefinementRatio * std::max<Index>(inputTriangles, 1))
    hint += "; the fewest are " + std::to_string(fewest / std::max<Index>(inputTriangles, 1)) +
            "x the input's " + std::to_string(inputTriangles) +
            " triangles, so the shape, not its surface, sets them (thin parts refine under "
            "TetGen's quality bound): --mesher netgen meshes thin shapes coarser";
  else if (!options.decimate && inputs.size() == 1)
    hint += ", or add coarser levels of detail (--decimate, or --lod-series)";
  else if (options.mesher == MesherKind::TetGen)
    hint += ", or widen --qualities";
  // Only a size bound gives more elements than the finest quality does.
  if (!options.sizeToTargets && targets.back() > static_cast<double>(most) * kTargetTolerance)
    hint += "; --size-to-targets meshes under size bounds aimed at the targets";
  return hint;
}

// One warning per chosen level with slivers, and for TetGen's the way
// around them: Netgen remeshes the input surface, TetGen meshes within its
// triangles (a decimated surface's can give slivers at every quality).
std::vector<std::string> sliverWarnings(const std::vector<CandidateReport>& candidates,
                                        const std::vector<int>& chosen) {
  std::vector<std::string> warnings;
  for (std::size_t level = 0; level < chosen.size(); ++level) {
    const CandidateReport& c = candidates[static_cast<std::size_t>(chosen[level])];
    const std::string problem = sliverProblem(c.statistics);
    if (problem.empty()) continue;
    if (level > 0 && chosen[level] == chosen[level - 1]) continue;  // said for the level before
    std::string warning = "level " + std::to_string(level) + " " + problem;
    if (c.mesher == toString(MesherKind::TetGen))
      warning += netgenAvailable()
                     ? "; --mesher netgen remeshes the surface"
                     : "; another input surface (finer, or decimated otherwise) may give better";
    warnings.push_back(warning);
  }
  return warnings;
}

}  // namespace

std::string levelOfDetailMismatch(const BoundingBox& finest, const BoundingBox& box,
                                  const std::string& finestName) {
  const double overlap = boxOverlap(finest, box);
  if (overlap >= kLevelOfDetailOverlap) return {};
  return "is not a level of detail of " + finestName + ": their bounding boxes share " +
         formatNumber(std::round(1000 * overlap) / 10) +
         "% of the volume they span together (levels of detail of one object share most of "
         "it); each is the same object, in the same place and units, at another resolution";
}

std::string meshingLabel(MesherKind mesher, double quality, double sizeBound) {
  char text[64];
  if (mesher == MesherKind::TetGen)
    std::snprintf(text, sizeof text, "q%g", quality);
  else if (quality >= 0 && quality <= 4 && quality == std::floor(quality))
    std::snprintf(text, sizeof text, "%s",
                  netgenFinenessName(static_cast<NetgenFineness>(quality)));
  else
    std::snprintf(text, sizeof text, "preset %g", quality);
  std::string label = text;
  if (sizeBound > 0) {
    std::snprintf(text, sizeof text, " %c%.3g", mesher == MesherKind::TetGen ? 'a' : 'h',
                  sizeBound);
    label += text;
  }
  return label;
}

BuildResult buildDataset(std::vector<SurfaceInput> inputs, const BuildOptions& options,
                         const BuildEvents& events) {
  for (double q : options.qualities)
    if (!(q > 1.0)) throw Error("quality " + formatNumber(q) + " must be greater than 1.0");
  // (The schema's ranges: wrap_option, build_option.)
  for (const auto& [option, value] :
       {std::pair{&wrap_option::kAlpha, options.wrap.alpha},
        std::pair{&wrap_option::kOffset, options.wrap.offset},
        std::pair{&build_option::kLevels, static_cast<double>(options.levels)}})
    if (const auto problem = option->problem(value)) throw Error(*problem);
  const std::vector<double> targets =
      levelTargets(options.minElements, options.maxElements, options.levels);
  if (options.mesher == MesherKind::Netgen && !netgenAvailable())
    throw Error("this TetSkin was built without Netgen");

  BuildResult result;
  using Clock = std::chrono::steady_clock;
  auto stageStart = Clock::now();
  auto endStage = [&](const char* name) {
    const auto now = Clock::now();
    result.stageSeconds.emplace_back(name, std::chrono::duration<double>(now - stageStart).count());
    stageStart = now;
  };
  if (events.progress) events.progress("repair", 0, inputs.size());
  // The finest input as read: what every level is measured against.
  SurfaceMesh reference;
  std::string finestFile;
  std::vector<RepairedInput> prepared =
      prepareInputs(std::move(inputs), options, events, reference, finestFile);
  bool trimmed = trimReference(reference, finestFile, prepared);
  endStage(options.decimate ? "repair + decimation" : "repair");
  if (events.cancelled && events.cancelled()) throw Cancelled();
  const std::vector<CandidateSpec> specs = candidateSpecs(prepared, options);

  Candidates found;
  result.meshingSeconds =
      meshCandidates(specs, prepared, reference, options, events, "meshing", found, targets.back());
  endStage("meshing + cleanup");
  if (options.wrap.mode == WrapMode::Auto) {
    const std::size_t first = prepared.size();
    if (wrapRefusedInputs(prepared, specs, found, options, events)) {
      if (!trimmed) trimmed = trimReference(reference, finestFile, prepared);
      result.meshingSeconds +=
          meshCandidates(candidateSpecs(prepared, options, first), prepared, reference, options,
                         events, "meshing the wraps", found, targets.back());
      endStage("wrap + meshing");
    }
  }
  if (options.sizeToTargets) {
    result.meshingSeconds +=
        addSizedCandidates(prepared, reference, targets, options, events, found);
    endStage("sizing");
  }
  if (events.progress) events.progress("selection", 0, 1);
  const FaithfulSelection selection = selectFaithfulLevels(found, targets, options);
  if (!selection.unfaithful.empty()) {
    std::string problems;
    for (const UnfaithfulLevel& level : selection.unfaithful)
      problems += (problems.empty() ? "" : "\n") + level.problem + ". " + level.waysOut;
    if (!options.acceptUnfaithful)
      throw Error(problems + "\n(nothing was written; the bound is " +
                  formatNumber(kFidelityMeanShare) + " of the element size on average and " +
                  formatNumber(kFidelityMaxShare) + " at worst)");
    for (const UnfaithfulLevel& level : selection.unfaithful)
      say(events, "warning: accepted: " + level.problem);
  }
  result.chosen = selection.chosen;
  result.skippedCandidates = found.skipped;
  result.candidates = std::move(found.reports);
  std::vector<TetMesh>& meshes = found.meshes;
  const std::vector<Index>& counts = found.counts;

  // Coarsest first, whatever order the targets' picks came in.
  std::stable_sort(result.chosen.begin(), result.chosen.end(), [&](int a, int b) {
    return counts[static_cast<std::size_t>(a)] < counts[static_cast<std::size_t>(b)];
  });
  const std::vector<std::string> warnings = selectionWarnings(counts, result.chosen, targets);
  for (const std::string& warning : warnings) say(events, "warning: " + warning);
  if (!warnings.empty()) say(events, selectionHint(counts, targets, options, prepared));
  for (const std::string& warning : sliverWarnings(result.candidates, result.chosen))
    say(events, "warning: " + warning);

  Dataset& dataset = result.dataset;
  nlohmann::json candidatesJson = nlohmann::json::array();
  for (const CandidateReport& c : result.candidates) {
    nlohmann::json j = {{"input", c.input},
                        {"mesher", c.mesher},
                        {"quality", c.label},
                        {"ok", c.ok},
                        {"seconds", c.seconds}};
    if (c.sizeBound > 0) j["size_bound"] = c.sizeBound;
    if (c.wrap) j["wrapped"] = true;
    if (c.ok) {
      j["nodes"] = c.nodes;
      j["elements"] = c.elements;
      j["statistics"] = c.statistics.asMap();
      if (c.fidelity)
        j["fidelity"] = {{"input_to_level_mean", c.fidelity->inputToLevelMean},
                         {"input_to_level_max", c.fidelity->inputToLevelMax},
                         {"element_size", c.fidelity->elementSize},
                         {"faithful", c.fidelity->faithful}};
    } else {
      j["error"] = c.error;
    }
    candidatesJson.push_back(j);
  }
  for (int chosen : result.chosen) {
    const auto i = static_cast<std::size_t>(chosen);
    appendLevel(dataset.mesh, meshes[i]);
    LevelConfig level;
    level.source.input = result.candidates[i].input;
    level.source.mesher = result.candidates[i].mesher;
    level.source.quality = result.candidates[i].quality;
    level.source.sizeBound = result.candidates[i].sizeBound;
    level.source.wrap = result.candidates[i].wrap;
    level.statistics = result.candidates[i].statistics.asMap();
    level.fidelity = result.candidates[i].fidelity;
    level.statistics["target_elements"] =
        targets[std::min(dataset.config.levels.size(), targets.size() - 1)];
    dataset.config.levels.push_back(level);
  }
  nlohmann::json inputsJson = nlohmann::json::array();
  for (const RepairedInput& r : prepared) {
    nlohmann::json j = {{"file", r.file}, {"derived", r.derived}, {"repair", repairJson(r.repair)}};
    if (r.wrap) {
      j["wrapped"] = true;
      if (!r.wrapReason.empty()) j["wrap_reason"] = r.wrapReason;
    }
    inputsJson.push_back(j);
  }
  // The finest original input is the surface a viewer shows by default.
  for (const RepairedInput& r : prepared)
    if (!r.derived) {
      dataset.config.surface = r.file;
      break;
    }
  dataset.config.up = options.up;
  dataset.config.provenance = {{"tool", "tetskin build"},
                               {"inputs", inputsJson},
                               {"options",
                                {{"levels", options.levels},
                                 {"min_elements", options.minElements},
                                 {"max_elements", options.maxElements},
                                 {"mesher", toString(options.mesher)},
                                 {"qualities", options.qualities},
                                 {"decimate", options.decimate},
                                 {"size_to_targets", options.sizeToTargets},
                                 {"accept_unfaithful", options.acceptUnfaithful},
                                 {"wrap", toString(options.wrap.mode)},
                                 {"wrap_alpha", options.wrap.alpha},
                                 {"wrap_offset", options.wrap.offset}}},
                               {"targets", targets},
                               {"candidates", candidatesJson}};
  endStage("selection + assembly");
  return result;
}

}  // namespace tetskin
