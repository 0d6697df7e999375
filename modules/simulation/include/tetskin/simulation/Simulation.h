// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The control mesh as an elastic body: corotated FEM, implicit (backward)
// Euler steps (M + h C + h^2 K_T) dv = h (f - C v - h K_T v) with Rayleigh
// damping C = alpha M + beta K and the tangent K_T = K + K_rot (K = sum
// R K_e R^T, K_rot the rotation term: CorotatedFem::SystemTerms), Dirichlet
// and kinematic nodes, gravity, external point forces and a floor with
// penalty contact. Solved by block-Jacobi CG, by CG
// with a multigrid V-cycle over the dataset's coarser levels, or by whichever
// of the two is faster on the running simulation (SolverChoice.h).
//
// A step composes units of the module's src, one concern each: the
// integrator (ImplicitEuler: the system of a step and its outcome), which
// sums the body's force models (ForceModel.h: elasticity, gravity, mass
// damping, the fixed and driven nodes' Dirichlet rows, contact with the
// obstacles and the floor: penalty springs and Coulomb friction), and the linear solve
// (SolverStack: the solvers, the multigrid hierarchy, the initial guess).
// A new contact model is a new force model; a new integrator or solver
// replaces its unit (doc/dev/extending.md).
//
// Threads: step() may run on one thread while others call state(),
// setExternalForces() or energies(), which are guarded by a mutex, or
// frameFields() and reactionForces() of a state taken before, which read
// nothing a step changes. Two threads must not call step() at the same time.

#include <array>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/FloorPlane.h"
#include "tetskin/core/FrameFields.h"
#include "tetskin/core/RunConditions.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/core/UpAxis.h"
#include "tetskin/simulation/CorotatedFem.h"
#include "tetskin/simulation/LinearSolvers.h"
#include "tetskin/simulation/Obstacle.h"
#include "tetskin/simulation/SolverChoice.h"
#include "tetskin/simulation/SurfaceLoad.h"

