// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Keyword arguments as the libraries' options, read through the option
// schema (core/OptionSchema.h): a number option goes by its config key
// (youngs_modulus) or by its command-line flag without the dashes (young),
// an enumeration by its names (solver="multigrid"); each is checked as the
// command line checks it, and an unknown keyword is an error that lists the
// known ones. So Python takes what `tetskin` takes, in the same words.

#include <pybind11/pybind11.h>

#include <optional>
#include <set>
#include <string>

#include "tetskin/core/OptionSchema.h"
#include "tetskin/io/DatasetConfig.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/session/RunRequest.h"

namespace tetskin::python {

namespace py = pybind11;

// The keywords of one call, each read at most once; finish() refuses the
// ones nobody read.
class Keywords {
 public:
  Keywords(const py::kwargs& kwargs, std::string call);

  // The option's value (by its key or its flag's name), checked against its
  // range; nullopt when not given.
  std::optional<double> number(const NumberOption& option);
  // The same for an option that counts (a whole number).
  std::optional<int> count(const NumberOption& option);
  // The value of an enum option (OptionSchema.h), given by its key.
  template <SchemaEnum E>
  std::optional<E> choice(const EnumOption<E>& option) {
    const char* key = option.key;
    const std::optional<py::object> value = take(key);
    if (!value) return std::nullopt;
    if (!py::isinstance<py::str>(*value))
      throw Error(call_ + ": " + key + ": expected one of " + listed(namesOf<E>()));
    try {
      return fromName<E>(value->cast<std::string>());
    } catch (const Error& e) {
      throw Error(call_ + ": " + key + ": " + e.what());
    }
  }
  // Any other keyword's value, nullopt when not given. (`listedAsKnown`:
  // whether an unknown keyword's error offers it: an old name is not.)
  std::optional<py::object> take(const char* key, bool listedAsKnown = true);
  // `value` (given as `name`), or the value given by `other`, another name
  // of the same option (`old`: one it had before, read with a
  // DeprecationWarning and not offered among the known names), `name` then
  // becoming `other`; an error when both are given.
  std::optional<py::object> orOtherName(std::optional<py::object> value, std::string& name,
                                        const std::string& other, bool old);
  // Whether `key` was given (and not taken yet).
  bool given(const char* key) const { return given_.contains(key); }
  // Error naming the keywords not read: "simulation: unknown option 'yung'
  // (known: ...)".
  void finish() const;
  const std::string& call() const { return call_; }

 private:
  py::dict given_;
  std::string call_;
  std::set<std::string> known_;
};

// A run request from keywords, as `tetskin simulate` makes it from its
// options: the material over the config's (youngs_modulus or young, ...),
// the time step, tolerance, solver, tangent, coarse_operators and the other
// numbers of simulation_option, up, gravity (3 numbers) and floor_height;
// the defaults are the request's (RunRequest.h), as in every front end.
RunRequest runRequest(Keywords& keywords);
// The same keywords set in `request` (a scene's run); what is not given
// stays as `request` has it.
void applyRunKeywords(Keywords& keywords, RunRequest& request);
// The request's scenario parameters (for its scenario, on a level of
// `levelNodes` nodes): its numbers (base_share or base, ...; refused for a
// scenario that does not read them, as on the command line), fixed_nodes,
// fixed_box ((2, 3): min and max corners), loads ((n, 3) newtons on the
// level's nodes), load_seconds and load_curve ((k, 2): time in s, factor).
void readScenarioParameters(Keywords& keywords, Index levelNodes, RunRequest& request);
// A build's options beyond those `build` names itself: qualities,
// size_to_targets, accept_unfaithful, jobs, timeout, wrap, wrap_alpha,
// wrap_offset, up.
void readBuildOptions(Keywords& keywords, BuildOptions& options);

// What runRequest and readScenarioParameters read, for Simulation's
// docstring: every keyword by its key, with an enum's names, as the schema
// has them ("the material (youngs_modulus, ...), time_step, ..., solver
// ('auto', 'cg' or 'multigrid'), ...").
std::string runKeywordsHelp();

}  // namespace tetskin::python
