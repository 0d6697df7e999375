// SPDX-License-Identifier: AGPL-3.0-or-later
// Scene: a scene file (or the same as a dict) run through the run layer as
// `tetskin simulate SCENE.json` runs it (SceneRun.h): a Simulation whose
// body is placed, whose skin meets the obstacles, and which reports the
// skin's contact.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "Api.h"
#include "ArrayConversion.h"
#include "KeywordOptions.h"
#include "Objects.h"
#include "tetskin/core/Error.h"
#include "tetskin/session/SceneRun.h"

namespace tetskin::python {
namespace {

struct SceneObject : SimulationObject {
  int sceneSteps = 0;  // the scene's "steps"
};

std::shared_ptr<SceneObject> make(py::object given, const py::kwargs& kwargs) {
  Keywords keywords(kwargs, "Scene");
  Scene scene;
  if (py::isinstance<py::dict>(given)) {
    // (Through JSON: the same reader, the same errors, paths from the
    // working folder.)
    const std::string text = py::str(py::module_::import("json").attr("dumps")(given));
    scene = parseScene(nlohmann::json::parse(text), "scene", std::filesystem::current_path());
  } else {
    scene = readScene(py::cast<std::filesystem::path>(given));
  }
  SceneRun run = loadScene(scene);
  applyRunKeywords(keywords, run.request);
  readScenarioParameters(keywords,
                         run.dataset.mesh.levels[static_cast<std::size_t>(run.level)].nodeCount,
                         run.request);
  keywords.finish();
  auto object = std::make_shared<SceneObject>();
  object->spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  object->sceneSteps = run.steps;
  object->dataset = std::make_shared<const Dataset>(std::move(run.dataset));
  {
    py::gil_scoped_release unlocked;
    object->session = std::make_unique<SimulationSession>(object->dataset->mesh, object->spec);
    if (run.surface)
      object->session->bindSurface(std::move(run.surface->surface), std::move(run.surface->binding),
                                   run.request.datasetName);
  }
  object->forces = Points3::Zero(object->nodeCount(), 3);
  warnOfRun(*object);
  return object;
}

}  // namespace

void addSceneApi(py::module_& m) {
  py::class_<SceneObject, SimulationObject, std::shared_ptr<SceneObject>>(
      m, "Scene",
      "A scene (doc/user/contact-and-scenes.md) as `tetskin simulate SCENE.json` runs it: a "
      "Simulation of its body among its obstacles, its skin meeting them.")
      .def(py::init(&make), py::arg("scene"),
           "Reads the scene: a path to a scene file, or a dict of the same keys (paths from the "
           "working folder). Keyword options as Simulation's, over the scene's values.")
      .def_property_readonly(
          "scene_steps", [](const SceneObject& s) { return s.sceneSteps; },
          "the scene's step count (its \"steps\", else the default)")
      .def(
          "skin_contact",
          [](const SceneObject& s) {
            const Simulation& sim = s.session->simulation();
            SkinContact contact = sim.skinContact(sim.state());
            return py::make_tuple(owning(std::move(contact.penetration)),
                                  owning(std::move(contact.forces)));
          },
          "(penetration, forces) per skin vertex now: the signed depth in the obstacle it is "
          "deepest in (model units, positive inside) and its contact spring's force (N), as the "
          "recorded run's Penetration and ContactForce; empty without a skin or obstacles.")
      .def(
          "skin_positions",
          [](SceneObject& s) {
            if (!s.session->hasSurface()) throw Error("skin_positions: the scene has no surface");
            return owning(Points3(
                s.session->deformedSurface(s.session->state().positions).deformed->positions));
          },
          "The skin's vertex positions now, float64 (V, 3).");
}

}  // namespace tetskin::python