namespace tetskin {

class ForceModel;
class Preconditioner;
class ImplicitEuler;
class NodeConstraints;
class ObstacleContact;
class BodyContact;
class SurfaceLoadForce;
class NodeNumbering;
class SolverStack;

// Multigrid coarse operators: Galerkin products P^T A P of the system, or the
// coarse meshes' own corotated FEM (rediscretized) at positions interpolated
// from the finer level, as sparse as the fine system.
enum class CoarseOperators { Galerkin, Rediscretized };
template <>
struct EnumSchema<CoarseOperators> {
  static constexpr const char* what = "coarse operators";
  static constexpr EnumValue<CoarseOperators> values[] = {
      {CoarseOperators::Galerkin, "galerkin", "P^T A P"},
      {CoarseOperators::Rediscretized, "rediscretized", "each coarse mesh's own FEM"}};
};

// Multigrid coarse levels: the solver's own nested grids enclosing the mesh
// (GridHierarchy.h: about 8x fewer nodes per level, no extrapolated
// weights), or the dataset's coarser levels (decimated and meshed again).
// Rediscretized coarse operators need the dataset's: a grid level is no
// body mesh with an FEM of its own.
enum class CoarseLevels { Grid, Dataset };
template <>
struct EnumSchema<CoarseLevels> {
  static constexpr const char* what = "coarse levels";
  static constexpr EnumValue<CoarseLevels> values[] = {
      {CoarseLevels::Grid, "grid", "nested grids enclosing the mesh, about 8x coarser each"},
      {CoarseLevels::Dataset, "dataset", "the dataset's coarser levels"}};
};

// What meets the obstacles: the bound skin's vertices (each acting on its
// control nodes through the binding's weights), the control mesh's nodes,
// or both. Without a skin (Simulation::setContactSkin) the nodes do.
enum class ContactPoints { Skin, Cage, Both };
template <>
struct EnumSchema<ContactPoints> {
  static constexpr const char* what = "contact points";
  static constexpr EnumValue<ContactPoints> values[] = {
      {ContactPoints::Skin, "skin", "the bound surface's vertices, through the binding"},
      {ContactPoints::Cage, "cage", "the control mesh's nodes"},
      {ContactPoints::Both, "both", "both"}};
};

// The implicit step's tangent stiffness: full (R K R^T and the rotation term
// K_rot, CorotatedFem.h: steady under large steps on stretched bodies) or
// warped (R K R^T alone, the stiffness warping of Müller et al. 2002: an
// element pass about a quarter cheaper).
enum class Tangent { Full, Warped };
template <>
struct EnumSchema<Tangent> {
  static constexpr const char* what = "tangent";
  static constexpr EnumValue<Tangent> values[] = {
      {Tangent::Full, "full",
       "R K R^T and the rotation term: steady under large steps on stretched bodies"},
      {Tangent::Warped, "warped", "R K R^T alone, stiffness warping: a cheaper element pass"}};
};

inline constexpr double kStandardGravity = 9.81;  // m/s^2

// Contact of the skins with each other and with themselves (BodyContact in
// the module's src): a run's bodies meet skin to skin whenever its contact
// skin holds several (Simulation::setContactSkin); a body's skin meets
// itself when `self` is set, or when its number is in `selfBodies`. The
// skins are shells `thickness` thick.
struct SkinCollisions {
  bool self = false;            // every body's
  std::vector<int> selfBodies;  // these bodies' (numbered as the contact skin's)
  double thickness = 0;         // model units; 0: the contact skin's mean edge length
  double stiffness = 0;         // N/m per skin vertex; 0: automatic, as the obstacles'
  double staticFriction = 0.5, kineticFriction = 0.4;  // mu_s >= mu_k >= 0
};

// The number options of a run (OptionSchema.h): their keys, flags, ranges
// and defaults, read by SimulationOptions' defaults, its checks, the
// command line and the GUI.
namespace simulation_option {
inline constexpr NumberOption kTimeStep{
    "time_step", "--time-step", "--dt", "the time step", "seconds per implicit step",
    above(0),    1.0 / 60.0};
inline constexpr NumberOption kTolerance{"tolerance",
                                         "--tolerance",
                                         "",
                                         "the solver tolerance (a relative residual)",
                                         "relative residual of each solve",
                                         between(0, 1, false, false),
                                         1e-6};
// At most kMaxProductColumns (NodeBlockMatrix.h): the guess's one pass over A.
inline constexpr NumberOption kGuessSolutions{
    "guess_solutions",
    "--guess-solutions",
    "",
    "the initial guess's solutions",
    "start each solve from the best combination of the last N solutions (0: from the last one "
    "as it is)",
    between(0, 16),
    6};
inline constexpr NumberOption kCoarseReuse{
    "coarse_reuse",
    "--coarse-reuse",
    "",
    "the coarse-operator reuse",
    "multigrid: rebuild the coarse operators every N steps (solves stay exact)",
    atLeast(1),
    4};
inline constexpr NumberOption kMaxIterations{"max_iterations",
                                             "--max-iterations",
                                             "",
                                             "the solver's iteration limit",
                                             "CG iterations per solve at most",
                                             atLeast(1),
                                             2000};
inline constexpr NumberOption kFriction{
    "friction",
    "--friction",
    "",
    "the floor's friction",
    "the floor's Coulomb friction coefficient, static and kinetic",
    atLeast(0),
    0.3};
inline constexpr NumberOption kFloorStiffness{
    "floor_stiffness",
    "--floor-stiffness",
    "",
    "the floor stiffness (0: automatic)",
    "floor penalty stiffness, N/m; 0: stiff enough for the mesh",
    atLeast(0),
    0};
// The enum options (their defaults: SimulationOptions' fields, and a run
// request's solver kDefaultRunSolver).
inline constexpr EnumOption<SolverKind> kSolver{"solver", "--solver", "the solver"};
inline constexpr EnumOption<Tangent> kTangent{"tangent", "--tangent", "the tangent",
                                              "the implicit step's stiffness: "};
inline constexpr EnumOption<CoarseOperators> kCoarseOperators{
    "coarse_operators", "--coarse-operators", "the coarse operators", "multigrid: "};
inline constexpr EnumOption<CoarseLevels> kCoarseLevels{"coarse_levels", "--coarse-levels",
                                                        "the coarse levels", "multigrid: "};
inline constexpr EnumOption<ContactPoints> kContactPoints{"contact_points", "--contact-points",
                                                          "the contact points", "obstacles meet "};
}  // namespace simulation_option

struct SimulationOptions {
  ElasticMaterial material;
  // Elements (the level's numbering) of other materials: a run of several
  // bodies. Their damping must be `material`'s: one damping for the run.
  std::vector<MaterialRegion> materialRegions;
  double timeStep = simulation_option::kTimeStep.defaultValue;
  Eigen::Vector3d gravity{0, -kStandardGravity, 0};
  UpAxis up = UpAxis::Y;              // the floor's normal (and the scenarios' vertical)
  std::optional<double> floorHeight;  // floor plane: the up coordinate = height
  double floorStiffness = simulation_option::kFloorStiffness.defaultValue;  // 0 = automatic
  double friction = simulation_option::kFriction.defaultValue;
  // Closed surfaces the nodes cannot enter (ObstacleContact: penalty
  // springs and Coulomb friction), each checked by obstacleProblem.
  std::vector<Obstacle> obstacles;
  ContactPoints contactPoints = ContactPoints::Skin;
  SkinCollisions skinCollisions;
  Tangent tangent = Tangent::Full;
  SolverKind solver = SolverKind::ConjugateGradient;
  double tolerance =
      simulation_option::kTolerance.defaultValue;  // relative residual of the linear solve
  // The solve starts from the combination of the last this many solutions
  // that is closest to the new one in the system's energy norm
  // (ProjectedInitialGuess.h); 0: from the last solution as it is.
  int guessSolutions = static_cast<int>(simulation_option::kGuessSolutions.defaultValue);
  // Multigrid: rebuild the coarse operators every this many steps (1 = every
  // step); the solve stays exact to `tolerance` either way. Rebuilt every
  // fourth step they cost 0-0.8 more iterations per step than rebuilt
  // every step, and the steps were 1.3-1.9x as fast (doc/user/simulation.md).
  int coarseReuse = static_cast<int>(simulation_option::kCoarseReuse.defaultValue);
  CoarseOperators coarseOperators = CoarseOperators::Galerkin;
  CoarseLevels coarseLevels = CoarseLevels::Grid;
  bool singlePrecisionCycle = true;  // multigrid: the V-cycle in float (CG stays double)
  // Multigrid: the V-cycle's smoother (LinearSolvers.h; Chebyshev of degree
  // 2 unless Gauss-Seidel is asked for, as the solver benchmark does to
  // compare them).
  MultigridSmoother smoother = MultigridSmoother::Chebyshev;
  int maxIterations = static_cast<int>(simulation_option::kMaxIterations.defaultValue);
  // cg: CG preconditioned by what this makes (one per simulation, set up
  // on every step's system) instead of block Jacobi; empty: block Jacobi.
  // How another solver is tried on the stepper's own systems (the solver
  // benchmark's sparse direct and algebraic multigrid baselines).
  std::function<std::unique_ptr<Preconditioner>()> preconditioner;

