// CalculiX (ccx) input deck for a muscle-activation solve of an FE face model.
//
// Units: the mesh is in mm, so forces are N, stresses/moduli N/mm² (= MPa; 1 Pa = 1e-6 N/mm²),
// the compressibility D N⁻¹mm², cable forces N.
//
// Model written (Modules/CLI/SimulateMuscleActivation/README.md explains the choices):
//   * solids: hyperelastic polynomial N=2 (C10, C01, C20, C11, C02, D1, D2), one material per
//     tissue layer; hexahedra as C3D8/C3D8I/C3D8R, wedges C3D6, tetrahedra C3D4;
//   * cables: SPRINGA (axial, large-rotation) elements, force N along the fibre. Each cable of a
//     track carries the Hill-type law of CableForce (active force-length times activation times the
//     track's maximum force, plus a small stabilising slope), written as a piecewise-linear
//     force-elongation curve at "temperature" 0 (activation 0) and 1 (the muscle's level); the
//     temperature is only a load parameter ramped 0 -> 1 over the step (no thermal expansion
//     anywhere), so the activation grows gradually;
//   * embedding: every muscle node follows its solid element, u_m − Σ N_i(pcoords) u_i = 0 (three
//     *EQUATION per node, the element's own shape functions, so it is exact for any deformation);
//   * fixed nodes (node set "skull" by default): *BOUNDARY 1–3;
//   * sliding nodes (optional, e.g. the lips' inner surface on the teeth): n·u = 0 by *EQUATION;
//   * a half model (mmrepHalfModel.h): its symmetry boundary's solid nodes keep n·u = 0, n the
//     refitted plane's normal, by *EQUATION too (a node that also slides gets both constraints);
//   * nodal loads (optional, *CLOAD, ramped with the step), e.g. for element tests;
//   * one *STEP, NLGEOM, *STATIC with automatic incrementation; *NODE FILE U (.frd).
#pragma once

#include "mmrepFEMesh.h"

