// CalculiX (ccx) input deck for a muscle-activation solve of an FE face model.
//
// Units: the mesh is in mm, so forces are N, stresses/moduli N/mm² (= MPa; 1 Pa = 1e-6 N/mm²),
// the compressibility D N⁻¹mm², the cable stiffness EA N.
//
// Model written (Modules/CLI/SimulateMuscleActivation/README.md explains the choices):
//   * solids: hyperelastic polynomial N=2 (C10, C01, C20, C11, C02, D1, D2), one material per
//     tissue layer; hexahedra as C3D8/C3D8I/C3D8R, wedges C3D6, tetrahedra C3D4;
//   * cables: SPRINGA (axial, large-rotation) elements with a non-linear, temperature-dependent
//     force-elongation curve F = EA/L0 · (e + a·ε·L0) above the active rest length (1 − a·ε)·L0,
//     0.1 % of that slope below it (slack; see CableModel::slackRatio). The curve is given at
//     "temperature" 0 (a = 0) and 1 (a = level); the temperature is only a load parameter ramped
//     0 → 1 over the step (no thermal expansion anywhere), so the activation grows gradually;
//   * embedding: every muscle node follows its solid element, u_m − Σ N_i(pcoords) u_i = 0 (three
//     *EQUATION per node, the element's own shape functions, so it is exact for any deformation);
//   * fixed nodes (node set "skull" by default; `maxilla` on a model with a jaw): *BOUNDARY 1–3;
//   * a jaw opening: the `mandible` nodes' rigid rotation as prescribed displacements (mmrepJaw.h);
//   * lips: GAPUNI gap elements between the facing nodes of the mouth slit (no interpenetration);
//   * sliding nodes (optional, e.g. the lips' inner surface on the teeth): n·u = 0 by *EQUATION;
//   * a half model (mmrepHalfModel.h): its symmetry boundary's solid nodes keep n·u = 0, n the
//     refitted plane's normal, by *EQUATION too (a node that also slides gets both constraints);
//   * one *STEP, NLGEOM, *STATIC with automatic incrementation; *NODE FILE U (.frd).
#pragma once

#include "mmrepFEMesh.h"

#include <array>
#include <cstdint>
#include <map>
#include <ostream>
#include <string>
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

struct CableModel
{
  double axialStiffness = 5.0; // EA in N: force per unit strain of a cable
  double maxContraction = 0.3; // ε: active rest length is (1 − a ε) L0 at activation a
  // Stiffness of the slack branch relative to EA/L0. ccx's non-linear SPRINGA diverges on a branch of
  // exactly zero stiffness (the first Newton correction is ~100 mm whatever the load), so a slack
  // cable keeps 0.1 % of its stiffness: in compression it pushes with at most 0.1 % of the force the
  // same stretch would pull with.
  double slackRatio = 1e-3;
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

struct DeckOptions
{
  // Index = TissueLayer (None, Epidermis, Dermis, Hypodermis); elements of layer None use [0].
  std::array<HyperelasticMaterial, 4> materials{FaceTissue(), FaceTissue(), FaceTissue(), FaceTissue()};
  std::string hexahedronType = "C3D8"; // C3D8, C3D8I or C3D8R
  std::vector<MuscleActivation> activations;
  CableModel cables;
  std::string fixedNodeSet = "skull";
  std::vector<SlidingNode> slidingNodes; // e.g. LipSupportNodes(mesh); fixed nodes among them are skipped
  bool symmetry = true; // a half model: its symmetry boundary's nodes move within the plane
  StepControl step;
  // Jaw opening (degrees, mmrepJaw.h): on a model with a jaw the `maxilla` nodes are fixed and the
  // `mandible` nodes rotate rigidly about the condylar axis (prescribed displacements, ramped over
  // the step); the lip-support nodes nearest the mandible are then left free (their support, the
  // lower teeth, moves away with it). Without a jaw the angle must be 0 and `fixedNodeSet` is fixed.
  double jawAngle = 0;
  // The lips' facing surfaces (mmrepLipContact.h) kept from interpenetrating: a gap element (GAPUNI,
  // frictionless) per pair of facing nodes along the upper surface's normal, penalty
  // `contactStiffness` (N/mm of overclosure per pair).
  bool lipContact = true;
  double contactStiffness = 50.0;
};

// What the deck contains (for reports and tests).
struct DeckSummary
{
  std::size_t solids = 0, springs = 0, equations = 0, fixedNodes = 0, slidingNodes = 0, symmetryNodes = 0;
  std::size_t jawNodes = 0, contactNodes = 0, contactFaces = 0; // mandible nodes moved; lip gap pairs, facing faces
  std::vector<std::string> activeMuscles; // muscles written as springs, in activation order
};

// Names of the muscles of `mesh`, in stored (sorted) order.
std::vector<std::string> MuscleNames(const FEMesh& mesh);

// Throws std::invalid_argument with one line when the mesh has no muscles, a muscle name is unknown
// (the message lists the valid names; on a half model a right-side "_R" muscle says so), a level is outside [0, 1], a muscle is named twice, or no
// muscle has a positive level.
// With `requireActive` false (a jaw opening alone), no muscle or only zero levels are accepted.
void CheckActivations(const FEMesh& mesh, const std::vector<MuscleActivation>& activations, bool requireActive = true);

// Writes the deck. Node id = node index + 1; element id = element index + 1. Only the cables of
// muscles with a positive level are written (inactive cables are slack and carry nothing), with
// their track nodes and equations; other muscle nodes are left out of the deck.
// Throws std::invalid_argument (see CheckActivations; also an empty or missing fixed node set,
// an unknown hexahedron type, a muscle node without a valid embedding).
DeckSummary WriteCalculiXDeck(const FEMesh& mesh, const DeckOptions& options, std::ostream& out);

// The cable law at activation `level` (elongation e in mm, force N), with s = e + level·ε·L0:
// F = EA/L0 · s when s > 0 (taut), EA/L0 · slackRatio · s otherwise (slack).
double CableForce(const CableModel& model, double restLength, double level, double elongation);

// Shape-function weights of a point with parametric coordinates `pcoords` in a solid element
// (VTK convention for hexahedra, wedges and tetrahedra), in the element's node order.
std::vector<double> ShapeFunctions(ElementType type, const std::array<double, 3>& pcoords);

} // namespace mmrep::simulation