  // Whether the body meets anything: a floor or obstacles.
  bool hasContact() const { return floorHeight || !obstacles.empty(); }
  // The floor plane, if there is one (floorHeight along up).
  std::optional<FloorPlane> floor() const {
    if (!floorHeight) return std::nullopt;
    return FloorPlane{up, *floorHeight};
  }
};

// `options` upright along `up`: the floor's normal and the scenarios'
// vertical, with standard gravity pointing down it.
SimulationOptions uprightAlong(UpAxis up, SimulationOptions options);

struct StepStats {
  SolverKind solver = SolverKind::ConjugateGradient;  // the one that solved this step
  int iterations = 0;
  double residual = 0;
  int contacts = 0;
  double assemblySeconds = 0;  // the force models' system: element pass, contacts, rows
  double setupSeconds = 0;     // preconditioner (Galerkin products, factorization)
  double solveSeconds = 0;     // initial guess and CG iterations
};

// Per node of the level (#N rows, level-local numbering), SI units where
// the material is (metres, seconds, newtons).
// The contact skin's vertices at a state (Simulation::skinContact).
struct SkinContact {
  Eigen::VectorXd penetration;  // model units, positive inside an obstacle
  Points3 forces;               // N, the contact spring's
};

struct SimulationState {
  Points3 positions;   // #N x 3, m
  Points3 velocities;  // #N x 3, m/s
  // The external forces (loads, scenario forces, pulls; not gravity) that
  // acted in the step that led to this state; zero before the first step.
  Points3 externalForces;
  // The last step's change of velocity over its length; zero before the
  // first step and after setPositions/setVelocities (a new start).
  Points3 accelerations;
  double time = 0;
  Index steps = 0;
};

// The steps whose linear solve stopped at maxIterations with the relative
// residual still above the tolerance: each was taken all the same (with
// the solver's last iterate), but less exactly than asked.
struct SolveShortfall {
  Index steps = 0;
  double largestResidual = 0;
  Index largestAtStep = 0;  // its step number, from 1
};
// "3 steps stopped at the iteration limit (2000) with the relative residual
// above the tolerance 1e-06 (at most 0.0032, in step 2)", and unless the
// multigrid solved them all, "; MULTIGRID needs far fewer iterations on
// stiff bodies" with MULTIGRID how the caller's user chooses it (the CLI's
// "--solver multigrid", the GUI's "the multigrid solver").
std::string describe(const SolveShortfall& shortfall, const SimulationOptions& options,
                     const std::string& multigrid);

// The static solve's default tolerance: the largest force left on a free
// node, as a share of the largest load on one.
inline constexpr double kStaticTolerance = 1e-8;

// The outcome of a static solve (Simulation::solveStatic). Forces are per
// node (N): the largest force left on a free node, against the largest
// load (weight and external force) on one, and the forces' round-off
// floor: eps |x|max K_max, the elastic force's round-off at positions
// as large as the body's (the forces are computed from positions, not
// displacements, and a load spread thin over a fine mesh can ask for less
// than that).
struct StaticStats {
  bool converged = false;    // residual <= max(tolerance * load, floor)
  int iterations = 0;        // Newton iterations
  int linearIterations = 0;  // the linear solver's, over all of them
  double residual = 0;
  double load = 0;
  double floor = 0;
};

// Joules. The gravitational energy is measured from the rest shape where
// the dataset puts it: the body at rest there has none of the potentials,
// any state of a run has the same zero whichever state the run started
// from (a run continued from a frame carries its energies on), and a body
// far from the origin does not swamp the others with its height's energy.
// `load` is the surface loads' potential (surfaceLoadEnergy, SurfaceLoad.h;
// zero without them).
struct Energies {
  double kinetic = 0, elastic = 0, gravitational = 0, load = 0;
  double total() const { return kinetic + elastic + gravitational + load; }
};

class Simulation {
 public:
  // Simulates `level` (< 0: the finest) of the dataset; multigrid uses the
  // coarser levels. Each level it uses must have positive element volumes;
  // errors name the level after `datasetName` (e.g. the config's path).
  Simulation(const MultiLevelTetMesh& dataset, int level, const SimulationOptions& options,
             const std::string& datasetName = "dataset");
  ~Simulation();