#include <array>
#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace mmrep::simulation
{

// Polynomial hyperelastic coefficients (N/mm²) and compressibilities D1, D2 (mm²/N).
// Strain energy: W = Σ Cij (I1−3)^i (I2−3)^j + Σ (J−1)^(2k)/Dk.
struct HyperelasticMaterial
{
  double c10 = 0, c01 = 0, c20 = 0, c11 = 0, c02 = 0, d1 = 0, d2 = 0;
  // Initial shear modulus 2(C10 + C01) and bulk modulus 2/D1 (N/mm²).
  double ShearModulus() const { return 2 * (c10 + c01); }
  double BulkModulus() const { return 2 / d1; }
};

// Nazari et al. 2010 face tissue: C10 = 2500 Pa, C20 = 1175 Pa, in N/mm²; D1 from the Poisson
// ratio of the initial (small-strain) response: K = 2μ(1+ν)/(3(1−2ν)), D1 = 2/K.
HyperelasticMaterial FaceTissue(double poissonRatio = 0.49);

// The activated state of one muscle: activation level in [0, 1].
struct MuscleActivation
{
  std::string muscle; // name as stored in FEMesh::muscles (case-sensitive)
  double level = 1.0;
};

// The fibre law. λ = L/L0 with L0 the cable's rest length, taken as the fibre's optimal length:
//   F = a · s · Fmax · f_L(λ) + k · s · Fmax · (λ − 1)   (N),
// a the activation, s = forceScale, Fmax the track's maximumForce. f_L is the active force-length
// curve of Thelen 2003 (J Biomech Eng 125:70-77), f_L = exp(−(λ − 1)²/γ), on its ascending limb
// (λ < 1); for λ >= 1 it stays at 1: the descending limb's negative slope would make the static
// equilibrium unstable. k adds a small positive slope everywhere: ccx's non-linear SPRINGA diverges
// on a branch of zero stiffness (the first Newton correction is ~100 mm whatever the load), and an
// inactive cable must still carry a little stiffness; with k = 0.05 a relaxed fibre stretched by
// 10 % pulls with 0.5 % of Fmax.
struct CableModel
{
  double forceScale = 1.0;        // multiplies every track's maximum force (1: the stored forces)
  double lengthWidth = 0.45;      // γ of f_L (Thelen 2003)
  double stabilisingSlope = 0.05; // k, per unit strain, as a fraction of Fmax
};

struct StepControl
{
  double initialIncrement = 0.5; // fraction of the step; ccx halves it (cutback) when it fails
  double minIncrement = 1e-4;
  double maxIncrement = 1.0;
  int maxIncrements = 100;
};

// A node that slides on a rigid support: its displacement along `normal` is zero (frictionless,
// bilateral contact, linearised at the rest position).
struct SlidingNode
{
  std::int32_t node = -1;
  Point3 normal = Point3::UnitY();
};

// The lips' support by the teeth and gums: the nodes of set "inner" (inner surface where no bone was
// found) that lie behind the lips, i.e. whose x (left-right) and z (inferior-superior) fall within
// the bounding box of node set "lips" widened by `margin` mm; normal = area-weighted normal of the
// inner boundary faces at the node. Empty when the model has no "inner" or "lips" set.
std::vector<SlidingNode> LipSupportNodes(const FEMesh& mesh, double margin = 5.0);

// A concentrated force (N) on a node of a solid element (*CLOAD), ramped from 0 over the step.
struct NodalLoad
{
  std::int32_t node = -1;
  Point3 force = Point3::Zero();
};

struct DeckOptions
{
  // Index = TissueLayer (None, Epidermis, Dermis, Hypodermis); elements of layer None use [0].
  std::array<HyperelasticMaterial, 4> materials{FaceTissue(), FaceTissue(), FaceTissue(), FaceTissue()};
  std::string hexahedronType = "C3D8R"; // C3D8R, C3D8I or C3D8 (see the module README: C3D8 locks)
  std::vector<MuscleActivation> activations;
  CableModel cables;
  std::string fixedNodeSet = "skull";
  std::vector<SlidingNode> slidingNodes; // e.g. LipSupportNodes(mesh); fixed nodes among them are skipped
  bool symmetry = true; // a half model: its symmetry boundary's nodes move within the plane
  std::vector<NodalLoad> loads; // with loads, `activations` may be empty (a purely passive solve)
  StepControl step;
};

// What the deck contains (for reports and tests).
struct DeckSummary
{
  std::size_t solids = 0, springs = 0, equations = 0, fixedNodes = 0, slidingNodes = 0, symmetryNodes = 0;
  std::vector<std::string> activeMuscles; // muscles written as springs, in activation order
};

// Names of the muscles of `mesh`, in stored (sorted) order.
std::vector<std::string> MuscleNames(const FEMesh& mesh);

// Throws std::invalid_argument with one line when the mesh has no muscles, a muscle name is unknown
// (the message lists the valid names; on a half model a right-side "_R" muscle says so), a level is outside [0, 1], a muscle is named twice, or no
// muscle has a positive level.
void CheckActivations(const FEMesh& mesh, const std::vector<MuscleActivation>& activations);

// Writes the deck. Node id = node index + 1; element id = element index + 1. Only the cables of
// muscles with a positive level are written (inactive cables would only add the small stabilising slope), with
// their track nodes and equations; other muscle nodes are left out of the deck.
// Throws std::invalid_argument (see CheckActivations, skipped when there are loads and no
// activations; also an empty or missing fixed node set, an unknown hexahedron type, a muscle node
// without a valid embedding, a load on a node that is not a solid's).
DeckSummary WriteCalculiXDeck(const FEMesh& mesh, const DeckOptions& options, std::ostream& out);

// The cable law (see CableModel) of a cable of rest length `restLength` (mm) on a track of maximum
// force `maximumForce` (N) at activation `level`, as the piecewise-linear curve the deck writes:
// (elongation mm, force N) at λ = 0, 0.3, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 1 and 3.
std::vector<std::pair<double, double>> CableCurve(const CableModel& model, double maximumForce, double restLength,
                                                  double level);

// The force (N) of that curve at `elongation` (mm), linear between its points and beyond its ends:
// the one definition used by the deck and by the reported cable forces.
double CableForce(const CableModel& model, double maximumForce, double restLength, double level, double elongation);

// Shape-function weights of a point with parametric coordinates `pcoords` in a solid element
// (VTK convention for hexahedra, wedges and tetrahedra), in the element's node order.
std::vector<double> ShapeFunctions(ElementType type, const std::array<double, 3>& pcoords);

} // namespace mmrep::simulation
