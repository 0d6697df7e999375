// SPDX-License-Identifier: AGPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <limits>

#include "Candidates.h"
#include "tetskin/meshing/Meshers.h"
#include "tetskin/meshing/TargetSizing.h"

namespace tetskin {
namespace {

// One target's sizing. The first round meshes the chosen input at every
// quality (`starts`: the quality and its mesh's count without a bound); the
// track then follows the quality that came closest, with its last bound.
struct SizingTrack {
  double target = 0;
  std::size_t input = 0;
  double volume = 0;
  std::vector<std::pair<double, double>> starts;  // (quality, unbounded elements)
  double quality = 0, unboundedElements = 0, bound = 0;
  std::size_t lastCandidate = 0;
  bool ended = false;  // no first-round mesh succeeded
};

bool someCandidateClose(const Candidates& found, double target) {
  for (std::size_t c = 0; c < found.counts.size(); ++c)
    if (faithful(found.reports[c]) && closeToTarget(static_cast<double>(found.counts[c]), target))
      return true;
  return false;
}

// The count of the candidate of `file` at `quality` without a size bound; -1
// when it failed or was not made.
Index unboundedCount(const Candidates& found, const std::string& file, double quality) {
  for (std::size_t c = 0; c < found.reports.size(); ++c)
    if (found.reports[c].input == file && found.reports[c].sizeBound == 0 &&
        found.reports[c].quality == quality)
      return found.counts[c];
  return -1;
}

// Where a target's sizing starts. TetGen keeps every input triangle, so a
// bound only adds elements: it meshes the finest input that has a quality
// whose unbounded mesh has fewer elements than the target, at each such
// quality. Netgen remeshes the surface, so the finest input serves every
// target, at the one quality given. False when no input can.
bool startTrack(const std::vector<RepairedInput>& prepared, const Candidates& found,
                const std::vector<double>& qualities, const BuildOptions& options,
                SizingTrack& track) {
  for (std::size_t i = 0; i < prepared.size(); ++i) {
    const double volume = enclosedVolume(prepared[i].mesh);
    if (!(volume > 0.0)) continue;
    track.starts.clear();
    for (double quality : qualities) {
      double unbounded = 0;
      if (options.mesher == MesherKind::TetGen) {
        const Index count = unboundedCount(found, prepared[i].file, quality);
        if (count < 0 || static_cast<double>(count) >= track.target) continue;
        unbounded = static_cast<double>(count);
      }
      track.starts.emplace_back(quality, unbounded);
    }
    if (track.starts.empty()) continue;
    track.input = i;
    track.volume = volume;
    return true;
  }
  return false;
}

CandidateSpec sizedSpec(std::size_t input, double quality, double volumeBound, MesherKind mesher) {
  const double bound = mesher == MesherKind::TetGen ? volumeBound : edgeForVolumeBound(volumeBound);
  return {input, quality, meshingLabel(mesher, quality, bound), bound};
}

// How far a count is from its target, either way.
double missRatio(Index count, double target) {
  const double ratio = static_cast<double>(count) / target;
  return ratio >= 1.0 ? ratio : 1.0 / ratio;
}

}  // namespace

double addSizedCandidates(const std::vector<RepairedInput>& prepared, const SurfaceMesh& reference,
                          const std::vector<double>& targets, const BuildOptions& options,
                          const BuildEvents& events, Candidates& found) {
  // TetGen: every quality asked for, best first, since the counts jump with
  // the bound by different steps at each (at q1.2 a box goes from about 160
  // to 820 elements as the bound halves); Netgen: the middle preset, whose
  // size bound the sizing replaces.
  const std::vector<double> qualities =
      options.mesher == MesherKind::TetGen
          ? distinctQualities(options)
          : std::vector<double>{static_cast<double>(NetgenFineness::Moderate)};
  const double firstFactor =
      options.mesher == MesherKind::TetGen ? kFirstTetGenSizingFactor : kFirstNetgenSizingFactor;
  std::vector<SizingTrack> tracks;
  for (double target : targets) {
    if (someCandidateClose(found, target)) continue;
    SizingTrack track;
    track.target = target;
    if (startTrack(prepared, found, qualities, options, track))
      tracks.push_back(track);
    else
      say(events, "sizing: no input can be meshed to about " +
                      std::to_string(std::llround(target)) + " elements: " +
                      (options.mesher == MesherKind::TetGen
                           ? "TetGen keeps every input triangle, and each input's mesh without "
                             "a size bound has more"
                           : "no input encloses a positive volume"));
  }
  double seconds = 0;
  for (int round = 1; round <= kSizingRounds && !tracks.empty(); ++round) {
    std::vector<CandidateSpec> specs;
    std::vector<std::vector<std::size_t>> made(tracks.size());  // candidate per start
    for (std::size_t k = 0; k < tracks.size(); ++k) {
      SizingTrack& track = tracks[k];
      if (round == 1) {
        for (const auto& [quality, unbounded] : track.starts) {
          made[k].push_back(found.counts.size() + specs.size());
          specs.push_back(
              sizedSpec(track.input, quality,
                        firstVolumeBound(track.volume, unbounded, track.target, firstFactor),
                        options.mesher));
        }
        continue;
      }
      track.bound =
          nextVolumeBound(track.volume, track.unboundedElements, track.target, track.bound,
                          static_cast<double>(found.counts[track.lastCandidate]));
      track.lastCandidate = found.counts.size() + specs.size();
      specs.push_back(sizedSpec(track.input, track.quality, track.bound, options.mesher));
    }
    seconds += meshCandidates(specs, prepared, reference, options, events,
                              "sizing, round " + std::to_string(round), found);
    if (round == 1)
      for (std::size_t k = 0; k < tracks.size(); ++k) {
        // Follow the quality whose mesh came closest (none: the track ends).
        SizingTrack& track = tracks[k];
        double bestMiss = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < made[k].size(); ++j) {
          const Index count = found.counts[made[k][j]];
          if (count < 0 || !(missRatio(count, track.target) < bestMiss)) continue;
          bestMiss = missRatio(count, track.target);
          track.quality = track.starts[j].first;
          track.unboundedElements = track.starts[j].second;
          track.bound =
              firstVolumeBound(track.volume, track.unboundedElements, track.target, firstFactor);
          track.lastCandidate = made[k][j];
        }
        track.ended = bestMiss == std::numeric_limits<double>::infinity();
      }
    // A target stays open while its last candidate succeeded and is still
    // off, and no other candidate meets it.
    std::erase_if(tracks, [&](const SizingTrack& track) {
      return track.ended || found.counts[track.lastCandidate] < 0 ||
             someCandidateClose(found, track.target);
    });
  }
  return seconds;
}

}  // namespace tetskin