  // Node ids here and in every call below are the dataset level's.
  // (Inside, nodes are renumbered breadth first for memory locality.)
  int level() const { return level_; }
  const TetMesh& restMesh() const { return rest_; }
  const SimulationOptions& options() const { return options_; }
  // SolverKind::Automatic: the trials so far and the faster solver of the
  // last round (nullptr for a fixed solver).
  const SolverChoice* solverChoice() const;
  // Lumped mass per node.
  Eigen::VectorXd nodeMasses() const;

  // The skin: `restSkin` bound to the simulated level by `binding`
  // (control ids in the dataset's numbering, as bind makes them). It meets
  // the obstacles where options.contactPoints is skin or both, and
  // skinContact reports on it in any case. Throws Error when the binding
  // is of another level or does not fit the surface.
  // `vertexBodies` numbers each vertex's body (empty: one body): the
  // bodies' skins meet each other, and each meets itself where
  // options.skinCollisions.self says (SkinCollisions); throws Error for a
  // triangle whose corners are of different bodies.
  void setContactSkin(const SurfaceMesh& restSkin, const SurfaceBinding& binding,
                      const std::vector<int>& vertexBodies = {});
  // The skins' contact thickness (model units; 0: the skins meet neither
  // each other nor themselves).
  double skinThickness() const;
  // The skins' spring per skin vertex in contact (N/m; the settings' or the
  // automatic one); 0 as skinThickness.
  double skinStiffness() const;
  // Per vertex of the contact skin at `state`: its penetration into the
  // obstacles and its contact spring's force (arrays::kPenetration,
  // kContactForce); empty without obstacles or a skin.
  SkinContact skinContact(const SimulationState& state) const;
  // Places obstacle k (of options().obstacles) at `placement` from the next
  // step on: a static obstacle's pose, a moving one's scale (its keyframes
  // stay). Not while a step runs: the GUI places obstacles while paused.
  // Throws Error for a k out of range or a placement obstacleProblem refuses.
  void setObstaclePlacement(std::size_t k, const ObstaclePose& placement);

  // Dirichlet nodes (level-local ids): they keep their position unless given
  // a kinematic target.
  void setFixedNodes(const std::vector<int>& nodes);
  const std::vector<int>& fixedNodes() const { return fixedNodes_; }
  // Nodes held along some axes only and free along the others (a symmetry
  // plane holds its nodes along its normal): level ids, each with the axes
  // (x, y, z) it is held along; replaces those given before. A node also
  // given to setFixedNodes is held whole. For the static solve and steps
  // alike; the multigrid's coarse corrections still reach such a node (CG
  // keeps its held axes). Throws Error for a node the level lacks, one
  // held along no axis, sizes that differ, and while the skins meet each
  // other (their coupling springs hold whole nodes only).
  void setHeldAxes(const std::vector<int>& nodes, const std::vector<std::array<bool, 3>>& axes);
  // The floor and the prescribed nodes (fixed, or held along an axis):
  // what a recorded run keeps of them.
  RunConditions conditions() const;
  // Positions (#nodes x 3, m) the given fixed nodes must reach at the end
  // of the next step.
  void setKinematicTargets(const std::vector<int>& nodes, const Points3& targets);
  // #N x 3 external forces (newtons, level-local), kept until replaced. Throws
  // Error naming the first node whose force is not finite: such a force
  // must not reach a step.
  void setExternalForces(const Points3& forces);
  Points3 externalForces() const;
  // Pressures and tractions on faces of the level (SurfaceLoad.h; node ids
  // the level's), replacing any given before; they act from the next step
  // on, times the factor below. Throws Error naming the load (from 0) and
  // its problem (surfaceLoadProblem).
  void setSurfaceLoads(const std::vector<SurfaceLoad>& loads);
  bool hasSurfaceLoads() const { return surfaceLoadForce_ != nullptr; }
  // Scales the surface loads from the next step on (a load curve's factor;
  // 1 at the start, 0 once they let go).
  void setSurfaceLoadFactor(double factor);
  // Their consistent nodal forces at `state` (#nodes x 3, N; zero rows
  // where none acts), at the present factor.
  Points3 surfaceLoadForces(const SimulationState& state) const;
  // #N x 3 positions (m) or velocities (m/s), level-local: a new start.
  void setPositions(const Points3& positions);
  void setVelocities(const Points3& velocities);

  // Throws Error when the step blows up (a node's new position or velocity
  // not finite or beyond kMaxCoordinate, Geometry.h), naming the step and
  // the node; the state is then left as it was.
  StepStats step();
  // Static equilibrium under the present loads, gravity, held and driven
  // nodes (at their targets), floor and obstacles (standing at the present
  // time; friction plays no part): the positions where every free node's
  // forces balance, by Newton's method on the corotated equations with a
  // backtracking line search, each Newton system solved by the run's
  // solver (cg, or multigrid over the solver's own grids). Starts from the
  // present positions; on return the body rests there (velocities zero,
  // time unchanged), unless it threw. Stops when the largest force left on
  // a free node is at most `tolerance` times the largest load on one (or,
  // with no load, the largest force at the start) or at the forces'
  // round-off floor (StaticStats), or after `maxIterations`
  // or when four line searches in a row find no decrease (then converged is
  // false and the best positions found are kept). Throws Error when there
  // is no equilibrium to find: a free body (no held node, floor or
  // obstacle) under a net load.
  StaticStats solveStatic(double tolerance = kStaticTolerance, int maxIterations = 60);
  SimulationState state() const;
  // The state's time and step count alone (state() converts every node's
  // rows to the level's numbering: too much for a caller that wants these).
  double time() const;
  Index steps() const;
  Energies energies() const;
  // Since construction (steps that failed not counted).
  SolveShortfall solveShortfall() const;
  // The forces the supports exert on the body at the fixed nodes (level
  // numbering; zero rows elsewhere) in `state` (one of this simulation's),
  // to hold them still or on their targets: M a + alpha M v - (f_el - beta K
  // v) - f_ext - M g there. A body settled under gravity and loads rests on
  // them: they sum to its weight and loads, opposed, and balance their
  // moment. Contact forces on fixed nodes are left out.
  Points3 reactionForces(const SimulationState& state) const;
  // Their sum: what the supports carry in all (a settled body's weight and
  // loads, opposed; zero without fixed nodes).
  Eigen::Vector3d supportReaction(const SimulationState& state) const;
  // `state` with its reactions and per element von Mises stress: what a
  // frame exports (FrameFields.h). (From a state taken once, so that a
  // frame's fields and the surface deformed with it are of one instant,
  // whatever step the GUI's runner takes in between.)
  // The force the floor and the obstacles exert on each node at `state`
  // (#nodes x 3, N): their penalty springs at `state`, and the obstacles'
  // friction of the last step (m dv / h).
  Points3 contactForces(const SimulationState& state) const;
  FrameFields frameFields(const SimulationState& state) const;

 private:
  int level_;
  Index levelFirstNode_;  // the level's first node in the dataset's numbering
  TetMesh rest_;          // the level's own numbering
  SimulationOptions options_;
  // The units a step composes (modules/simulation/src): the numbering, the
  // body, its force models (the fixed and driven nodes among them), the
  // integrator, the solver.
  std::unique_ptr<NodeNumbering> numbering_;
  TetMesh internal_;  // rest_ renumbered
  CorotatedFem fem_;  // on internal_
  std::vector<std::unique_ptr<ForceModel>> models_;
  NodeConstraints* constraints_ = nullptr;        // one of models_
  ObstacleContact* obstacles_ = nullptr;          // one of models_ (null: no obstacles)
  BodyContact* bodyContact_ = nullptr;            // one of models_ (null: skins do not meet)
  SurfaceLoadForce* surfaceLoadForce_ = nullptr;  // one of models_ (null: no surface loads)
  std::unique_ptr<ImplicitEuler> integrator_;
  std::unique_ptr<SolverStack> solvers_;
  std::vector<int> fixedNodes_;  // level numbering
  std::vector<int> axisNodes_;   // level numbering, held along axes_
  std::vector<std::array<bool, 3>> axes_;
  // The fixed nodes' and the held axes' dofs to the constraints and the
  // solvers.
  void applyHolds();

  mutable std::mutex mutex_;  // guards x_, v_, acceleration_, time_, steps_, external_,
                              // appliedExternal_, shortfall_
  Eigen::VectorXd x_, v_, external_;
  Eigen::VectorXd acceleration_;     // (v_ - v before the last step) / h
  Eigen::VectorXd stepExternal_;     // external_ as the step being taken reads it
  Eigen::VectorXd appliedExternal_;  // stepExternal_ of the last step taken
  double time_ = 0;
  Index steps_ = 0;
  SolveShortfall shortfall_;  // guarded by mutex_

  // Per-step work arrays, allocated once.
  SparseMatrix system_;
  Eigen::VectorXd rhs_, dv_;
};

}  // namespace tetskin
